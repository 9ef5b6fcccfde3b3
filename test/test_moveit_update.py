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
``urdfgenpy srdf --update``: the matrix recomputed, every hand-written line kept.

Judged on example-robot-data's own Panda SRDF, whose matrix is the one the Setup
Assistant computed: updating it gives the file back byte for byte; edited by hand, every
line not of the computed matrix comes back as it was, in its place.
"""

from __future__ import annotations

import difflib
from pathlib import Path
import re

from click.testing import CliRunner
from helpers import require_module
import pytest
from test_moveit_srdf import _share, _urdf

from urdfgenpy_ros.cli import main

COMPUTED = re.compile(r'reason="(Adjacent|Default|Always|Never)"')


def _shipped() -> Path:
    return _share() / 'example-robot-data/robots/panda_description/srdf/panda.srdf'


def _update(path: Path) -> str:
    result = CliRunner().invoke(main, ['srdf', str(_urdf('panda')), '-o', str(path),
                                       '--update', str(path), '-p', str(_share())])
    assert result.exit_code == 0, result.output
    return result.stdout


@pytest.mark.slow  # 10,000 states, as the shipped file was computed with
def test_an_unchanged_matrix_gives_the_file_back_byte_for_byte(tmp_path: Path) -> None:
    require_module('coal')
    path = tmp_path / 'panda.srdf'
    path.write_bytes(_shipped().read_bytes())
    assert 'unchanged' in _update(path)
    assert path.read_bytes() == _shipped().read_bytes()


@pytest.mark.slow
def test_hand_written_lines_are_kept_and_changes_said(tmp_path: Path) -> None:
    require_module('coal')
    lines = _shipped().read_text().splitlines(keepends=True)
    dropped = next(line for line in lines if 'link2="panda_link3" reason="Never"' in line)
    lines.remove(dropped)  # a computed pair lost: added back
    wrong = next(n for n, line in enumerate(lines) if 'reason="Never"' in line)
    lines[wrong] = lines[wrong].replace('"Never"', '"Always"')  # its reason changed back
    at = next(n for n, line in enumerate(lines) if '<disable_collisions' in line)
    lines[at:at] = ['    <!-- pairs below: computed; the User one is mine -->\n',
                    '    <disable_collisions link1="panda_link0" link2="panda_link7" '
                    'reason="User"/>\n',
                    '    <disable_collisions link1="old_link" link2="panda_link0" '
                    'reason="Never"/>\n']  # a link renamed since: removed
    path = tmp_path / 'panda.srdf'
    path.write_text(''.join(lines))
    said = _update(path)
    assert f'added {dropped.split(chr(34))[1]} panda_link3 (Never)' in said
    assert 'removed old_link panda_link0 (Never)' in said
    assert re.search(r'changed \S+ \S+ \(Always -> Never\)', said)
    out = path.read_text().splitlines(keepends=True)
    hand = [line for line in lines if not COMPUTED.search(line)]
    assert [line for line in out if not COMPUTED.search(line)] == hand
    changes = [d for d in difflib.ndiff(lines, out) if d[:2] in ('- ', '+ ')]
    assert len(changes) == 4, changes  # stale line out, wrong line out and in, lost one in
    assert dropped in out  # in the file's indentation and quotes


def _matrix(**pairs: str):
    from urdfgenpy_ros.moveit.collision_matrix import CollisionMatrix, Reason
    disabled = {tuple(key.split('__')): Reason(value) for key, value in pairs.items()}
    return CollisionMatrix(disabled, (), 0, 0, 1)


def test_commented_elements_quotes_and_an_empty_matrix_block() -> None:
    from urdfgenpy_ros.moveit.srdf_update import update_text
    text = ("<robot name='r'>\n  <group name='g'/>\n"
            "  <!-- <disable_collisions link1='a' link2='b' reason='Never'/> -->\n"
            "  <disable_collisions link1='a' link2='c' reason='Adjacent'/>\n</robot>\n")
    update = update_text(text, _matrix(a__b='Never', a__c='Adjacent'))
    assert update.text == text.replace(
        "reason='Adjacent'/>\n", "reason='Adjacent'/>\n  <disable_collisions link1='a' "
        "link2='b' reason='Never'/>\n")  # the commented one is a comment, left alone
    bare = '<robot name="r">\n    <group name="g"/>\n</robot>\n'
    assert update_text(bare, _matrix(a__b='Default')).text == bare.replace(
        '</robot>', '    <disable_collisions link1="a" link2="b" reason="Default"/>\n</robot>')
