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
The SRDF of a robot: groups, states, end effectors, virtual joint and collision matrix.

Written in the order and layout of MoveIt's Setup Assistant (four-space indentation;
``group``, ``group_state``, ``end_effector``, ``virtual_joint``, ``passive_joint``, then
``disable_collisions`` sorted by link names), every name taken from the robot.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from os import PathLike
from pathlib import Path
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.dynamics import movable_joints
from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.floats import fmt
from urdfgenpy_ros.moveit import sampling, VIRTUAL_JOINTS
from urdfgenpy_ros.moveit.collision_matrix import CollisionMatrix, compute_matrix
from urdfgenpy_ros.moveit.gripper_states import opens_at_upper
from urdfgenpy_ros.moveit.groups import (EndEffector, find_groups, Group, parse_group,
                                         start_link)

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


@dataclass(frozen=True)
class GroupState:
    """A named set of joint values of one group."""

    name: str
    group: str
    values: tuple[tuple[str, float], ...]


@dataclass
class Srdf:
    """An SRDF's text and what it was made of."""

    text: str
    groups: list[Group]
    states: list[GroupState]
    end_effectors: list[EndEffector]
    matrix: CollisionMatrix
    notes: list[str] = field(default_factory=list)


def group_joints(robot: RobotModel, group: Group) -> list[str]:
    """Return the joints of ``group`` that move on their own, in the robot's order."""
    if group.base is not None and group.tip is not None:
        names = {joint.name for joint in robot.chain(group.tip, group.base)}
    else:
        links = set(group.links)
        names = {joint.name for joint in robot.joints if joint.child in links}
    return [name for name in movable_joints(robot) if name in names]


def group_states(robot: RobotModel, groups: list[Group], initial: Mapping[str, float],
                 notes: list[str] | None = None) -> list[GroupState]:
    """
    Return the states of the groups: ``home``, ``open`` and ``close``.

    ``home`` of each chain: ros2_control's initial values, else 0 (or mid-range where 0 is
    outside the limits). ``open`` and ``close`` of each gripper: its joints' limits where
    the finger tips lie farthest apart and nearest (:mod:`.gripper_states`); where that
    cannot be told, upper and lower, with a line in ``notes``.
    """
    default = dict(zip(movable_joints(robot), sampling.default_state(robot)))
    states = []
    for group in groups:
        joints = group_joints(robot, group)
        if not joints:
            continue
        if group.base is not None:
            states.append(GroupState('home', group.name, tuple(
                (name, float(initial.get(name, default[name]))) for name in joints)))
            continue
        ranges = {name: sampling.joint_bounds(robot.get_joint(name)) for name in joints}
        upper, note = opens_at_upper(robot, group.name, group.links, ranges)
        if note is not None and notes is not None:
            notes.append(note)
        for state, index in (('open', int(upper)), ('close', 1 - int(upper))):
            states.append(GroupState(state, group.name, tuple(
                (name, bounds[index]) for name, bounds in ranges.items())))
    return states


def state_values(states: list[GroupState], name: str) -> dict[str, float]:
    """Return the joint values of every state called ``name``, or a ModelError."""
    values = {joint: value for state in states if state.name == name
              for joint, value in state.values}
    if not values:
        known = sorted({state.name for state in states})
        raise ModelError(f'no group state {name!r} (the states are: {", ".join(known)})')
    return values


def build_srdf(robot: RobotModel, samples: int = 10000, seed: int = 0,
               groups: Mapping[str, Any] | list[str] | None = None,
               default_state: str | Mapping[str, float] | None = None,
               virtual_joint: str | None = 'fixed', search_paths: Any = (),
               rates: bool = False) -> Srdf:
    """
    Return the SRDF of ``robot`` with the matrix MoveIt's Setup Assistant would compute.

    ``groups``: chain groups to name or override, ``{'arm': ('base_link', 'tool0')}`` or
    ``['arm=base_link:tool0']``. ``default_state``: a group state's name (``home``) or
    joint values, for the "Default" step instead of zeros. ``virtual_joint``: ``fixed``,
    ``floating`` or ``planar`` to the world, or None for none (and none when the root
    link is called ``world``: the URDF holds the robot to the world). ``rates``: count
    each Default pair's collision rate over the samples (``Srdf.matrix.rates``).
    """
    if virtual_joint is not None and virtual_joint not in VIRTUAL_JOINTS:
        raise ModelError(f'virtual_joint {virtual_joint!r}: one of {", ".join(VIRTUAL_JOINTS)}'
                         ' or None')
    from urdfgenpy_ros.formats.mjcf.actuators import initial_values
    notes: list[str] = []
    if virtual_joint is not None and start_link(robot) != robot.root.name:
        virtual_joint = None
        notes.append("no virtual joint: the root link 'world' is the world frame (the URDF "
                     'fixes the robot to the world)')
    found, effectors = find_groups(robot, _overrides(groups))
    states = group_states(robot, found, initial_values(robot), notes)
    values = state_values(states, default_state) if isinstance(default_state, str) \
        else default_state
    matrix = compute_matrix(robot, samples, seed, values, search_paths, rates)
    text = write_text(robot, found, states, effectors, matrix, virtual_joint)
    return Srdf(text, found, states, effectors, matrix, notes)


def _overrides(groups: Mapping[str, Any] | list[str] | None) -> dict[str, tuple[str, str]]:
    if groups is None:
        return {}
    if isinstance(groups, Mapping):
        return {name: (str(value[0]), str(value[1])) for name, value in groups.items()}
    return dict(parse_group(text) for text in groups)


def write_text(robot: RobotModel, groups: list[Group], states: list[GroupState],
               effectors: list[EndEffector], matrix: CollisionMatrix,
               virtual_joint: str | None) -> str:
    """Return the SRDF document."""
    root = etree.Element('robot', name=robot.name)
    for group in groups:
        element = etree.SubElement(root, 'group', name=group.name)
        if group.base is not None and group.tip is not None:
            etree.SubElement(element, 'chain', base_link=group.base, tip_link=group.tip)
        for link in group.links:
            etree.SubElement(element, 'link', name=link)
    for state in states:
        element = etree.SubElement(root, 'group_state', name=state.name, group=state.group)
        for name, value in state.values:
            etree.SubElement(element, 'joint', name=name, value=fmt(value))
    for effector in effectors:
        attributes = {'name': effector.name, 'parent_link': effector.parent_link,
                      'group': effector.group}
        if effector.parent_group is not None:
            attributes['parent_group'] = effector.parent_group
        etree.SubElement(root, 'end_effector', attributes)
    if virtual_joint is not None:
        etree.SubElement(root, 'virtual_joint', name='virtual_joint', type=virtual_joint,
                         parent_frame='world', child_link=robot.root.name)
    gripper_links = {link for group in groups for link in group.links}
    for joint in robot.joints:
        if joint.mimic is not None and joint.type.is_movable and joint.child in gripper_links:
            etree.SubElement(root, 'passive_joint', name=joint.name)
    for (one, two), reason in matrix.disabled.items():
        etree.SubElement(root, 'disable_collisions', link1=one, link2=two,
                         reason=reason.value)
    etree.indent(root, space='    ')
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + etree.tostring(
        root, encoding='unicode', pretty_print=True)


def write_srdf(robot: RobotModel, path: str | PathLike[str] | None = None, **options: Any) -> Srdf:
    """Return the SRDF of ``robot`` (see :func:`build_srdf`); also write it to ``path``."""
    srdf = build_srdf(robot, **options)
    if path is not None:
        Path(path).write_text(srdf.text, encoding='utf-8')
    return srdf
