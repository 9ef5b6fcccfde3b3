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

"""convert refuses, in one located line, a robot that is not one tree, before any other word."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import check_urdf_verdict
import pytest

from urdfgenpy_ros.cli import main

BROKEN = {  # case: (the joint's parent, its child, the code)
    'missing child': ('base', 'plat', 'S005'),  # 'plat' for 'plate'
    'missing parent': ('ghost', 'plate', 'S004'),
}


@pytest.mark.parametrize('declaration', ['<?xml version="1.0"?>', '<?xml< version="1.0"?>'],
                         ids=['declared', 'declaration malformed (a reader warning)'])
@pytest.mark.parametrize('case', sorted(BROKEN))
@pytest.mark.parametrize('suffix', ['sdf', 'xml'])
def test_a_robot_that_is_not_one_tree_is_one_line_naming_file_line_and_code(
        tmp_path: Path, case: str, suffix: str, declaration: str) -> None:
    parent, child, code = BROKEN[case]
    source = tmp_path / 'r.urdf'
    source.write_text(
        f'{declaration}\n<robot name="r">\n  <link name="base"/>\n'
        '  <link name="plate"/>\n'
        '  <joint name="j" type="fixed">\n'
        f'    <parent link="{parent}"/>\n    <child link="{child}"/>\n  </joint>\n</robot>\n')
    assert not check_urdf_verdict(source, timeout=10)  # urdfdom refuses it too
    target = tmp_path / f'out.{suffix}'
    result = CliRunner().invoke(main, ['convert', str(source), str(target)])
    assert result.exit_code == 2, result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr  # no mass warning before the refusal
    assert f'{source}:' in lines[0] and f'error {code}' in lines[0], lines[0]
    assert 'not written' in lines[0]
    assert not target.exists()
