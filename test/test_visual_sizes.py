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

"""A negative size on a visual is an error (MuJoCo refuses it); a zero one stays a warning."""

from __future__ import annotations

from pathlib import Path

from helpers import require_module
import pytest

from urdfgenpy_ros import Robot

ROBOT = """<robot name="r">
  <mujoco><compiler discardvisual="false"/></mujoco>
  <link name="base_link">
    <inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <visual><geometry>{shape}</geometry></visual>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
  </link>
</robot>
"""


@pytest.mark.parametrize('shape', ['<box size="-0.1 0.1 0.1"/>', '<sphere radius="-1"/>',
                                   '<cylinder radius="0.1" length="-0.2"/>'])
def test_a_negative_visual_size_is_an_error_mujoco_agrees(shape: str, tmp_path: Path) -> None:
    mujoco = require_module('mujoco')
    path = tmp_path / 'r.urdf'
    path.write_text(ROBOT.format(shape=shape))
    with pytest.raises(ValueError, match='must be positive'):
        mujoco.MjModel.from_xml_path(str(path))  # keeping visuals, it refuses the model
    (finding,) = [f for f in Robot.from_urdf(path).validate() if f.code.startswith('R')]
    assert (finding.code, str(finding.severity)) == ('R304', 'error')
    assert 'on a visual' in finding.message and 'inside out' in finding.hint


@pytest.mark.parametrize('shape', ['<box size="0 0.1 0.1"/>',
                                   '<mesh filename="x.stl" scale="0 1 1"/>'])
def test_a_zero_visual_size_or_scale_stays_a_warning(shape: str) -> None:
    robot = Robot.from_urdf_string(ROBOT.format(shape=shape))
    codes = {(f.code, str(f.severity)) for f in robot.validate(check_meshes=False)}
    assert ('R307', 'warning') in codes and not any(c == 'R304' for c, _ in codes)
