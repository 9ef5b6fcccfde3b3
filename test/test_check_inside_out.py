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

"""An inside-out convex mesh is named so (M510), not "not convex"; a .dae M506 is no path."""

from __future__ import annotations

from pathlib import Path

from helpers import require_module
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.validation.preflight import preflight

LINKS = """<?xml version="1.0"?>
<robot name="r">
  <link name="base_link"/>
  <link name="a"><inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><mesh filename="inverted.stl"/></geometry></collision></link>
  <link name="b"><inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><geometry><mesh filename="cube.dae"/></geometry></collision></link>
  <joint name="j" type="revolute"><parent link="base_link"/><child link="a"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="k" type="revolute"><parent link="a"/><child link="b"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_an_inverted_cube_is_said_inside_out_as_mujoco_finds_it(tmp_path: Path) -> None:
    trimesh = require_module('trimesh')
    mujoco = require_module('mujoco')
    cube = trimesh.creation.box(extents=(0.1, 0.1, 0.1))
    cube.export(tmp_path / 'cube.dae')
    cube.invert()
    cube.export(tmp_path / 'inverted.stl')
    read = trimesh.load(tmp_path / 'inverted.stl', force='mesh')
    assert read.volume < 0.0  # the independent judges: trimesh, and MuJoCo's exact inertia
    with pytest.raises(ValueError, match='mesh volume is negative'):
        mujoco.MjModel.from_xml_string(
            f'<mujoco><asset><mesh name="m" file="{tmp_path / "inverted.stl"}" '
            'inertia="exact"/></asset><worldbody><body><freejoint/><geom type="mesh" '
            'mesh="m"/></body></worldbody></mujoco>')
    (tmp_path / 'r.urdf').write_text(LINKS)
    found = {f.code: f for f in preflight(Robot.from_urdf(tmp_path / 'r.urdf'), ['mujoco'])}
    assert 'M504' not in found  # it is convex, the right way out
    said = found['M510'].message
    assert 'inverted.stl is wound inside out' in said and '-0.001 m^3' in said
    assert 'mesh volume is negative' in said
    assert '--package-path' not in str(found['M506'])  # cube.dae was found: it is no path
    assert "MuJoCo cannot read .dae meshes ('cube.dae')" in found['M506'].message
