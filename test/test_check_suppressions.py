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

"""Suppression comments and --ignore: they round-trip, and silence exactly what they name."""

from __future__ import annotations

from pathlib import Path
import re

from click.testing import CliRunner
from helpers import canonical, xacro_expand
from lxml import etree
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.validation.suppressions import read_suppressions
from validation_fixtures import broken

# Two joints with the same defect (a non-unit axis, J102) and a zero velocity (J106).
TWO_AXES = broken('J102').replace('<axis xyz="0 0 1"/>', '<axis xyz="0 0 3"/>').replace(
    'effort="10" velocity="1"/>', 'effort="10" velocity="0"/>')
IGNORE_SHOULDER = '  <!-- urdfgenpy: ignore J102 -->\n  <joint name="shoulder"'


def _codes(path: Path, *options: str) -> tuple[list[tuple[str, str]], str, int]:
    result = CliRunner().invoke(main, ['check', *options, str(path)])
    found = re.findall(r": (?:warning|error) (\w+) (\w+ '[^']*')", result.stdout)
    return sorted(found), result.stderr, result.exit_code


def _write(tmp_path: Path, text: str, name: str = 'robot.urdf') -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def test_without_comments_both_joints_are_reported(tmp_path: Path) -> None:
    found, _, _ = _codes(_write(tmp_path, TWO_AXES))
    assert found == [('J102', "joint 'shoulder'"), ('J102', "joint 'wrist'"),
                     ('J106', "joint 'shoulder'")]


def test_a_comment_silences_its_code_on_its_element_only(tmp_path: Path) -> None:
    text = TWO_AXES.replace('  <joint name="shoulder"', IGNORE_SHOULDER)
    found, summary, code = _codes(_write(tmp_path, text))
    # the other joint's J102 and the same joint's J106 stay
    assert found == [('J102', "joint 'wrist'"), ('J106', "joint 'shoulder'")]
    assert summary == '1 file(s): 0 error(s), 2 warning(s), 0 unreadable, 1 suppressed\n'
    assert code == 0


def test_a_comment_covers_the_elements_inside_and_not_the_ones_beside(tmp_path: Path) -> None:
    text = broken('I203').replace('<link name="arm">', '<!-- urdfgenpy: ignore I203 -->\n'
                                  '  <link name="arm">')
    assert _codes(_write(tmp_path, text))[0] == []  # the <inertia> inside the link
    inner = broken('I203').replace('    <inertial>\n      <origin xyz="0 0 0.1"/>',
                                   '    <!-- urdfgenpy: ignore I203 -->\n    <inertial>\n'
                                   '      <origin xyz="0 0 0.1"/>', 1)
    assert _codes(_write(tmp_path, inner))[0] == []
    beside = broken('I203').replace('    <visual>\n      <origin xyz="0 0 0.1"/>',
                                    '    <!-- urdfgenpy: ignore I203 -->\n    <visual>\n'
                                    '      <origin xyz="0 0 0.1"/>', 1)
    assert _codes(_write(tmp_path, beside))[0] == [('I203', "link 'arm'")]


def test_several_codes_and_stacked_comments(tmp_path: Path) -> None:
    text = TWO_AXES.replace('  <joint name="shoulder"', '  <!-- urdfgenpy: ignore J106 -->\n'
                            '  <!-- urdfgenpy: ignore J102 -->\n  <joint name="shoulder"')
    text = text.replace('  <joint name="wrist"', '  <!-- urdfgenpy: ignore J102, J106 -->\n'
                        '  <joint name="wrist"')
    found, summary, _ = _codes(_write(tmp_path, text))
    assert found == [] and summary.endswith(', 3 suppressed\n')


def test_file_level_comment_and_ignore_option(tmp_path: Path) -> None:
    top = TWO_AXES.replace('<?xml version="1.0"?>\n', '<?xml version="1.0"?>\n'
                           '<!-- urdfgenpy: ignore-file J102 -->\n')
    assert _codes(_write(tmp_path, top))[0] == [('J106', "joint 'shoulder'")]
    inside = TWO_AXES.replace('<robot name="fixture">\n', '<robot name="fixture">\n'
                              '  <!-- urdfgenpy: ignore-file J102 J106 -->\n')
    assert _codes(_write(tmp_path, inside))[0] == []
    late = TWO_AXES.replace('</robot>', '<!-- urdfgenpy: ignore-file J102 -->\n</robot>')
    assert len(_codes(_write(tmp_path, late))[0]) == 3  # not at the top: no effect
    path = _write(tmp_path, TWO_AXES)
    found, summary, _ = _codes(path, '--ignore', 'J106', '--ignore', 'C401,J102')
    assert found == [] and summary.endswith(', 3 suppressed\n')
    bad = CliRunner().invoke(main, ['check', '--ignore', 'J10', str(path)])
    assert bad.exit_code == 2 and 'J10 is not a finding code' in bad.output


