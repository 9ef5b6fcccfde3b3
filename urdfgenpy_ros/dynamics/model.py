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
A robot compiled to arrays for numpy: links in tree order, each with its joint.

Every link but the root has the joint that carries it: its origin (4x4, the rotation the
model gives, quaternion or rpy), its unit axis, and its motion (fixed, a turn, a shift).
Floating and planar joints stay at their origin, as robot_state_publisher draws them.
Mimic joints take ``multiplier * leader + offset`` of the independent joint they follow.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
import math
import operator
from typing import Any, TYPE_CHECKING

import numpy

from urdfgenpy_ros.caller import warn_caller
from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.joint import Joint, JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

FIXED, REVOLUTE, PRISMATIC = 0, 1, 2
AGREE = 1e-9  # relative: a mimic joint's given value this close to its leader's formula agrees
_MOTION = {JointType.REVOLUTE: REVOLUTE, JointType.CONTINUOUS: REVOLUTE,
           JointType.PRISMATIC: PRISMATIC}


@dataclass(frozen=True)
class ChainModel:
    """The arrays forward kinematics and statics run on (see the module docstring)."""

    links: tuple[str, ...]
    """Link names, every parent before its children (the root first)."""
    joints: tuple[str | None, ...]
    """The joint carrying each link (None for the root)."""
    parent: numpy.ndarray
    """Index of each link's parent link (-1 for the root)."""
    origin: numpy.ndarray
    """(L, 4, 4) joint origins, parent link frame to joint frame (identity for the root)."""
    axis: numpy.ndarray
    """(L, 3) unit joint axes in the joint frame."""
    motion: numpy.ndarray
    """(L,) FIXED, REVOLUTE or PRISMATIC."""
    source: numpy.ndarray
    """(L,) index into the movable joints of the value that moves the joint (-1: none)."""
    multiplier: numpy.ndarray
    """(L,) joint value = multiplier * q[source] + offset."""
    offset: numpy.ndarray
    movable: tuple[str, ...]
    """The independent movable joints, in the robot's joint order: the columns of q."""
    depth: int
    """The most joints between the root and a link."""

    @cached_property
    def index(self) -> dict[str, int]:
        """Return each link's position in :attr:`links` (do not change it)."""
        return {name: number for number, name in enumerate(self.links)}

    @cached_property
    def below(self) -> numpy.ndarray:
        """Return S (L, L): S[j, b] = 1 when link b is link j or below it."""
        count = len(self.links)
        below = numpy.eye(count)
        for number in range(count - 1, 0, -1):  # children come after their parents
            below[self.parent[number]] += below[number]
        return below

    @cached_property
    def moving(self) -> numpy.ndarray:
        """Return the links a movable joint (or a mimic one) carries."""
        return numpy.flatnonzero(self.source >= 0)

    @cached_property
    def spread(self) -> numpy.ndarray:
        """Return (moving, dof): each moving link's multiplier in its column of ``q``."""
        spread = numpy.zeros((len(self.moving), len(self.movable)))
        spread[numpy.arange(len(self.moving)), self.source[self.moving]] = \
            self.multiplier[self.moving]
        return spread


def _leader(joint: Joint, joints: Mapping[str, Joint]) -> tuple[str, float, float]:
    """Return the independent joint ``joint`` follows, and the multiplier and offset."""
    multiplier, offset, current, seen = 1.0, 0.0, joint, {joint.name}
    while current.mimic is not None:
        leader = joints.get(current.mimic.joint)
        if leader is None or not leader.type.is_movable or leader.name in seen:
            break  # validate() reports it (J107-J109): the joint moves on its own
        multiplier, offset = (multiplier * current.mimic.multiplier,
                              offset + multiplier * current.mimic.offset)
        current = leader
        seen.add(current.name)
    return current.name, multiplier, offset


def compile_robot(robot: RobotModel) -> ChainModel:
    """Return the arrays of ``robot`` (one root link, or a ModelError naming the roots)."""
    joints = {joint.name: joint for joint in robot.joints}
    leaders = {name: _leader(joint, joints) for name, joint in joints.items()
               if joint.type.is_movable}
    movable = tuple(name for name, (leader, _, _) in leaders.items() if leader == name)
    column = {name: number for number, name in enumerate(movable)}
    order = list(robot.walk())
    count = len(order)
    position = {link.name: number for number, (_, link) in enumerate(order)}
    parent = numpy.full(count, -1, dtype=numpy.intp)
    origin = numpy.tile(numpy.eye(4), (count, 1, 1))
    axis = numpy.zeros((count, 3))
    motion = numpy.zeros(count, dtype=numpy.intp)
    source = numpy.full(count, -1, dtype=numpy.intp)
    multiplier, offset = numpy.zeros(count), numpy.zeros(count)
    depth = numpy.zeros(count, dtype=numpy.intp)
    for number, (joint, _) in enumerate(order):
        if joint is None:
            continue
        parent[number] = position[joint.parent]
        depth[number] = depth[parent[number]] + 1
        origin[number] = numpy.array(joint.origin.matrix())
        x, y, z = joint.effective_axis
        norm = math.sqrt(x * x + y * y + z * z)
        axis[number] = (x / norm, y / norm, z / norm) if norm else (1.0, 0.0, 0.0)
        motion[number] = _MOTION.get(joint.type, FIXED)
        if joint.name in leaders:
            leader, factor, shift = leaders[joint.name]
            source[number], multiplier[number], offset[number] = column[leader], factor, shift
    return ChainModel(tuple(link.name for _, link in order),
                      tuple(joint.name if joint is not None else None for joint, _ in order),
                      parent, origin, axis, motion, source, multiplier, offset, movable,
                      int(numpy.max(depth)) if count else 0)


