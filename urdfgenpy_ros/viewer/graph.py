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


"""The kinematic tree as a Graphviz diagram: links as boxes, joints as labelled edges."""

from __future__ import annotations

from os import PathLike
from pathlib import Path

from urdfgenpy_ros.model.errors import MissingDependencyError, UrdfgenpyError
from urdfgenpy_ros.model.joint import Joint, JointType
from urdfgenpy_ros.report import counted
from urdfgenpy_ros.robot import Robot

FORMATS = ('svg', 'png', 'pdf', 'dot')
_DIM = '#9a9a9a'


def _number(value: float) -> str:
    return f'{value:.4g}'


def joint_label(joint: Joint) -> str:
    """Return an edge's label: name, type, then axis and limits where they mean something."""
    lines = [joint.name, f'[{joint.type}]']
    if joint.type not in (JointType.FIXED, JointType.FLOATING):
        lines.append('axis ' + ' '.join(_number(v) for v in joint.effective_axis))
    limit = joint.limit
    if limit is not None and joint.type in (JointType.REVOLUTE, JointType.PRISMATIC):
        unit = 'm' if joint.type is JointType.PRISMATIC else 'rad'
        lines.append(f'{_number(limit.lower)} .. {_number(limit.upper)} {unit}')
    if joint.mimic is not None:
        lines.append(f'mimics {joint.mimic.joint}')
    return '\n'.join(lines)


def _stagger(robot: Robot) -> int:
    """
    Return how many ranks to stagger the leaves of a wide rank over (1: no need).

    A mobile base with forty sensor frames on its base link is one rank forty boxes wide:
    drawn as it is, a strip thousands of pixels wide. Such a tree is drawn left to right
    and Graphviz's ``unflatten`` staggers the leaves over about as many ranks as the
    square root of the width.
    """
    depth: dict[str, int] = {}
    for root in robot.roots:
        for joint, link in robot.walk(root):
            depth[link.name] = depth[joint.parent] + 1 if joint is not None else 0
    ranks: dict[int, int] = {}
    for level in depth.values():
        ranks[level] = ranks.get(level, 0) + 1
    widest = max(ranks.values(), default=1)
    return max(1, round(widest ** 0.5)) if widest > 8 else 1


def to_dot(robot: Robot):  # -> graphviz.Digraph
    """
    Return the robot's tree as a ``graphviz.Digraph``.

    Node ids are ``link0``, ``link1``...: link names may hold ``:``, which Graphviz
    reads as a port. Each node's SVG ``id`` is ``link:<name>``, each edge's ``joint:<name>``.

    :raises MissingDependencyError: without the Python package graphviz.
    """
    try:
        import graphviz
    except ImportError:
        raise MissingDependencyError('graphviz', 'graph', 'urdfgenpy graph') from None
    direction = 'LR' if _stagger(robot) > 1 else 'TB'
    dot = graphviz.Digraph(robot.name, graph_attr={
        'rankdir': direction,
        'label': f"{robot.name}: {counted(len(robot.links), 'link')}, "
                 f"{counted(len(robot.joints), 'joint')}",
        'labelloc': 't', 'fontname': 'Helvetica', 'nodesep': '0.3', 'ranksep': '0.45'},
        node_attr={'shape': 'box', 'style': 'rounded,filled', 'fillcolor': '#e8eef7',
                   'color': '#34568b', 'fontname': 'Helvetica', 'fontsize': '12'},
        edge_attr={'fontname': 'Helvetica', 'fontsize': '9', 'color': '#34568b'})
    ids = {link.name: f'link{index}' for index, link in enumerate(robot.links)}
    for link in robot.links:
        dot.node(ids[link.name], link.name, id=f'link:{link.name}')
    for joint in robot.joints:
        if joint.parent not in ids or joint.child not in ids:
            continue  # validation reports the dangling joint; the diagram draws what exists
        attributes = {'id': f'joint:{joint.name}'}
        if joint.type is JointType.FIXED:
            attributes.update(color=_DIM, fontcolor=_DIM, style='dashed')
        dot.edge(ids[joint.parent], ids[joint.child], joint_label(joint), **attributes)
    return dot


def save_graph(robot: Robot, path: str | PathLike[str], file_format: str | None = None
               ) -> Path:
    """
    Draw the tree of ``robot`` to ``path`` (svg, png, pdf, or dot source) and return it.

    :raises MissingDependencyError: without the Python package graphviz.
    :raises UrdfgenpyError: without Graphviz's ``dot`` program, or for an unknown format.
    """
    path = Path(path)
    kind = (file_format or path.suffix.lstrip('.')).lower()
    if kind not in FORMATS:
        raise UrdfgenpyError(f'{path}: unknown diagram format {kind!r} (use one of '
                             f'{", ".join(FORMATS)})')
    path.write_bytes(diagram(robot, kind))
    return path


def diagram(robot: Robot, file_format: str = 'svg') -> bytes:
    """
    Return the tree of ``robot`` drawn as ``file_format`` (svg, png, pdf, or dot source).

    :raises MissingDependencyError: without the Python package graphviz.
    :raises UrdfgenpyError: without Graphviz's ``dot`` program.
    """
    dot = to_dot(robot)
    if file_format == 'dot':
        return dot.source.encode()
    import graphviz
    stagger = _stagger(robot)
    try:
        if stagger > 1:  # a wide flat rank: leaves over several ranks (Graphviz's unflatten)
            return dot.unflatten(stagger=stagger).pipe(format=file_format)
        return dot.pipe(format=file_format)
    except graphviz.ExecutableNotFound:
        raise UrdfgenpyError("drawing the tree needs Graphviz's 'dot' program: apt install "
                             "graphviz (or your system's package of it)") from None
