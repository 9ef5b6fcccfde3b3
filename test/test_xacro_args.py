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

"""A misspelt Xacro argument, which xacro ignores, is a warning naming the declared ones."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import xacro_expand
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main

PARTS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <link name="$(arg prefix)base_link"/>
</robot>
"""
TOP = """<?xml version="1.0"?>
<robot name="post" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="use_sim" default="false"/>
  <xacro:include filename="parts.xacro"/>
  <xacro:if value="$(arg use_sim)"><link name="sim_only"/>
    <joint name="j" type="fixed"><parent link="base_link"/><child link="sim_only"/></joint>
  </xacro:if>
</robot>
"""


def _files(tmp_path: Path) -> Path:
    (tmp_path / 'parts.xacro').write_text(PARTS)
    top = tmp_path / 'post.urdf.xacro'
    top.write_text(TOP)
    return top


def test_a_misspelt_argument_is_named_with_the_declared_ones(tmp_path: Path) -> None:
    top = _files(tmp_path)
    # xacro itself: the misspelt argument changes nothing, the right one does
    assert xacro_expand(top, {'usesim': 'true'}) == xacro_expand(top)
    assert 'sim_only' in xacro_expand(top, {'use_sim': 'true'})
    robot = Robot.from_xacro(top, {'usesim': 'true'})
    (warning,) = [w for w in robot.read_warnings if w.code == 'X103']
    assert "'usesim'" in warning.message and "did you mean 'use_sim'?" in warning.message
    assert 'use_sim, prefix' in warning.message  # declared in the top file and an include
    assert not [w for w in Robot.from_xacro(top, {'use_sim': 'true', 'prefix': 'a_'})
                .read_warnings if w.code == 'X103']


def test_the_cli_prints_it_once(tmp_path: Path) -> None:
    top = _files(tmp_path)
    result = CliRunner().invoke(main, ['tree', str(top), 'usesim:=true'])
    assert result.exit_code == 0
    assert result.stderr.count('warning X103') == 1


KINDS = {  # the argument picks the file read: a misspelling breaks the expansion
    'yaml': """<?xml version="1.0"?>
<robot name="kinds" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="kind" default="a"/>
  <xacro:property name="p" value="${xacro.load_yaml('config/$(arg kind)/p.yaml')}"/>
  <link name="base_${p['n']}"/>
</robot>
""",
    'include': """<?xml version="1.0"?>
<robot name="kinds" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="kind" default="a"/>
  <xacro:include filename="config/$(arg kind)/parts.xacro"/>
</robot>
"""}


@pytest.mark.parametrize('how', sorted(KINDS))
def test_a_misspelling_that_breaks_the_expansion_is_named_on_its_line(
        how: str, tmp_path: Path) -> None:
    (tmp_path / 'config' / 'b').mkdir(parents=True)
    (tmp_path / 'config' / 'b' / 'p.yaml').write_text('n: b\n')
    (tmp_path / 'config' / 'b' / 'parts.xacro').write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro"><link name="base_b"/></robot>')
    top = tmp_path / 'kinds.urdf.xacro'
    top.write_text(KINDS[how])
    assert 'base_b' in xacro_expand(top, {'kind': 'b'})  # xacro: the suggestion expands
    result = CliRunner().invoke(main, ['check', str(top), 'kimd:=b'])
    assert result.exit_code == 2
    (line,) = [line for line in result.stdout.splitlines() if ' error X001 ' in line]
    assert "'kimd' is not declared by the files read: did you mean 'kind'?" in line
    kept = CliRunner().invoke(main, ['check', str(top), 'kimd:=b', 'kind:=b'])  # expands
    assert ' X001 ' not in kept.stdout and "did you mean 'kind'?" in kept.stdout  # X103