_JOINT_FIELDS = operator.attrgetter('name', 'parent', 'child', 'origin', 'axis', 'mimic')
# Joint.type's stored value, read past the descriptor that checks what is set (no Python call)
_JOINT_TYPE = getattr(vars(Joint)['type'], '_get', operator.attrgetter('type'))
_NAME = operator.attrgetter('name')


def fingerprint(robot: RobotModel) -> tuple:
    """Return what the compiled arrays depend on; equal fingerprints, equal arrays."""
    joints = robot.joints
    return (tuple(map(_JOINT_FIELDS, joints)), tuple(map(_JOINT_TYPE, joints)),
            tuple(map(_NAME, robot.links)))


def positions(model: ChainModel, q: Any, strict: bool = False) -> tuple[numpy.ndarray, bool]:
    """
    Return ``q`` as an (N, dof) array, and whether it was a single configuration.

    ``q`` is a mapping of joint names (missing joints: 0; a fixed one is a ModelError), an
    array over the movable joints, or an (N, dof) array of configurations; values must be
    finite numbers. A mimic joint in a mapping (a JointState names them all) follows its
    leader, as robot_state_publisher computes it: a value that disagrees is one warning,
    or a ModelError with ``strict``.
    """
    dof = len(model.movable)
    if isinstance(q, Mapping):
        row = numpy.zeros(dof)
        columns = {name: number for number, name in enumerate(model.movable)}
        followers = []
        for name, value in q.items():
            if name in columns:
                row[columns[name]] = _finite(value, name)
            elif name in model.joints and model.source[model.joints.index(name)] >= 0:
                followers.append((name, _finite(value, name)))
            else:
                raise ModelError(_not_a_column(model, name))
        if followers:
            _check_followers(model, row, followers, strict)
        return row[None, :], True
    try:
        values = numpy.asarray(q if q is not None else numpy.zeros(dof), dtype=float)
    except (TypeError, ValueError):
        raise ModelError(f'q must be numbers (radians or metres), got {q!r}') from None
    if not numpy.isfinite(values).all():
        raise ModelError('q holds a value that is not a finite number (NaN or inf): give '
                         'finite joint values')
    if values.ndim == 1 and values.shape[0] == dof:
        return values[None, :], True
    if values.ndim == 2 and values.shape[1] == dof:
        return values, False
    raise ModelError(f'q has shape {values.shape}: give {dof} values in robot.movable_joints '
                     f'order ({", ".join(model.movable)}), an (N, {dof}) array, or a mapping '
                     'of joint names')


def _check_followers(model: ChainModel, row: numpy.ndarray,
                     followers: list[tuple[str, float]], strict: bool) -> None:
    """Warn (raise with ``strict``) when a mimic joint's value is not its leader's formula."""
    wrong = []
    for name, value in followers:
        link = model.joints.index(name)
        leader = model.movable[model.source[link]]
        factor, shift = float(model.multiplier[link]), float(model.offset[link])
        expected = factor * float(row[model.source[link]]) + shift
        if abs(value - expected) > AGREE * max(1.0, abs(expected)):
            wrong.append(f'q[{name!r}] is {value:g}, {factor:g} * q[{leader!r}] + {shift:g} '
                         f'is {expected:g}')
            first = name, leader
    if not wrong:
        return
    more = f' (and {len(wrong) - 1} more)' if len(wrong) > 1 else ''
    name, leader = first
    if strict:
        raise ModelError(f'q gives mimic joint {name!r} a value that does not follow '
                         f'{leader!r} ({wrong[0]}{more}): leave {name!r} out (its value comes '
                         f'from {leader!r}) or give it the value the formula gives')
    warn_caller(f'mimic joint {name!r} follows {leader!r}: {wrong[0]}{more}; the value '
                f'from {leader!r} is used, as robot_state_publisher does')


def _finite(value: Any, name: str) -> float:
    """Return ``value`` as a finite float, or a ModelError naming the joint."""
    try:
        number = float(value)
    except (TypeError, ValueError):
        number = math.nan
    if not math.isfinite(number):
        raise ModelError(f'q[{name!r}] is {value!r}: give a finite number (radians or metres)')
    return number


def _not_a_column(model: ChainModel, name: str) -> str:
    """Return why joint ``name`` of a q mapping is not one of its columns."""
    known = ', '.join(model.movable) or 'none'
    if name not in model.joints:
        return (f'q names {name!r}, which is not a joint of the robot '
                f'(movable joints: {known})')
    link = model.joints.index(name)
    if model.source[link] >= 0:
        leader = model.movable[model.source[link]]
        return (f'q names {name!r}, a mimic joint: it follows {leader!r}; give a value '
                f'for {leader!r} instead')
    return (f'q names {name!r}, a joint q does not move (fixed, floating or planar; '
            f'movable joints: {known})')
