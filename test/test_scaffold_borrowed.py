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
``init --from``: a path in another package's folder that is no file here stays that package's.

As lbr_description's Gazebo block names ``$(find lbr_ros2_control)/config/...``, which a
partial install found through ``-p`` lacks: the package must not bake this machine's path.
Judges: the real xacro (through a real ament index) and catkin_pkg reading package.xml.
"""

from __future__ import annotations

from pathlib import Path

from helpers import ament_index, environment, require_module, xacro_expand
import pytest

from urdfgenpy_ros.scaffold.command import main as init

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.0.1</version><description>x</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<export><build_type>ament_cmake</build_type></export></package>
"""
ROBOT = """<?xml version="1.0"?>
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base_link">
    <collision><geometry><box size="0.3 0.2 0.1"/></geometry></collision>
    <inertial><mass value="2"/>
      <inertia ixx="0.0083" ixy="0" ixz="0" iyy="0.0167" iyz="0" izz="0.0217"/></inertial>
  </link>
  <gazebo>
    <plugin filename="gz_ros2_control-system" name="gz_ros2_control::GazeboSimROS2ControlPlugin">
      <parameters>$(find arm_control)/config/arm_controllers.yaml</parameters>
      <ros><namespace>/arm</namespace></ros>
    </plugin>
  </gazebo>
</robot>
"""


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    """Write arm_description and a partial arm_control (its config/ lacks the YAML named)."""
    root = tmp_path / 'trial' / '_prefix' / 'share'
    for name in ('arm_description', 'arm_control'):
        (root / name / 'config').mkdir(parents=True)
        (root / name / 'package.xml').write_text(PACKAGE_XML.format(name=name))
    (root / 'arm_control' / 'config' / 'other.yaml').write_text('a: 1\n')
    (root / 'arm_description' / 'arm.urdf.xacro').write_text(ROBOT)
    return tmp_path / 'trial'


def test_a_path_in_another_package_is_written_through_it_and_depended_on(
        workspace: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    source = workspace / '_prefix' / 'share' / 'arm_description' / 'arm.urdf.xacro'
    assert init(['gen_description', '--from', str(source), '-p', str(workspace),
                 '--destination-directory', str(tmp_path / 'out')]) == 0
    package = tmp_path / 'out' / 'gen_description'
    gazebo = package / 'urdf' / 'arm.gazebo.xacro'
    assert str(workspace) not in gazebo.read_text()
    catkin = require_module('catkin_pkg.package')
    depends = {depend.name for depend in
               catkin.parse_package(str(package / 'package.xml')).exec_depends}
    assert 'arm_control' in depends
    (line,) = [line for line in capsys.readouterr().err.splitlines() if 'arm_control' in line]
    assert 'urdf/arm.gazebo.xacro' in line and "package 'arm_control'" in line
    assert str(workspace / '_prefix' / 'share' / 'arm_control' / 'config') in line
    elsewhere = tmp_path / 'installed' / 'arm_control'  # where it is installed, not here
    elsewhere.mkdir(parents=True)
    with environment(ament_index(tmp_path / 'index', {'arm_control': elsewhere,
                                                      'gen_description': package})):
        text = xacro_expand(package / 'urdf' / 'arm.urdf.xacro')
    parameters = text.split('<parameters>')[1].split('</parameters>')[0]
    assert parameters == str(tmp_path / 'index' / 'share' / 'arm_control' / 'config' /
                             'arm_controllers.yaml')
    assert '<namespace>/arm</namespace>' in text  # a ROS name that only looks like a path
