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
``check --fix`` on Xacro edits the value where it is written, and only the lines it names.

The real xacro (plain ``process_file``, no map) expands the fixed files; the robot it
makes must be clean of what was fixed.
"""

from __future__ import annotations

import os
from pathlib import Path
import re

from click.testing import CliRunner
from helpers import xacro_expand
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main

NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
INERTIAL = ('<inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" '
            'iyz="0" izz="0.1"/></inertial>')
PARTS = f"""<?xml version="1.0"?>
<robot {NS}>
  <xacro:property name="axis" value="0 2 0"/>
  <xacro:macro name="arm" params="prefix">
    <link name="${{prefix}}upper">{INERTIAL}</link>
    <joint name="${{prefix}}elbow" type="revolute">
      <parent link="base_link"/>
      <child link="${{prefix}}upper"/>
      <axis xyz="${{axis}}"/>
      <limit lower="1.5" upper="-1.5"
             effort="10" velocity="1"/>
    </joint>
  </xacro:macro>
</robot>
"""
TOP = f"""<?xml version="1.0"?>
<robot name="r" {NS}>
  <xacro:include filename="parts.xacro"/>
  <link name="base_footprint"/>
  <joint name="base" type="fixed"><parent link="base_footprint"/><child link="base_link"/>
  </joint>
  <link name="base_link">{INERTIAL}</link>
  <xacro:arm prefix="left_"/>
  <xacro:arm prefix="right_"/>
</robot>
"""


@pytest.fixture
def robot(tmp_path: Path) -> Path:
    (tmp_path / 'parts.xacro').write_text(PARTS)
    (tmp_path / 'r.urdf.xacro').write_text(TOP)
    return tmp_path / 'r.urdf.xacro'


def _check(robot: Path, *arguments: str):
    cwd = os.getcwd()
    os.chdir(robot.parent)
    try:
        return CliRunner().invoke(main, ['check', *arguments, robot.name])
    finally:
        os.chdir(cwd)


def _changed(before: str, after: str) -> set[int]:
    """Return the numbers of the lines of ``before`` that ``after`` changes (same count)."""
    old, new = before.split('\n'), after.split('\n')
    assert len(old) == len(new)
    return {number for number, (one, two) in enumerate(zip(old, new), start=1) if one != two}


def _cited(output: str, name: str) -> set[int]:
    return {int(line) for line in re.findall(rf'^{re.escape(name)}:(\d+):\d+: ', output,
                                             re.MULTILINE)}


def test_values_in_a_macro_body_and_a_property_are_edited_where_written(robot: Path) -> None:
    codes = [f.code for f in Robot.from_xacro(robot).validate()]
    assert codes.count('J104') == 2 and codes.count('J102') == 2  # both instances
    result = _check(robot, '--fix')
    parts = (robot.parent / 'parts.xacro').read_text()
    changed = _changed(PARTS, parts)
    assert changed and changed <= _cited(result.stdout, 'parts.xacro')  # only lines it names
    assert (robot.parent / 'r.urdf.xacro').read_text() == TOP
    assert 'every instance of the macro changes, 2 in this robot' in result.stdout
    assert 'a property: every use of it changes' in result.stdout
    assert '  <xacro:property name="axis" value="0 1 0"/>' in parts.split('\n')
    fixed = Robot.from_urdf_string(xacro_expand(robot))  # the real xacro, no map
    assert not {'J104', 'J102'} & {f.code for f in fixed.validate()}
    assert {joint.limit.lower for joint in fixed.joints if joint.limit} == {-1.5}


def test_dry_run_shows_the_same_edit_and_writes_nothing(robot: Path) -> None:
    shown = _check(robot, '--fix', '--dry-run').stdout
    assert (robot.parent / 'parts.xacro').read_text() == PARTS
    added = [line[1:] for line in shown.splitlines()
             if line.startswith('+') and not line.startswith('+++')]
    _check(robot, '--fix')
    parts = (robot.parent / 'parts.xacro').read_text().split('\n')
    assert added == [parts[number - 1] for number in sorted(_changed(PARTS, '\n'.join(parts)))]


def test_a_value_that_differs_between_instances_is_refused(robot: Path) -> None:
    text = TOP.replace('<xacro:arm prefix="right_"/>', '')
    parts = PARTS.replace('params="prefix"', 'params="prefix lower"').replace(
        'lower="1.5"', 'lower="${lower}"')
    (robot.parent / 'parts.xacro').write_text(parts)
    robot.write_text(text.replace('<xacro:arm prefix="left_"/>',
                                  '<xacro:arm prefix="left_" lower="1.5"/>'))
    result = _check(robot, '--fix')
    assert (robot.parent / 'parts.xacro').read_text().count('${lower}') == 1
    assert "not fixed: J104 joint 'left_elbow': lower=\"${lower}\"" in result.stdout
    assert 'is an expression: repair it by hand' in result.stdout
    assert result.stdout.count('by hand') == 1  # said once
    assert result.exit_code == 2


ROOT_WITH_MASS = f"""<?xml version="1.0"?>
<robot name="m" {NS}>
  <xacro:macro name="body" params="name">
    <link name="${{name}}">{INERTIAL}</link>
  </xacro:macro>
  <xacro:body name="base_link"/>
  <xacro:body name="arm"/>
  <joint name="j" type="revolute"><parent link="base_link"/><child link="arm"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_a_warning_xacro_fix_leaves_is_repaired_as_the_advice_says(tmp_path: Path) -> None:
    """I205 (a root with mass) is a warning, which convert --fix leaves: check --fix does it."""
    from helpers import check_urdf, require_module
    yourdfpy = require_module('yourdfpy')
    robot = tmp_path / 'm.urdf.xacro'
    robot.write_text(ROOT_WITH_MASS)
    said = _check(robot, '--fix').output
    assert 'I205' in said and 'OUT.urdf --fix' not in said
    assert 'urdfgenpy convert m.urdf.xacro OUT.urdf and repair that with urdfgenpy check ' \
           '--fix OUT.urdf' in said
    out = tmp_path / 'OUT.urdf'
    runner = CliRunner()
    assert runner.invoke(main, ['convert', str(robot), str(out)]).exit_code == 0
    runner.invoke(main, ['check', '--fix', str(out)])
    assert 'I205' not in runner.invoke(main, ['check', str(out)]).output
    assert check_urdf(out).returncode == 0  # urdfdom reads the repaired copy
    model = yourdfpy.URDF.load(str(out), build_scene_graph=False, load_meshes=False)
    children = {joint.child for joint in model.robot.joints}
    roots = [link for link in model.robot.links if link.name not in children]
    assert len(roots) == 1 and roots[0].inertial is None  # a massless root, as KDL wants
