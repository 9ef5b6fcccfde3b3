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

"""ReviewOptions takes and refuses what the command line takes and refuses."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
import pytest

from urdfgenpy_ros import Link, review, ReviewOptions, Robot
from urdfgenpy_ros.cli import main


def _bare(tmp_path: Path) -> Path:
    path = tmp_path / 'bare.urdf'
    Robot('bare').add_link(Link('base_link')).to_urdf(path)  # I209: nothing has mass
    return path


def test_codes_as_one_string_silence_as_the_ignore_option_does(tmp_path: Path) -> None:
    path = _bare(tmp_path)
    robot = Robot.from_urdf(path)
    assert 'I209' in {finding.code for finding in review(robot, ReviewOptions()).findings}
    as_string = review(robot, ReviewOptions(ignore='I209, i205'))
    as_set = review(robot, ReviewOptions(ignore={'I209', 'I205'}))
    assert [f.code for f in as_string.findings] == [f.code for f in as_set.findings]
    assert 'I209' not in {finding.code for finding in as_string.findings}
    result = CliRunner().invoke(main, ['check', str(path), '--ignore', 'I209,i205'])
    assert 'I209' not in result.output and result.exit_code == 0, result.output


@pytest.mark.parametrize('option, value, cli', [
    ('ignore', {'XYZ'}, ['--ignore', 'XYZ']),
    ('target', 'humble', ['--target', 'humble']),
    ('engines', 'bullet', ['--engines', 'bullet']),
])
def test_what_the_command_refuses_the_options_refuse(
        tmp_path: Path, option: str, value: object, cli: list[str]) -> None:
    result = CliRunner().invoke(main, ['check', str(_bare(tmp_path)), *cli])
    assert result.exit_code == 2 and len(result.stderr.splitlines()) == 1, result.output
    with pytest.raises(ValueError, match=repr(value) if isinstance(value, str) else 'XYZ'):
        ReviewOptions(**{option: value})  # type: ignore[arg-type]


@pytest.mark.parametrize('given', ['effort=-5', 'velocity=0', 'effort=nan', 'lower=inf'])
def test_a_limit_default_that_is_no_limit_is_refused(tmp_path: Path, given: str) -> None:
    result = CliRunner().invoke(main, ['check', str(_bare(tmp_path)), '--fix',
                                       '--limit-default', given])
    assert result.exit_code == 2, result.output
    assert "Invalid value for '--limit-default'" in result.stderr
