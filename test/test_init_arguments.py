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

"""init takes Xacro arguments as NAME:=VALUE, as every other command does."""

from __future__ import annotations

from pathlib import Path

from helpers import FIXTURES, require_module
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.scaffold.command import main as init

PACKAGES = FIXTURES / 'packages'
ARM = PACKAGES / 'fixture_description' / 'urdf' / 'arm.urdf.xacro'


def _joints(folder: Path, name: str) -> list[str]:
    """Return the joints of the generated package's robot, expanded by the real xacro."""
    return [joint.name for joint in Robot.from_urdf_string(_expand(folder / name)).joints]


def _expand(package: Path) -> str:
    """Expand the generated top-level file with xacro, its own package found by name."""
    xacro = require_module('xacro')
    from xacro import substitution_args
    original = substitution_args._eval_find
    substitution_args._eval_find = lambda name: str(package)  # noqa: E731 - one package
    try:
        return xacro.process_file(str(package / 'urdf' / 'fixture_arm.urdf.xacro')).toxml()
    finally:
        substitution_args._eval_find = original


@pytest.mark.parametrize('arguments', [
    ['--from', str(ARM), 'dof:=4', 'gripper:=true'],
    ['dof:=4', '--from', str(ARM), 'gripper:=true'],
    ['--from', str(ARM), '--xacro-args', 'dof:=4', 'gripper:=true'],
])
def test_name_value_arguments_anywhere_as_with_the_old_option(
        arguments: list[str], tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code = init(['arm_description', *arguments, '-p', str(PACKAGES),
                 '--destination-directory', str(tmp_path)])
    assert code == 0, capsys.readouterr().err
    expected = Robot.from_xacro(ARM, {'dof': '4', 'gripper': 'true'},
                                search_paths=[PACKAGES]).joints
    assert sorted(_joints(tmp_path, 'arm_description')) == sorted(j.name for j in expected)


@pytest.mark.parametrize('arguments, said', [
    (['--from', str(ARM), 'oops'], "unexpected argument 'oops': after the package name come "
                                   'Xacro arguments, NAME:=VALUE'),
    (['dof:=4'], 'Xacro arguments dof:=4 without --from'),
])
def test_a_word_that_is_no_argument_is_one_line(arguments: list[str], said: str,
                                                tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    assert init(['arm_description', *arguments, '--destination-directory',
                 str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert said in err and 'Traceback' not in err
    assert not (tmp_path / 'arm_description').exists()
