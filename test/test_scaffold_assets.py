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
``init --from`` brings every file the robot names into the package, and no path of the machine.

The fixture is a workspace written here, as articubot_one's is laid out: the description's
Gazebo block names its controllers YAML by ``$(find)``, its meshes and texture live in another
package. Judges: the real xacro, yourdfpy, colcon build and colcon test.
"""

from __future__ import annotations

import os
from pathlib import Path
import subprocess
import sys

from helpers import (ament_index, environment, load_yourdfpy, require_module, snapshot,
                     xacro_expand)
import pytest

from urdfgenpy_ros.scaffold.command import main as init

CONTROLLERS = 'controller_manager:\n  ros__parameters:\n    update_rate: 30\n'
PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.0.1</version><description>x</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>ament_cmake</buildtool_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""
ROBOT = """<?xml version="1.0"?>
<robot name="bot" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find bot_parts)/urdf/materials.xacro"/>
  <link name="base_link">
    <visual>
      <geometry><mesh filename="package://bot_parts/meshes/chassis.stl"/></geometry>
      <material name="decal"/>
    </visual>
    <visual><geometry><mesh filename="package://bot_parts/meshes/wheel.obj"/></geometry>
    </visual>
    <collision><geometry><box size="0.3 0.2 0.1"/></geometry></collision>
    <inertial><mass value="2"/>
      <inertia ixx="0.0083" ixy="0" ixz="0" iyy="0.0167" iyz="0" izz="0.0217"/></inertial>
  </link>
  <ros2_control name="GazeboSystem" type="system">
    <hardware><plugin>gz_ros2_control/GazeboSimSystem</plugin></hardware>
  </ros2_control>
  <gazebo>
    <plugin filename="gz_ros2_control-system" name="gz_ros2_control::GazeboSimROS2ControlPlugin">
      <parameters>$(find bot_description)/config/my_controllers.yaml</parameters>
    </plugin>
  </gazebo>
</robot>
"""
MATERIALS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <material name="decal"><texture filename="package://bot_parts/meshes/decal.png"/></material>
</robot>
"""


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    trimesh = require_module('trimesh')
    source = tmp_path / 'source_ws' / 'src'
    for name in ('bot_description', 'bot_parts'):
        (source / name).mkdir(parents=True)
        (source / name / 'package.xml').write_text(PACKAGE_XML.format(name=name))
    (source / 'bot_description' / 'urdf').mkdir()
    (source / 'bot_description' / 'urdf' / 'bot.urdf.xacro').write_text(ROBOT)
    (source / 'bot_description' / 'config').mkdir()
    (source / 'bot_description' / 'config' / 'my_controllers.yaml').write_text(CONTROLLERS)
    (source / 'bot_parts' / 'meshes').mkdir()
    (source / 'bot_parts' / 'urdf').mkdir()
    (source / 'bot_parts' / 'urdf' / 'materials.xacro').write_text(MATERIALS)
    trimesh.creation.box((0.3, 0.2, 0.1)).export(source / 'bot_parts' / 'meshes' / 'chassis.stl')
    (source / 'bot_parts' / 'meshes' / 'decal.png').write_bytes(b'\x89PNG\r\n\x1a\n fake')
    # an OBJ whose material's image lies in a folder beside it
    meshes = source / 'bot_parts' / 'meshes'
    (meshes / 'textures').mkdir()
    require_module('PIL.Image').new('RGB', (4, 4), (200, 30, 30)).save(
        meshes / 'textures' / 'paint.png')
    (meshes / 'wheel.mtl').write_text('newmtl paint\nKd 1 1 1\nmap_Kd textures/paint.png\n')
    (meshes / 'wheel.obj').write_text('mtllib wheel.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n'
                                      'vt 0 0\nvt 1 0\nvt 0 1\nusemtl paint\nf 1/1 2/2 3/3\n')
    return source


def _generate(workspace: Path, out: Path) -> Path:
    robot = workspace / 'bot_description' / 'urdf' / 'bot.urdf.xacro'
    code = init(['gen_description', '--from', str(robot),
                 '--package-path', str(workspace), '--destination-directory', str(out)])
    assert code == 0
    return out / 'gen_description'


def test_every_named_file_is_in_the_package_and_no_machine_path(
        workspace: Path, tmp_path: Path) -> None:
    package = _generate(workspace, tmp_path / 'out')
    assert (package / 'config' / 'my_controllers.yaml').read_text() == CONTROLLERS
    assert (package / 'meshes' / 'chassis.stl').read_bytes() == (
        workspace / 'bot_parts' / 'meshes' / 'chassis.stl').read_bytes()
    assert (package / 'meshes' / 'decal.png').is_file()
    for path in package.rglob('*'):
        if path.is_file() and path.suffix not in ('.png', '.stl', '.obj', '.mtl'):
            text = path.read_text()
            assert str(tmp_path) not in text and '/tmp' not in text, path
    trimesh = require_module('trimesh')  # the copied OBJ finds its material and image
    wheel = trimesh.load(package / 'meshes' / 'wheel.obj', force='mesh')
    assert wheel.visual.material.image.size == (4, 4)
    gazebo = (package / 'urdf' / 'bot.gazebo.xacro').read_text()
    assert '$(find gen_description)/config/my_controllers.yaml' in gazebo


def test_the_package_expands_in_xacro_to_the_original_model(
        workspace: Path, tmp_path: Path) -> None:
    package = _generate(workspace, tmp_path / 'out')
    with environment(ament_index(tmp_path / 'index', {
            'bot_description': workspace / 'bot_description',
            'bot_parts': workspace / 'bot_parts', 'gen_description': package})):
        (tmp_path / 'original.urdf').write_text(
            xacro_expand(workspace / 'bot_description' / 'urdf' / 'bot.urdf.xacro'))
        (tmp_path / 'generated.urdf').write_text(
            xacro_expand(package / 'urdf' / 'bot.urdf.xacro'))
    original, generated = (load_yourdfpy(tmp_path / f'{name}.urdf')
                           for name in ('original', 'generated'))
    # the same model, but for where the files are found
    mine = snapshot(generated)
    theirs = snapshot(original)
    assert repr(mine).replace('gen_description/meshes', 'bot_parts/meshes') == repr(theirs)
    text = (tmp_path / 'generated.urdf').read_text()
    controllers = text.split('<parameters>')[1].split('</parameters>')[0]
    assert Path(controllers).read_text() == CONTROLLERS
    assert Path(controllers).resolve().is_relative_to(package.resolve())


@pytest.mark.slow
@pytest.mark.colcon
def test_the_package_builds_and_its_tests_pass_with_colcon(
        workspace: Path, tmp_path: Path) -> None:
    require_module('colcon_core')
    root = tmp_path / 'ws'
    _generate(workspace, root / 'src')
    colcon = str(Path(sys.executable).with_name('colcon'))
    env = dict(os.environ, PATH=f'{Path(sys.executable).parent}:{os.environ["PATH"]}')
    for verb in (['build'], ['test'], ['test-result', '--verbose']):
        result = subprocess.run([colcon, *verb], cwd=root, capture_output=True, text=True,
                                env=env, timeout=900)
        assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    share = root / 'install' / 'gen_description' / 'share' / 'gen_description'
    assert (share / 'config' / 'my_controllers.yaml').read_text() == CONTROLLERS
