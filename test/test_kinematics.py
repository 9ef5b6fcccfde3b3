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

from helpers import CORPUS, full_robot, require_module
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.kinematics import JointTransforms, link_poses


def _matrix(pose):
    transformations = require_module('trimesh.transformations')
    (x, y, z), (qx, qy, qz, qw) = pose
    matrix = transformations.quaternion_matrix([qw, qx, qy, qz])
    matrix[:3, 3] = (x, y, z)
    return matrix


@pytest.mark.parametrize('source', ['every_element', 'pr2_desc.urdf', 'minitaur.urdf',
                                    'gen3_lite.urdf'])
def test_link_poses_equal_yourdfpy_at_random_states(source: str, tmp_path: Path) -> None:
    files = {'pr2_desc.urdf': CORPUS / 'urdf/urdf/test/pr2_desc.urdf',
             'minitaur.urdf': CORPUS / 'pybullet_data/quadruped/minitaur.urdf',
             'gen3_lite.urdf': CORPUS / 'kortex/kortex_description/robots/gen3_lite.urdf'}
    robot = full_robot() if source == 'every_element' else Robot.from_urdf(files[source])
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
