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

"""init says which Xacro values it baked in, lists the plugins' packages, names meshes plainly."""

from __future__ import annotations

from pathlib import Path
import re

from helpers import require_module
import pytest

from urdfgenpy_ros import Mesh, Robot
from urdfgenpy_ros.scaffold.command import main as init

SOURCE = """<?xml version="1.0"?>
<robot name="hw" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="use_sim" default="false"/>
  <link name="base_link"/>
  <link name="wheel">
    <inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <visual><geometry>
      <mesh filename="package://hw_description/meshes/visual/../parts/wheel.stl"/>
    </geometry></visual>
    <collision><geometry>
      <mesh filename="package://hw_description/meshes/collision/wheel.stl"/>
    </geometry></collision>
  </link>
  <joint name="wheel_joint" type="continuous"><parent link="base_link"/><child link="wheel"/>
    <axis xyz="0 1 0"/><limit effort="1" velocity="1"/></joint>
  <ros2_control name="hw_system" type="system">
    <hardware>
      <xacro:if value="$(arg use_sim)"><plugin>gz_ros2_control/GazeboSimSystem</plugin></xacro:if>
      <xacro:unless value="$(arg use_sim)"><plugin>hw_hardware/HwSystem</plugin></xacro:unless>
    </hardware>
    <joint name="wheel_joint"><command_interface name="velocity"/>
      <state_interface name="position"/></joint>
  </ros2_control>
  <gazebo><plugin filename="libgz_ros2_control-system.so"
                  name="gz_ros2_control::GazeboSimROS2ControlPlugin"/></gazebo>
</robot>
"""


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    """Write hw_description (two meshes named wheel.stl, one behind '..') and hw_hardware."""
    trimesh = require_module('trimesh')
    package = tmp_path / 'ws' / 'hw_description'
    for folder in ('meshes/parts', 'meshes/collision'):
        (package / folder).mkdir(parents=True)
    for name in ('hw_description', 'hw_hardware'):
        (tmp_path / 'ws' / name).mkdir(exist_ok=True)
        (tmp_path / 'ws' / name / 'package.xml').write_text(
            f'<package format="3"><name>{name}</name></package>')
    trimesh.creation.cylinder(radius=0.1, height=0.05).export(
        package / 'meshes/parts/wheel.stl')
    trimesh.creation.box(extents=(0.2, 0.05, 0.2)).export(
        package / 'meshes/collision/wheel.stl')
    (package / 'hw.urdf.xacro').write_text(SOURCE)
    return tmp_path / 'ws'


def _expanded(package: Path) -> Robot:
    """Return the generated package's robot as the real xacro expands it."""
    xacro = require_module('xacro')
    from xacro import substitution_args
    original = substitution_args._eval_find
    substitution_args._eval_find = lambda name: str(package)  # noqa: E731 - one package
    try:
        text = xacro.process_file(str(package / 'urdf' / 'hw.urdf.xacro')).toxml()
    finally:
        substitution_args._eval_find = original
    return Robot.from_urdf_string(text)


def _scaffold(workspace: Path, tmp_path: Path, *arguments: str) -> Path:
    out = tmp_path / 'out'
    code = init(['hw2_description', '--from', str(workspace / 'hw_description/hw.urdf.xacro'),
                 '-p', str(workspace), '--destination-directory', str(out), *arguments])
    assert code == 0
    return out / 'hw2_description'


def test_meshes_of_one_name_keep_readable_names_and_a_dotdot_path_is_found(
        workspace: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    trimesh = require_module('trimesh')
    package = _scaffold(workspace, tmp_path)
    err = capsys.readouterr().err
    assert 'not copied' not in err, err
    robot = _expanded(package)
    link = robot.get_link('wheel')
    volumes = {}
    for kind, item in (('visual', link.visuals[0]), ('collision', link.collisions[0])):
        assert isinstance(item.geometry, Mesh)
        uri = item.geometry.filename
        assert uri.startswith('package://hw2_description/meshes/')
        assert not re.search(r'/[0-9a-f]{8}_', uri), uri  # no hash prefix
        volumes[kind] = trimesh.load(package / uri.split('hw2_description/', 1)[1]).volume
    cylinder = trimesh.load(workspace / 'hw_description/meshes/parts/wheel.stl').volume
    box = trimesh.load(workspace / 'hw_description/meshes/collision/wheel.stl').volume
    assert volumes == {'visual': pytest.approx(cylinder), 'collision': pytest.approx(box)}


def test_package_xml_lists_the_plugins_packages_and_baked_values_are_said(
        workspace: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    catkin = require_module('catkin_pkg.package')
    package = _scaffold(workspace, tmp_path)
    err = capsys.readouterr().err
    assert 'the package holds the robot as xacro expanded it with use_sim:=false (the ' \
        'defaults)' in err
    assert '<ros2_control name="hw_system"> uses the hardware plugin hw_hardware/HwSystem' in err
    assert 'the source has use_sim:=false' in err
    assert '`use_sim:=false` (default)' in (package / 'README.md').read_text()
    depends = {d.name for d in catkin.parse_package(str(package / 'package.xml')).exec_depends}
    assert {'gz_ros2_control', 'hw_hardware'} <= depends
    plugins = [element.text for block in _expanded(package).extensions
               for element in block.element.iter('plugin') if element.text]
    assert plugins == ['hw_hardware/HwSystem']  # as the source expands with the defaults


def test_the_values_given_are_those_baked_and_said(
        workspace: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    catkin = require_module('catkin_pkg.package')
    package = _scaffold(workspace, tmp_path, 'use_sim:=true')
    err = capsys.readouterr().err
    assert 'expanded it with use_sim:=true (given)' in err
    assert 'hardware plugin' not in err
    depends = {d.name for d in catkin.parse_package(str(package / 'package.xml')).exec_depends}
    assert 'gz_ros2_control' in depends and 'hw_hardware' not in depends
    plugins = [element.text for block in _expanded(package).extensions
               for element in block.element.iter('plugin') if element.text]
    assert plugins == ['gz_ros2_control/GazeboSimSystem']
