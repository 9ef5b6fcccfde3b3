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

"""check --fix says why a bad tensor stays: the link has no shape to take one from."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import require_module

from urdfgenpy_ros.cli import main

FINGER = """<?xml version="1.0"?>
<robot name="r">
  <link name="base_link"/>
  <link name="finger">
    <inertial><mass value="0.1"/>
      <inertia ixx="-0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <visual><geometry><mesh filename="finger.stl"/></geometry></visual>
  </link>
  <joint name="j" type="revolute"><parent link="base_link"/><child link="finger"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_a_tensor_fix_cannot_make_is_said_and_the_file_stays(tmp_path: Path) -> None:
    path = tmp_path / 'finger.urdf'
    path.write_text(FINGER)
    mujoco = require_module('mujoco')
    try:  # the finding is real: MuJoCo refuses the tensor
        mujoco.MjModel.from_xml_string(FINGER.replace('<visual><geometry><mesh filename='
                                                      '"finger.stl"/></geometry></visual>', ''))
        refused = False
    except ValueError:
        refused = True
    assert refused
    result = CliRunner().invoke(main, ['check', str(path), '--fix', '--no-meshes'])
    assert result.exit_code == 1, result.output
    assert "I202 not fixed for link 'finger': no box, cylinder, sphere or capsule" \
        in result.output
    assert path.read_text() == FINGER
