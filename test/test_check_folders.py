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
``check`` of a colcon ``src/`` folder: its packages resolve, its include files are skipped.

The real xacro, given an ament index of the same packages, is the judge of what the
robot file expands to; check_urdf accepts that expansion.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import ament_index, assert_check_urdf_accepts, environment, xacro_expand
import pytest

from urdfgenpy_ros.cli import main

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.0.1</version>
  <description>test</description><maintainer email="a@b.c">a</maintainer>
  <license>Apache-2.0</license></package>
"""
MATERIALS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">

  <material name="black"><color rgba="0 0 0 1"/></material>
  <material name="orange"><color rgba="1 0.4 0 1"/></material>
</robot>
"""
ROBOT = """<?xml version="1.0"?>
<robot name="rover" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find polish_rover_materials)/urdf/rover.materials.xacro"/>
  <link name="base_link">
    <visual><geometry><box size="0.2 0.1 0.05"/></geometry><material name="orange"/></visual>
    <inertial><mass value="1"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.004" iyz="0" izz="0.004"/></inertial>
  </link>
</robot>
"""


def _src(root: Path) -> Path:
    """Lay out a colcon src/ folder: a robot package and a materials package."""
    src = root / 'src'
    for name, file, text in (('polish_rover_description', 'rover.urdf.xacro', ROBOT),
                             ('polish_rover_materials', 'rover.materials.xacro', MATERIALS)):
        (src / name / 'urdf').mkdir(parents=True)
        (src / name / 'package.xml').write_text(PACKAGE_XML.format(name=name))
        (src / name / 'urdf' / file).write_text(text)
    return src


def _check(*arguments: str) -> tuple[int, str]:
    result = CliRunner().invoke(main, ['check', *arguments])
    return result.exit_code, result.output


def test_a_checked_folder_resolves_the_packages_under_it(tmp_path: Path) -> None:
    src = _src(tmp_path)
    robot = src / 'polish_rover_description' / 'urdf' / 'rover.urdf.xacro'
    # the judge: the real xacro, finding the packages through an ament index
    packages = {path.parent.name: path.parent for path in src.glob('*/package.xml')}
    with environment(ament_index(tmp_path / 'index', packages)):
        expanded = xacro_expand(robot)
    (tmp_path / 'rover.urdf').write_text(expanded)
    assert_check_urdf_accepts(tmp_path / 'rover.urdf')
    assert 'rgba="1 0.4 0 1"' in expanded
    code, output = _check(str(src))
    assert code == 0, output
    assert '2 file(s): 0 error(s), 0 warning(s), 0 unreadable' in output


def test_a_missing_package_names_only_the_cli_option(tmp_path: Path) -> None:
    src = _src(tmp_path)
    robot = src / 'polish_rover_description' / 'urdf' / 'rover.urdf.xacro'
    code, output = _check(str(robot))  # a file alone: its neighbours are not searched
    assert code == 2
    assert 'polish_rover_materials' in output and '-p/--package-path' in output
    assert 'search_paths' not in output


@pytest.mark.parametrize('suffix', ['.xacro', '.urdf'])
def test_a_materials_only_file_is_skipped_at_its_source_line(tmp_path: Path,
                                                             suffix: str) -> None:
    path = tmp_path / f'rover.materials{suffix}'
    path.write_text(MATERIALS)
    line = next(number for number, text in enumerate(MATERIALS.splitlines(), start=1)
                if '<material' in text)
    code, output = _check(str(tmp_path))
    assert code == 0, output
    assert f'{path}: note: skipped, it holds materials only' in output
    assert 'X003 defines materials (black, orange) and no robot' in output
    assert '(expanded)' not in output and 'P002' not in output
    assert '1 file(s): 0 error(s), 0 warning(s), 0 unreadable' in output
    from urdfgenpy_ros.formats import load
    from urdfgenpy_ros.model.errors import ParseError
    with pytest.raises(ParseError) as raised:
        load(path)
    assert str(raised.value).startswith(f'{path}:{line}:')
