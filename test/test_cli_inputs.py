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

"""``check`` of a folder reads every description under it; '=' for ':=' is named."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
import pytest

from urdfgenpy_ros import Joint, Link, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.examples import pan_tilt_unit

XACRO = """<?xml version="1.0"?>
<robot name="post" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="use_sim" default="false"/>
  <link name="base_link"><visual><geometry><box size="0.1 0.1 $(arg use_sim) and 1 or 1"/>
  </geometry></visual></link>
</robot>
"""


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    root = tmp_path / 'urdf'
    (root / 'parts').mkdir(parents=True)
    pan_tilt_unit().to_urdf(root / 'ptu.urdf')
    robot = pan_tilt_unit()
    robot.get_joint('pan_joint').limit.lower = 4.0  # J104
    robot.to_urdf(root / 'parts' / 'bad.urdf')
    (root / '.git').mkdir()
    (root / '.git' / 'broken.urdf').write_text('<robot')  # hidden: not read
    (root / 'notes.txt').write_text('not a description')
    return root


def test_check_of_a_folder_reads_every_description_under_it(folder: Path) -> None:
    result = CliRunner().invoke(main, ['check', str(folder)])
    assert result.exit_code == 1, result.output
    one_by_one = [CliRunner().invoke(main, ['check', str(path)])
                  for path in (folder / 'parts' / 'bad.urdf', folder / 'ptu.urdf')]
    assert [r.exit_code for r in one_by_one] == [1, 0]
    findings = [line for r in one_by_one for line in r.stdout.splitlines()]
    assert result.stdout.splitlines() == findings  # the same, file by file, in order
    assert result.stderr.splitlines()[-1].startswith('2 file(s): 1 error(s)')


def test_a_clean_single_file_prints_its_summary(folder: Path) -> None:
    result = CliRunner().invoke(main, ['check', str(folder / 'ptu.urdf')])
    assert result.exit_code == 0 and result.stdout == ''
    assert result.stderr == '1 file(s): 0 error(s), 0 warning(s), 0 unreadable\n'


def test_an_empty_folder_is_one_line(tmp_path: Path) -> None:
    result = CliRunner().invoke(main, ['check', str(tmp_path)])
    assert result.exit_code == 2
    assert 'a folder with no .urdf or .xacro file under it' in result.stderr


@pytest.mark.parametrize('command', [['check'], ['tree'], ['convert']])
def test_an_argument_written_with_equals_gets_its_colon_spelling(
        command: list[str], tmp_path: Path) -> None:
    source = tmp_path / 'post.urdf.xacro'
    source.write_text(XACRO)
    target = [str(tmp_path / 'out.urdf')] if command == ['convert'] else []
    result = CliRunner().invoke(main, [*command, str(source), *target, 'use_sim=true'])
    assert result.exit_code == 2
    assert 'use_sim:=true' in result.stderr and 'unknown suffix' not in result.stderr


def test_render_names_a_second_joint_value_given_without_its_option(tmp_path: Path) -> None:
    pan_tilt_unit().to_urdf(tmp_path / 'ptu.urdf')
    result = CliRunner().invoke(main, ['render', str(tmp_path / 'ptu.urdf'), '-o',
                                       str(tmp_path / 'p.png'), '-j', 'pan_joint=1',
                                       'tilt_joint=0.5'])
    assert result.exit_code == 2
    assert "'tilt_joint=0.5': give each joint its own --joints (-j tilt_joint=0.5)" in \
        result.stderr


def test_counts_of_one_are_singular(tmp_path: Path) -> None:
    robot = Robot('pan').add_link(Link('base_link')).add_link(Link('head'))
    robot.add_joint(Joint('pan_joint', 'fixed', 'base_link', 'head'))
    robot.to_urdf(tmp_path / 'pan.urdf')
    result = CliRunner().invoke(main, ['convert', str(tmp_path / 'pan.urdf'),
                                       str(tmp_path / 'pan.sdf')])
    assert result.exit_code == 0, result.output
    # the massless head on a fixed joint is an SDF frame, with one for its joint
    assert result.stdout.rstrip().endswith(': 1 link, 0 joints, 2 frames')
    tree = CliRunner().invoke(main, ['tree', str(tmp_path / 'pan.urdf')])
    assert '2 links, 1 joint' in tree.stdout and '1 joints' not in tree.stdout
