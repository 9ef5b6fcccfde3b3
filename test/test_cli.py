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

"""The urdfgenpy command line."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import assert_check_urdf_accepts, load_yourdfpy, snapshot, xacro_expand
from urdfgenpy_ros.cli import main


def test_example_prints_the_tree_and_writes_urdf_and_xacro(tmp_path: Path) -> None:
    result = CliRunner().invoke(main, ['example', '--output-dir', str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert 'pan_joint [revolute] → pan_link' in result.output
    urdf, xacro = tmp_path / 'ptu.urdf', tmp_path / 'ptu.urdf.xacro'
    assert_check_urdf_accepts(urdf)
    expanded = tmp_path / 'expanded.urdf'
    expanded.write_text(xacro_expand(xacro))
    assert snapshot(load_yourdfpy(expanded)) == snapshot(load_yourdfpy(urdf))


def test_unwritable_output_is_one_line_and_exit_2(tmp_path: Path) -> None:
    blocker = tmp_path / 'file'
    blocker.write_text('x')
    result = CliRunner().invoke(main, ['example', '-o', str(blocker / 'sub')])
    assert result.exit_code == 2
    assert result.stdout == ''
    assert result.stderr.count('\n') == 1 and result.stderr.startswith('urdfgenpy: ')
    assert 'file/sub: Not a directory' in result.stderr
