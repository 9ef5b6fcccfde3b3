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

"""Joint transforms and link poses agree with yourdfpy's forward kinematics."""

from __future__ import annotations

from pathlib import Path
import random

from helpers import corpus_cases, corpus_file, full_robot, require_module
import pytest
from registry_robots import robot as registry_robot

from urdfgenpy_ros import Robot
from urdfgenpy_ros.dynamics.kinematics import JointTransforms, link_poses


def _matrix(pose):
    transformations = require_module('trimesh.transformations')
    (x, y, z), (qx, qy, qz, qw) = pose
    matrix = transformations.quaternion_matrix([qw, qx, qy, qz])
    matrix[:3, 3] = (x, y, z)
    return matrix


# Registry robots of different shapes: arm, humanoid tree, wheeled biped, arm with a
# gripper's mimic joints, small arm with a fixed frame; the corpus ones when a run has it.
REGISTRY = ['panda.urdf', 'icub.urdf', 'upkie.urdf', 'kinova_robotiq.urdf', 'so101.urdf']
CORPUS_FILES = {'pr2_desc.urdf': 'urdf/urdf/test/pr2_desc.urdf',
                'minitaur.urdf': 'pybullet_data/quadruped/minitaur.urdf',
                'gen3_lite.urdf': 'kortex/kortex_description/robots/gen3_lite.urdf'}


def _source(source: str) -> Robot:
    if source == 'every_element':
        return full_robot()
    if source.startswith('corpus:'):
        return Robot.from_urdf(corpus_file(CORPUS_FILES[source[len('corpus:'):]]))
    return Robot.from_urdf(registry_robot(source))


@pytest.mark.parametrize('source', ['every_element', *REGISTRY,
                                    *corpus_cases([f'corpus:{name}' for name in CORPUS_FILES])])
def test_link_poses_equal_yourdfpy_at_random_states(source: str, tmp_path: Path) -> None:
    robot = _source(source)
    path = tmp_path / 'robot.urdf'
    robot.to_urdf(path)
    yourdfpy = require_module('yourdfpy')
    model = yourdfpy.URDF.load(str(path), load_meshes=False, build_scene_graph=True)
    root = robot.root.name
    rng = random.Random(5)
    worst = 0.0
    for _ in range(30):
        free = {joint.name: rng.uniform(-1.0, 1.0) for joint in robot.joints
                if joint.is_movable and joint.mimic is None}
        model.update_cfg(free)
        state = dict(free)
        for joint in robot.joints:  # yourdfpy applies mimic joints: so do we
            if joint.is_movable and joint.mimic is not None:
                state[joint.name] = (joint.mimic.multiplier * state[joint.mimic.joint]
                                     + joint.mimic.offset)
        for link, pose in link_poses(robot, state).items():
            difference = abs(_matrix(pose) - model.get_transform(link, root)).max()
            worst = max(worst, float(difference))
    assert worst < 1e-12


def test_fixed_joints_are_static_and_movable_ones_move(ptu: Robot) -> None:
    transforms = JointTransforms(ptu)
    assert [(parent, child) for parent, child, *_ in transforms.static] == [
        ('base_link', 'base_plate')]
    assert transforms.moving_joints == ['pan_joint', 'tilt_joint']
    rest, turned = transforms.moving({}), transforms.moving({'pan_joint': 1.0})
    assert rest[0][3] == (0.0, 0.0, 0.0, 1.0) and turned[0][3] != rest[0][3]
    assert turned[0][2] == (0.0, 0.0, 0.025)
