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
Planning groups found from the tree: a chain per limb, a gripper per end effector.

A **gripper** starts at a link where two or more branches carry movable joints (fingers)
and below which at most two joints move on their own (mimic joints follow) and none is
continuous but a mimic one (wheels are not fingers; Robotiq's finger tips are); or at the
parent link of the one joint moving below it, when other joints mimic that joint and
nothing else moves below it. Its
group holds the links below that start; its mimic joints are passive.

A **chain** runs from the root or a branching link (two or more branches that move) down
the one branch that moves, to the link above a gripper, or to the end of the branch:
down fixed joints to the tool frame (the deepest link, when one path of fixed joints
goes deepest: UR's wrist_3_link, flange, tool0 beside ft_frame). A chain needs two
joints that move on their own. With one chain it is named ``arm``; with several, after
its tip link. A root link called ``world`` is the world frame: the search starts at the
link its one fixed joint holds. ``overrides`` (name to base and tip) name a chain, or
replace the found one with that tip or over the same joints.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.joint import JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


@dataclass(frozen=True)
class Group:
    """A planning group: a chain (``base``, ``tip``) or the ``links`` of a gripper."""

    name: str
    base: str | None = None
    tip: str | None = None
    links: tuple[str, ...] = ()


@dataclass(frozen=True)
class EndEffector:
    """A gripper group held by the tip of a chain group."""

    name: str
    parent_link: str
    group: str
    parent_group: str | None


class _Tree:
    """What the search asks of the tree: children, and the joints moving below a link."""

    def __init__(self, robot: RobotModel) -> None:
        self.robot = robot
        self.children = {link.name: list(robot.child_joints(link.name))
                         for link in robot.links}
        self.leaders = {joint.mimic.joint for joint in robot.joints if joint.mimic}
        self.free: dict[str, int] = {}  # joints moving on their own at or below each link
        self.moving: dict[str, int] = {}  # movable joints (mimic ones too) below each link
        self.turning: dict[str, bool] = {}  # a continuous joint at or below each link
        for joint, link in reversed(list(robot.walk())):
            below = self.children[link.name]
            self.turning[link.name] = any(  # a mimic joint turning on is a finger's
                self.turning[j.child] or (j.type is JointType.CONTINUOUS and j.mimic is None)
                for j in below)
            self.free[link.name] = sum(self.free[j.child] + _free(j) for j in below)
            self.moving[link.name] = sum(self.moving[j.child] + j.type.is_movable
                                         for j in below)

    def moving_branches(self, link: str) -> list[str]:
        """Return the child links of ``link`` whose joint or subtree moves."""
        return [joint.child for joint in self.children[link]
                if joint.type.is_movable or self.moving[joint.child]]

    def is_gripper(self, link: str) -> bool:
        """Return whether fingers start at ``link`` (wheels, which turn on, do not count)."""
        if not 1 <= self.free[link] <= 2 or self.turning[link]:
            return False
        if len(self.moving_branches(link)) >= 2:
            return True
        moving = [joint for joint in self.children[link]
                  if joint.type.is_movable or self.moving[joint.child]]
        return (len(moving) == 1 and moving[0].name in self.leaders and bool(_free(moving[0]))
                and self.free[moving[0].child] == 0)


def _free(joint: object) -> int:
    return int(getattr(joint, 'type').is_movable and getattr(joint, 'mimic') is None)


def find_groups(robot: RobotModel, overrides: Mapping[str, tuple[str, str]] | None = None
                ) -> tuple[list[Group], list[EndEffector]]:
    """Return the planning groups and end effectors of ``robot`` (see the module doc)."""
    tree = _Tree(robot)
    grippers: list[str] = []
    chains: list[tuple[str, str]] = []
    top = start_link(robot)
    _search(tree, top, top, grippers, chains)
    named = _chain_names(chains)
    for name, (base, tip) in (overrides or {}).items():
        for link in (base, tip):
            try:
                robot.get_link(link)
            except KeyError as error:  # a name the user gave: their mistake, in one line
                raise ModelError(f'group {name!r}: {error.args[0]}') from None
        joints = _free_joints(robot, base, tip)  # a ModelError unless tip is below base
        named = {key: value for key, value in named.items()
                 if value[1] != tip and key != name and _free_joints(robot, *value) != joints}
        named[name] = (base, tip)
    groups = [Group(name, base, tip) for name, (base, tip) in named.items()]
    effectors = []
    for start in grippers:
        name = 'gripper' if len(grippers) == 1 else _gripper_name(start)
        groups.append(Group(name, links=tuple(link.name for link in robot.subtree(start))))
        parent = robot.parent_joint(start)
        above = parent.parent if parent is not None else start
        holder = next((key for key, (_, tip) in named.items() if tip == above), None)
        effectors.append(EndEffector(name, above, name, holder))
    return groups, effectors


def start_link(robot: RobotModel) -> str:
    """Return the root, or the link a root called ``world`` holds by its one fixed joint."""
    root = robot.root.name
    below = list(robot.child_joints(root))
    if root == 'world' and len(below) == 1 and below[0].type is JointType.FIXED:
        return below[0].child
    return root


def _free_joints(robot: RobotModel, base: str, tip: str) -> set[str]:
    return {joint.name for joint in robot.chain(tip, base) if _free(joint)}


def _tool_frame(tree: _Tree, link: str) -> str:
    """Return the deepest link below ``link`` by fixed joints, when one path goes deepest."""
    level = [link]
    while True:
        following = [joint.child for name in level for joint in tree.children[name]
                     if joint.type is JointType.FIXED]
        if not following:
            break
        level = following
    if len(level) == 1:
        return level[0]
    while len(tree.children[link]) == 1:  # several as deep: down while it does not branch
        link = tree.children[link][0].child
    return link


def _search(tree: _Tree, start: str, link: str, grippers: list[str],
            chains: list[tuple[str, str]]) -> None:
    """Walk down from ``link``, a chain starting at ``start``; record chains and grippers."""
    while True:
        if tree.is_gripper(link) and link != start:
            grippers.append(link)
            parent = tree.robot.parent_joint(link)
            _close(tree, start, parent.parent if parent is not None else link, chains)
            return
        branches = tree.moving_branches(link)
        if len(branches) >= 2 or (link == start and tree.is_gripper(link)):
            if link != start:
                _close(tree, start, link, chains)
            if tree.is_gripper(link):
                grippers.append(link)
                return
            for child in branches:
                _search(tree, link, child, grippers, chains)
            return
        if not branches:
            _close(tree, start, _tool_frame(tree, link), chains)
            return
        link = branches[0]


def _close(tree: _Tree, base: str, tip: str, chains: list[tuple[str, str]]) -> None:
    """Record the chain ``base`` to ``tip`` if two joints move on their own along it."""
    if sum(_free(joint) for joint in tree.robot.chain(tip, base)) >= 2:
        chains.append((base, tip))


def _short(link: str) -> str:
    return link[:-5] if link.endswith('_link') else link


def _gripper_name(link: str) -> str:
    short = _short(link)
    return short if 'gripper' in short or 'hand' in short else f'{short}_gripper'


def _chain_names(chains: list[tuple[str, str]]) -> dict[str, tuple[str, str]]:
    if len(chains) == 1:
        return {'arm': chains[0]}
    return {_short(tip): (base, tip) for base, tip in chains}


def parse_group(text: str) -> tuple[str, tuple[str, str]]:
    """Return ``NAME=BASE:TIP`` as (name, (base, tip)), or a ModelError saying the form."""
    name, equals, rest = text.partition('=')
    base, colon, tip = rest.partition(':')
    if not (equals and colon and name and base and tip):
        raise ModelError(f'group {text!r} is not NAME=BASE:TIP (e.g. arm=base_link:tool0)')
    return name, (base, tip)
