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

"""The kinematic tree as text: one line per joint, colour only on a terminal."""

from __future__ import annotations

import io
from pathlib import Path

from urdfgenpy_ros import Robot
from urdfgenpy_ros.tree import print_tree


class _Terminal(io.StringIO):

    def isatty(self) -> bool:
        return True


def test_tree_lists_every_joint_under_its_parent(every_element: Robot) -> None:
    lines = every_element.tree_string().splitlines()
    assert lines[0] == 'robot every_element: 8 links, 7 joints'
    assert lines[1] == 'base_link (box)'
    assert '│   └── cont [continuous] → cont_link (cylinder)' in lines
    for joint in every_element.joints:
        assert sum(f'{joint.name} [{joint.type.value}] → {joint.child}' in line
                   for line in lines) == 1


def test_colour_only_on_a_terminal(ptu: Robot) -> None:
    plain, terminal = io.StringIO(), _Terminal()
    print_tree(ptu, plain)
    print_tree(ptu, terminal)
    assert '\033[' not in plain.getvalue()
    assert '\033[' in terminal.getvalue()
    assert plain.getvalue() == ptu.tree_string()


def test_save_tree_writes_the_plain_text(ptu: Robot, tmp_path: Path) -> None:
    ptu.save_tree(tmp_path / 'tree.txt')
    assert (tmp_path / 'tree.txt').read_text(encoding='utf-8') == ptu.tree_string()
