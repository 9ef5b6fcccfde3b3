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

"""Structure: one root, no loops, joints between existing links, valid names."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from urdfgenpy_ros.model.findings import Findings, joint_path, link_path

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

_FRAME_NAME = re.compile(r'^[A-Za-z_][A-Za-z0-9_./-]*$')


def check_topology(robot: RobotModel, findings: Findings) -> None:
    """Find missing links, self-joints, links with two parents, loops and root problems."""
    parents: dict[str, list[str]] = {}
    for joint in robot.joints:
        where = joint_path(joint.name)
        for role, code in (('parent', 'S004'), ('child', 'S005')):
            name = getattr(joint, role)
            if not robot.has_link(name):
                findings.add(code, joint, f'joint {joint.name!r}', f'{where}/{role}',
                             f'{role} link {name!r} does not exist',
                             f'define <link name="{name}"/> or fix the name', role)
        if joint.parent == joint.child:
            findings.add('S006', joint, f'joint {joint.name!r}', where,
                         f'parent and child are both {joint.child!r}',
                         'a joint connects two different links')
        parents.setdefault(joint.child, []).append(joint.name)
    for child, joints in parents.items():
        if len(joints) > 1 and robot.has_link(child):
            findings.add('S007', robot.get_link(child), f'link {child!r}', link_path(child),
                         f'is the child of {len(joints)} joints: '
                         + ', '.join(repr(name) for name in joints),
                         'URDF is a tree: keep one joint, or add a link per joint')
    looped = _check_loops(robot, findings)
    roots = robot.roots
    if not robot.links:
        findings.add('S001', robot, f'robot {robot.name!r}', '/robot', 'has no link',
                     'a robot needs at least one <link> (e.g. <link name="base_link"/>)')
    elif not roots and looped:
        findings.add('S001', robot, f'robot {robot.name!r}', '/robot',
                     "every link is some joint's child, so there is no root",
                     "break the loop: one link must be no joint's child")
    # Without a loop, a missing root is a joint's missing parent: S004 says so already.
    elif len(roots) > 1:
        names = ', '.join(repr(link.name) for link in roots)
        findings.add('S002', roots[1], f'robot {robot.name!r}', link_path(roots[1].name),
                     f"{len(roots)} links are no joint's child: {names}",
                     'connect them with joints so that exactly one root is left')
    _check_names(robot, findings)


def _check_loops(robot: RobotModel, findings: Findings) -> bool:
    """Report every loop of joints; return whether there was one."""
    looped = False
    parent_of = {joint.child: joint for joint in robot.joints if joint.parent != joint.child}
    done: set[str] = set()  # links whose way up is known to end (or was reported)
    for start in parent_of:
        chain: dict[str, None] = {}
        current = start
        while current in parent_of and current not in chain and current not in done:
            chain[current] = None
            current = parent_of[current].parent
        done.update(chain)
        if current in chain:
            names_up = list(chain)
            loop = names_up[names_up.index(current):]
            joint = parent_of[current]
            names = ' -> '.join(parent_of[link].name for link in loop)
            findings.add('S003', joint, f'joint {joint.name!r}', joint_path(joint.name),
                         f'joints form a loop: {names}',
                         'URDF is a tree: remove one joint of the loop (closed chains need '
                         'a simulator-specific constraint)')
            looped = True
    return looped


def _check_names(robot: RobotModel, findings: Findings) -> None:
    for kind, items, path in (('link', robot.links, link_path),
                              ('joint', robot.joints, joint_path)):
        for item in items:
            if not item.name or item.name.isspace():
                findings.add('S008', item, f'{kind} {item.name!r}', path(item.name),
                             'has an empty name', f'give the {kind} a name')
            elif not _FRAME_NAME.match(item.name):
                findings.add('S009', item, f'{kind} {item.name!r}', path(item.name),
                             'is not a valid ROS name (letters, digits, _ . / -, not '
                             'starting with a digit)',
                             'tf2 and ROS tools may refuse it: rename it')
    if robot.links and not robot.has_link('base_link'):
        root = robot.roots[0] if robot.roots else robot.links[0]
        findings.add('C401', root, f'robot {robot.name!r}', link_path(root.name),
                     "has no link called 'base_link'",
                     'ROS tools and REP 105 expect one: rename the main body base_link')
