# Copyright 2026 urdfgenpy_ros contributors
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.

"""Forward kinematics, Jacobians and gravity torques against pinocchio on real robots."""

from __future__ import annotations

from pathlib import Path

from helpers import require_module
import numpy
import pytest
from registry_robots import robot_id, robots, search_paths

from urdfgenpy_ros import Robot
from urdfgenpy_ros.formats import load

CONFIGS = 100


def _read(path: Path) -> Robot:
    return load(path, {}, search_paths())


class Pinocchio:
    """A robot in pinocchio, its mimic joints moved by hand (``mimic=False``)."""

    def __init__(self, robot: Robot) -> None:
        self.pin = require_module('pinocchio')
        self.model = self.pin.buildModelFromXML(robot.to_urdf())
        self.data = self.model.createData()
        self.robot = robot
        self.names = robot.movable_joints
        self.followers = []  # (joint, leader column, multiplier, offset), chains resolved
        column = {name: number for number, name in enumerate(self.names)}
        for joint in robot.joints:
            if joint.is_movable and joint.name not in column:
                multiplier, offset, leader = 1.0, 0.0, joint
                while leader.mimic is not None:
                    multiplier, offset = (multiplier * leader.mimic.multiplier,
                                          offset + multiplier * leader.mimic.offset)
                    leader = robot.get_joint(leader.mimic.joint)
                self.followers.append((joint.name, column[leader.name], multiplier, offset))

    def q(self, values: numpy.ndarray) -> numpy.ndarray:
        """Return pinocchio's configuration (continuous joints as cos, sin)."""
        q = self.pin.neutral(self.model)
        moved = [*zip(self.names, values),
                 *((name, multiplier * values[column] + offset)
                   for name, column, multiplier, offset in self.followers)]
        for name, value in moved:
            joint = self.model.joints[self.model.getJointId(name)]
            if joint.nq == 2:
                q[joint.idx_q:joint.idx_q + 2] = numpy.cos(value), numpy.sin(value)
            else:
                q[joint.idx_q] = value
        return q

    def fold(self, matrix: numpy.ndarray) -> numpy.ndarray:
        """Return pinocchio's columns (or entries) over our movable joints, mimic added."""
        def column(name: str) -> numpy.ndarray:
            return matrix[..., self.model.joints[self.model.getJointId(name)].idx_v]
        result = numpy.stack([column(name) for name in self.names], axis=-1)
        for name, leader, multiplier, _ in self.followers:
            result[..., leader] += multiplier * column(name)
        return result


def _configurations(robot: Robot, count: int, seed: int) -> numpy.ndarray:
    rng = numpy.random.default_rng(seed)
    low, high = [], []
    for name in robot.movable_joints:
        joint = robot.get_joint(name)
        limit = joint.limit
        bounded = joint.type.needs_limit and limit is not None and limit.lower < limit.upper
        low.append(limit.lower if bounded else -numpy.pi)
        high.append(limit.upper if bounded else numpy.pi)
    return rng.uniform(low, high, (count, len(low)))


ROBOTS = [pytest.param(path, id=robot_id(path)) for path in robots()]


@pytest.mark.parametrize('path', ROBOTS)
def test_fk_and_jacobians_equal_pinocchio_at_random_configurations(path: Path) -> None:
    robot = _read(path)
    judge = Pinocchio(robot)
    pin, model, data = judge.pin, judge.model, judge.data
    configurations = _configurations(robot, CONFIGS, 7)
    poses = robot.fk(configurations)  # all at once; single ones below
    links = [link for link in poses if model.existFrame(link)]
    assert links
    tip = links[-1]
    jacobians = {frame: robot.jacobian(tip, configurations, frame=frame)
                 for frame in ('world', 'local')}
    reference = {'world': pin.LOCAL_WORLD_ALIGNED, 'local': pin.LOCAL}
    frame_id = model.getFrameId(tip)
    worst = 0.0
    for number, values in enumerate(configurations):
        q = judge.q(values)
        pin.framesForwardKinematics(model, data, q)
        single = robot.fk(values) if number % 25 == 0 else None
        for link in links:
            expected = data.oMf[model.getFrameId(link)].homogeneous
            worst = max(worst, abs(poses[link][number] - expected).max())
            if single is not None:
                worst = max(worst, abs(single[link] - expected).max())
        pin.computeJointJacobians(model, data, q)
        for frame, kind in reference.items():
            found = pin.getFrameJacobian(model, data, frame_id, kind)
            expected = judge.fold(numpy.reshape(found, (6, model.nv)))  # nv 1 comes 1-D
            worst = max(worst, abs(jacobians[frame][number] - expected).max())
    assert worst < 1e-12


@pytest.mark.parametrize('path', ROBOTS)
def test_gravity_torques_equal_pinocchio(path: Path) -> None:
    robot = _read(path)
    judge = Pinocchio(robot)
    configurations = _configurations(robot, CONFIGS, 11)
    torques = robot.gravity_torques(configurations)
    worst = 0.0
    for number, values in enumerate(configurations):
        expected = judge.fold(judge.pin.computeGeneralizedGravity(
            judge.model, judge.data, judge.q(values)))
        worst = max(worst, abs(torques[number] - expected).max())
    assert worst < 1e-9