def test_an_error_silenced_does_not_fail_the_run(tmp_path: Path) -> None:
    text = broken('J104').replace('  <joint name="wrist"', '  <!-- urdfgenpy: ignore J104 -->'
                                  '\n  <joint name="wrist"')
    assert _codes(_write(tmp_path, text))[2] == 0
    assert _codes(_write(tmp_path, broken('J104')))[2] == 1


@pytest.mark.parametrize('edit', [False, True])
def test_comments_round_trip_through_read_and_write(edit: bool, tmp_path: Path) -> None:
    text = TWO_AXES.replace('  <joint name="shoulder"', IGNORE_SHOULDER).replace(
        '<?xml version="1.0"?>\n', '<?xml version="1.0"?>\n<!-- urdfgenpy: ignore-file C401 -->\n')
    robot = Robot.from_urdf(_write(tmp_path, text))
    if edit:  # the element right after the comment is written anew
        robot.get_joint('shoulder').axis = (0.0, 0.0, 1.0)
    written = robot.to_urdf()
    expected = text.replace('<axis xyz="0 0 3"/>', '<axis xyz="0 0 1"/>') if edit else text
    assert written == expected
    comments = [node.text for node in etree.fromstring(written.encode()).iter(etree.Comment)]
    assert ' urdfgenpy: ignore J102 ' in comments
    again = read_suppressions(Robot.from_urdf_string(written))
    assert again.file_codes == {'C401'}
    assert [(s.path, s.codes) for s in again.scopes] == [
        ("/robot/joint[@name='shoulder']", {'J102'})]


def test_fix_keeps_the_comments_and_leaves_silenced_findings_alone(tmp_path: Path) -> None:
    text = TWO_AXES.replace('  <joint name="shoulder"', IGNORE_SHOULDER)
    path = _write(tmp_path, text)
    result = CliRunner().invoke(main, ['check', '--fix', str(path)])
    assert path.read_text() == text.replace('<axis xyz="0 2 0"/>', '<axis xyz="0 1 0"/>')
    assert result.stderr.endswith(', 1 suppressed, 1 fixed\n')


def test_suppressions_in_xacro_survive_expansion(tmp_path: Path) -> None:
    text = TWO_AXES.replace('<robot name="fixture">', '<robot name="fixture" '
                            'xmlns:xacro="http://www.ros.org/wiki/xacro">').replace(
        '  <joint name="shoulder"', IGNORE_SHOULDER)
    path = _write(tmp_path, text, 'robot.urdf.xacro')
    assert canonical(xacro_expand(path)) == canonical(Robot.from_xacro(path).to_urdf())
    found, _, _ = _codes(path)
    assert found == [('J102', "joint 'wrist'"), ('J106', "joint 'shoulder'")]


def test_a_code_that_does_not_exist_is_said_not_silently_ignored(tmp_path: Path) -> None:
    path = tmp_path / 'typo.urdf'
    path.write_text('<?xml version="1.0"?>\n<robot name="r">\n'
                    '  <!-- urdfgenpy: ignore I2O5 C401 -->\n  <link name="a"/>\n</robot>\n')
    result = CliRunner().invoke(main, ['check', str(path)])
    assert f"{path}:3: warning: the suppression comment names 'I2O5'" in result.output
    assert ' C401 ' not in result.output  # the real code in it still works
    refused = CliRunner().invoke(main, ['check', '--ignore', 'I250', str(path)])
    assert refused.exit_code == 2 and 'I250 is not a finding code' in refused.output
    lower = CliRunner().invoke(main, ['check', '--ignore', 'c401', str(path)])
    assert lower.exit_code == 0 and '1 suppressed' in lower.output


def test_the_reader_keeps_the_comments_that_speak_to_it_as_data() -> None:
    text = ('<?xml version="1.0"?>\n<!-- urdfgenpy: ignore-file I205 -->\n'
            + TWO_AXES.replace('  <joint name="shoulder"', IGNORE_SHOULDER).split('\n', 1)[1]
            + '\n<!-- a plain comment -->')
    document = Robot.from_urdf_string(text).extras
    # lxml, reading the same text on its own, judges lines, texts and the element that follows
    root = etree.fromstring(text.encode())
    comments = [node for node in [*root.itersiblings(preceding=True), *root.iter(etree.Comment)]
                if 'urdfgenpy' in (node.text or '')]
    assert [(item.line, item.text) for item in document.directives] == [
        (node.sourceline, node.text) for node in comments]
    assert [item.leading for item in document.directives] == [True, False]
    shoulder = comments[1].getnext()
    assert document.directives[1][3:] == ("/robot/joint[@name='shoulder']", shoulder.sourceline,
                                          max(node.sourceline for node in shoulder.iter()))
