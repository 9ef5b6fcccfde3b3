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

"""A name defined twice on one line (a generator's one-line file) is P007 at its place too."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import check_urdf_verdict
import pytest

from urdfgenpy_ros.cli import main

TWICE = {
    'link': '<link name="a"/><link name="a"/>',
    'joint': ('<link name="a"/><link name="b"/>'
              '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'
              '<joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>'),
    'material': ('<material name="m"><color rgba="1 0 0 1"/></material>'
                 '<material name="m"><color rgba="0 1 0 1"/></material><link name="a"/>'),
}


@pytest.mark.parametrize('kind', sorted(TWICE))
def test_a_name_twice_on_one_line_is_p007_with_file_and_line(
        tmp_path: Path, kind: str) -> None:
    path = tmp_path / 'one_line.urdf'
    path.write_text(f'<robot name="x">\n{TWICE[kind]}</robot>\n')
    if kind != 'material':  # urdfdom refuses a link or joint twice (a material it keeps)
        assert not check_urdf_verdict(path, timeout=10)
    result = CliRunner().invoke(main, ['check', str(path), '--no-meshes'])
    assert result.exit_code == 2, result.output
    assert f'{path}:2:' in result.output and 'P007' in result.output, result.output
    assert f"{kind} {'a' if kind == 'link' else kind[0]!r} is defined twice" in result.output
