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


"""
``urdfgenpy init`` takes -p as every command does, and describes the robot by its name.

catkin_pkg (what colcon and rosdep read package.xml with) is the judge of the manifest.
"""

from __future__ import annotations

import os
from pathlib import Path

from click.testing import CliRunner
from helpers import require_module

from urdfgenpy_ros.cli import main

MESH_PACKAGE = """<?xml version="1.0"?>
<package format="3"><name>polish_mast_parts</name><version>0.0.1</version>
  <description>parts</description><maintainer email="a@b.c">a</maintainer>
  <license>Apache-2.0</license></package>
"""
MAST = """<?xml version="1.0"?>
<robot name="camera_mast" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find polish_mast_parts)/urdf/colours.xacro"/>
  <link name="base_link">
    <visual><geometry><box size="0.1 0.1 0.5"/></geometry><material name="grey"/></visual>
    <inertial><mass value="1"/>
      <inertia ixx="0.02" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.002"/></inertial>
  </link>
</robot>
"""
COLOURS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
</robot>
"""


def test_init_from_xacro_takes_p_and_names_the_robot(tmp_path: Path) -> None:
    require_module('jinja2')
    catkin_pkg = require_module('catkin_pkg.package')
    parts = tmp_path / 'polish_mast_parts'
    (parts / 'urdf').mkdir(parents=True)
    (parts / 'package.xml').write_text(MESH_PACKAGE)
    (parts / 'urdf' / 'colours.xacro').write_text(COLOURS)
    (tmp_path / 'mast.urdf.xacro').write_text(MAST)
    before = Path.cwd()
    os.chdir(tmp_path)
    try:
        result = CliRunner().invoke(main, ['init', 'camera_mast_description', '--from',
                                           'mast.urdf.xacro', '-p', '.',
                                           '--destination-directory', 'out'])
    finally:
        os.chdir(before)
    assert result.exit_code == 0, result.output
    folder = tmp_path / 'out' / 'camera_mast_description'
    package = catkin_pkg.parse_package(str(folder / 'package.xml'))
    assert package.description == 'Robot description of camera_mast'
    assert 'Robot description of camera_mast\n' in \
        (folder / 'README.md').read_text()
