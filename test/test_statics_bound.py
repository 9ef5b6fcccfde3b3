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

"""The bound that spares check --statics a search holds every torque pinocchio computes."""

from __future__ import annotations

from pathlib import Path

import numpy
import pytest
from registry_robots import robot_id, robots
from test_dynamics import _configurations, _read, Pinocchio

from urdfgenpy_ros import Inertial, Joint, JointLimit, Link, Origin, Robot
from urdfgenpy_ros.dynamics import compiled
from urdfgenpy_ros.dynamics.bound import torque_bounds
from urdfgenpy_ros.dynamics.gravity import mass_model
from urdfgenpy_ros.dynamics.worst import ranges

G = numpy.array([0.0, 0.0, -9.81])


def _bounds(robot: Robot) -> numpy.ndarray:
    model = compiled(robot)
    return torque_bounds(model, mass_model(robot, model), ranges(robot, model), G)


@pytest.mark.parametrize('path', [pytest.param(path, id=robot_id(path)) for path in robots()])
def test_no_pose_needs_more_than_the_bound(path: Path) -> None:
    robot = _read(path)
    if len(robot.roots) != 1 or not robot.movable_joints:
        pytest.skip(f'{path.name}: not one tree with movable joints')
    judge = Pinocchio(robot)
    bounds = _bounds(robot)
    most = numpy.zeros(len(bounds))
    for values in _configurations(robot, 60, 4):
        torques = judge.fold(judge.pin.computeGeneralizedGravity(
            judge.model, judge.data, judge.q(values)))
        most = numpy.maximum(most, numpy.abs(torques))
    assert (most <= bounds * (1.0 + 1e-9) + 1e-12).all(), (most, bounds)


def test_a_turn_about_the_vertical_under_vertical_turns_is_bounded_by_zero() -> None:
    """A pan joint under a pan joint never carries gravity; a tilt joint is bounded by m g l."""
    robot = Robot('pan').add_link(Link('base'))
    for number, (axis, rpy) in enumerate([((0, 0, 1), (0, 0, 0)), ((0, 0, -1), (0, 0, 0.7)),
                                          ((0, 1, 0), (0, 0, 0))]):
        robot.add_link(Link(f'l{number}').set_inertial(
            Inertial(2.0, 0.01, 0, 0, 0.01, 0, 0.01, origin=Origin((0.3, 0, 0)))))
        robot.add_joint(Joint(f'j{number}', 'revolute', 'base' if number == 0 else
                              f'l{number - 1}', f'l{number}', axis=axis,
                              origin=Origin((0.1, 0, 0), rpy),
                              limit=JointLimit(-3, 3, effort=1, velocity=1)))
    bounds = _bounds(robot)
    assert bounds[0] == 0.0 and bounds[1] == 0.0
    assert bounds[2] == pytest.approx(9.81 * 2.0 * 0.3)
    found = robot.validate(statics=True, check_meshes=False)
    assert [(finding.code, finding.element) for finding in found
            if finding.code == 'T801'] == [('T801', "joint 'j2'")]
