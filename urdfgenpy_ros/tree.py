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

"""The kinematic tree as text: plain for files, coloured on a terminal."""

from __future__ import annotations

from collections.abc import Callable
from os import PathLike
from pathlib import Path
import sys
from typing import TextIO, TYPE_CHECKING

from urdfgenpy_ros.report import counted

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.model.joint import Joint
    from urdfgenpy_ros.model.link import Link

_COLOURS = {'robot': '1', 'link': '1;32', 'joint': '0', 'fixed': '90', 'revolute': '36',
            'continuous': '34', 'prismatic': '35', 'floating': '31', 'planar': '31',
            'shape': '33', 'line': '90'}

Paint = Callable[[str, str], str]


def _plain(_: str, text: str) -> str:
    return text


def _ansi(kind: str, text: str) -> str:
    return f'\033[{_COLOURS.get(kind, "0")}m{text}\033[0m'


def _shape(link: Link, paint: Paint) -> str:
    visual = link.visual or link.collision
    if visual is None:
        return ''
    return ' ' + paint('shape', f'({type(visual.geometry).__name__.lower()})')


def tree_string(robot: RobotModel, colour: bool = False) -> str:
    """
    Return the tree of ``robot``: each line a joint, its type and its child link.

    Several roots are drawn one after another; links no root reaches (a loop) are
    listed at the end.
    """
    paint = _ansi if colour else _plain
    children: dict[str, list[Joint]] = {}
    for joint in robot.joints:
        children.setdefault(joint.parent, []).append(joint)
    lines = [paint('robot', f'robot {robot.name}') +
             f": {counted(len(robot.links), 'link')}, {counted(len(robot.joints), 'joint')}"]
    seen: set[str] = set()

    def draw(link_name: str, prefix: str) -> None:
        kids = children.get(link_name, [])
        for number, joint in enumerate(kids):
            last = number == len(kids) - 1
            branch = paint('line', '└── ' if last else '├── ')
            shape = (_shape(robot.get_link(joint.child), paint) if robot.has_link(joint.child)
                     else ' (missing link)')
            lines.append(f'{prefix}{branch}{paint("joint", joint.name)} '
                         f'{paint(joint.type.value, "[" + joint.type.value + "]")} → '
                         f'{paint("link", joint.child)}{shape}')
            if joint.child not in seen:
                seen.add(joint.child)
                draw(joint.child, prefix + paint('line', '    ' if last else '│   '))

    for root in robot.roots:
        seen.add(root.name)
        lines.append(paint('link', root.name) + _shape(root, paint))
        draw(root.name, '')
    stray = [link.name for link in robot.links if link.name not in seen]
    if stray:
        lines.append('not reachable from a root: ' + ', '.join(stray))
    return '\n'.join(lines) + '\n'


def print_tree(robot: RobotModel, stream: TextIO | None = None) -> None:
    """Print the tree, coloured only when the stream is a terminal."""
    stream = stream or sys.stdout
    stream.write(tree_string(robot, colour=stream.isatty()))


def save_tree(robot: RobotModel, path: str | PathLike[str]) -> None:
    """Write the plain tree to ``path`` as UTF-8."""
    Path(path).write_text(tree_string(robot), encoding='utf-8')
