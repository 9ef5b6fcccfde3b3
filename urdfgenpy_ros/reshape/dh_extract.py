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
The DH table of a robot's serial chain (``DHTable.from_robot``).

Each movable joint of the chain is a line in space at the zero configuration (its axis,
through its frame's origin). DH frames are placed on these lines by the convention's rules:
z along each joint's axis, in the axis' own direction (so a DH joint value is the URDF
joint value), x along the common normal to the next axis. Where the rules leave a choice,
this module takes the first of these: frame 0 sits where the base origin projects onto
the first axis, with x from the base's x; of parallel axes' common normals, the one that
starts at the previous frame's origin (``d = 0``); of intersecting axes', x along
``z_prev x z_next``; the last frame sits where the tip's origin projects onto the last
axis, with x from the tip's x. The base and tool transforms carry what remains, so the
table's forward kinematics is the chain's.
"""

from __future__ import annotations

import math
import random
import warnings

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.joint import Joint, JointType
from urdfgenpy_ros.model.transforms import IDENTITY4, Matrix4, multiply
from urdfgenpy_ros.reshape._frames import (
    add, column, cross, dot, frame, inverse, norm, origin_of, require_link, sub, unit, Vec)

_PARALLEL = 1e-9  # |z1 x z2| below this: the axes are parallel
# Axes closer than this (radians) are taken as parallel: their common normal lies
# (separation / angle) away, kilometres for the 1.5708 of a URDF's rounded pi/2 (hundreds
# of metres for 1.57, 3.14). A warning gives the error this costs, when above _EXACT.
NEARLY_PARALLEL = 5e-3
_EXACT = 1e-9  # metres: a table this close to the chain is its forward kinematics
_SAMPLES = 16
_SAME = 1e-12  # distances below this (metres): the lines meet
_MOVING = (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC)


class Axis:
    """One movable joint of a chain at the zero configuration, in the base frame."""

    def __init__(self, joint: Joint, pose: Matrix4) -> None:
        self.joint = joint
        self.pose = pose  # the child link's pose at q = 0
        self.point = column(pose, 3)
        axis = joint.effective_axis
        turned = tuple(sum(pose[i][k] * axis[k] for k in range(3)) for i in range(3))
        self.direction = unit(turned)  # type: ignore[arg-type]


def chain_axes(robot, base: str, tip: str) -> tuple[list[Joint], list[Axis], Matrix4]:
    """
    Return the chain's joints, its movable joints as axes, and the tip's pose (at q = 0).

    :raises ModelError: naming the joint when the chain is not serial revolute/prismatic.
    """
    require_link(robot, base, 'DH chain base')
    require_link(robot, tip, 'DH chain tip')
    if tip not in {link.name for link in robot.subtree(base)}:
        raise ModelError(f'link {tip!r} is not below {base!r}: a chain runs from a base link '
                         'down to a tip below it')
    joints = robot.chain(tip, base)
    if not joints:
        raise ModelError(f'no chain from {base!r} to {tip!r}: name a base link above the tip')
    pose = IDENTITY4
    axes = []
    for joint in joints:
        pose = multiply(pose, joint.origin.matrix())
        if joint.type is JointType.FIXED:
            continue
        if joint.type not in _MOVING:
            raise ModelError(f'joint {joint.name!r} is {joint.type.value}: a DH table holds '
                             'revolute and prismatic joints only (choose a base and tip '
                             'around it)')
        if joint.mimic is not None:
            raise ModelError(f'joint {joint.name!r} mimics {joint.mimic.joint!r}: a DH '
                             'table has one free variable per row (choose a chain without '
                             'mimic joints)')
        if norm(joint.effective_axis) == 0.0:
            raise ModelError(f'joint {joint.name!r} has a zero axis: give it a direction')
        axes.append(Axis(joint, pose))
    if not axes:
        raise ModelError(f'the chain from {base!r} to {tip!r} has no revolute or prismatic '
                         'joint: a DH table needs at least one')
    return joints, axes, pose


def _across(direction: Vec, z: Vec) -> Vec | None:
    """Return ``direction`` made perpendicular to ``z`` and unit, or None if along ``z``."""
    rest = add(direction, z, -dot(direction, z))
    return unit(rest) if norm(rest) > 1e-9 else None


def _project(point: Vec, origin: Vec, z: Vec) -> Vec:
    """Return the foot of ``point`` on the line through ``origin`` along ``z``."""
    return add(origin, z, dot(sub(point, origin), z))


def _normal(origin: Vec, z: Vec, point: Vec, u: Vec, x_previous: Vec) -> tuple[Vec, Vec, Vec]:
    """
    Return the common normal from line (origin, z) to line (point, u).

    As (foot on the first line, foot on the second, unit x along it). Of x's two senses,
    the one closer to ``x_previous`` (a DH angle offset within +-90 degrees, as tables in
    the literature are written; ``a`` then may be negative).
    """
    w = cross(z, u)
    between = sub(point, origin)
    if norm(w) > _PARALLEL:
        c, square = dot(z, u), dot(w, w)  # |z x u|^2 = 1 - c^2, without the cancellation
        bz, bu = dot(between, z), dot(between, u)
        s = (bz - bu * c) / square
        t = (bz * c - bu) / square
        first, second = add(origin, z, s), add(point, u, t)
        gap = sub(second, first)
        return first, second, _closer(unit(gap) if norm(gap) > _SAME else unit(w), x_previous)
    second = _project(origin, point, u)
    gap = sub(second, origin)
    if norm(gap) > _SAME:
        return origin, second, _closer(unit(gap), x_previous)
    return origin, origin, _across(x_previous, z) or _any_across(z)


def _closer(x: Vec, x_previous: Vec) -> Vec:
    """Return ``x`` or ``-x``, whichever is closer to ``x_previous``."""
    return (-x[0], -x[1], -x[2]) if dot(x, x_previous) < -1e-12 else x


def _any_across(z: Vec) -> Vec:
    return _across((1.0, 0.0, 0.0), z) or _across((0.0, 1.0, 0.0), z)  # type: ignore[return-value]


def _base_frame(first: Axis) -> Matrix4:
    z = first.direction
    origin = _project((0.0, 0.0, 0.0), first.point, z)
    return frame(origin, _across((1.0, 0.0, 0.0), z) or _any_across(z), z)


def _angle(a: Vec, b: Vec, about: Vec) -> float:
    """Return the angle that turns ``a`` onto ``b`` about ``about`` (all unit)."""
    return math.atan2(dot(cross(a, b), about), dot(a, b)) + 0.0


def _standard_frames(axes: list[Axis], tip: Matrix4) -> list[Matrix4]:
    frames = [_base_frame(axes[0])]
    for following in axes[1:]:
        origin, x, z = column(frames[-1], 3), column(frames[-1], 0), column(frames[-1], 2)
        _, foot, x_new = _normal(origin, z, following.point, following.direction, x)
        frames.append(frame(foot, x_new, following.direction))
    origin, x, z = column(frames[-1], 3), column(frames[-1], 0), column(frames[-1], 2)
    tip_z = column(tip, 2)
    z_last = tip_z if abs(dot(tip_z, z)) > 1.0 - 1e-12 else z
    x_last = _across(column(tip, 0), z) or _across(column(tip, 1), z) or x
    at = column(tip, 3)
    foot = _project(at, origin, z)
    frames.append(frame(add(foot, x_last, dot(sub(at, foot), x_last)), x_last, z_last))
    return frames


def _standard_row(previous: Matrix4, current: Matrix4) -> tuple[float, float, float, float]:
    """Return (a, alpha, d, theta) with current = previous Rz(theta) Tz(d) Tx(a) Rx(alpha)."""
    o0, x0, z0 = column(previous, 3), column(previous, 0), column(previous, 2)
    o1, x1, z1 = column(current, 3), column(current, 0), column(current, 2)
    step = sub(o1, o0)
    return dot(step, x1), _angle(z0, z1, x1), dot(step, z0), _angle(x0, x1, z0)


def _modified_frames(axes: list[Axis], tip: Matrix4) -> list[Matrix4]:
    frames = [_base_frame(axes[0])]
    landing = column(frames[0], 3)  # where the previous x meets this axis
    for index, axis in enumerate(axes):
        z = axis.direction
        x_previous = column(frames[-1], 0)
        if index + 1 < len(axes):
            following = axes[index + 1]
            on_line = _project(landing, axis.point, z)
            origin, foot, x = _normal(on_line, z, following.point, following.direction,
                                      x_previous)
            landing = foot
        else:
            origin = _project(column(tip, 3), axis.point, z)
            x = _across(column(tip, 0), z) or _across(column(tip, 1), z) or \
                _across(x_previous, z) or _any_across(z)
        frames.append(frame(origin, x, z))
    return frames


def _modified_row(previous: Matrix4, current: Matrix4) -> tuple[float, float, float, float]:
    """Return (a, alpha, d, theta) with current = previous Rx(alpha) Tx(a) Rz(theta) Tz(d)."""
    o0, x0, z0 = column(previous, 3), column(previous, 0), column(previous, 2)
    o1, x1, z1 = column(current, 3), column(current, 0), column(current, 2)
    step = sub(o1, o0)
    a = dot(step, x0)
    return a, _angle(z0, z1, x0), dot(sub(o1, add(o0, x0, a)), z1), _angle(x0, x1, z1)


def _snap(value: float) -> float:
    """Return 0 for rounding residue (below 1e-15), else the value."""
    return 0.0 if abs(value) < 1e-15 else value + 0.0


def dh_from_robot(robot, base: str, tip: str, convention: str = 'standard', *, cls):
    """
    Return the DH table (a ``cls``) of the chain from link ``base`` to link ``tip``.

    Its rows are named after the joints and carry their types (a continuous joint stays
    continuous) and limits, no more (a joint without ``<limit>`` has no effort or
    velocity); ``base`` and ``tool``
    hold the transforms from the base link to DH frame 0 and from the last DH frame to
    the tip link, so ``table.to_robot()`` has the chain's forward kinematics.

    :raises ModelError: when the chain is not serial revolute/prismatic (naming the joint).
    """
    from urdfgenpy_ros.model.dh_row import DHConvention, DHRow
    style = DHConvention(convention)
    joints, axes, tip_pose = chain_axes(robot, base, tip)
    snapped = _snap_parallel(axes)
    if style is DHConvention.STANDARD:
        frames, measure = _standard_frames(axes, tip_pose), _standard_row
    else:
        frames, measure = _modified_frames(axes, tip_pose), _modified_row
    rows = []
    for axis, previous, current in zip(axes, frames, frames[1:]):
        a, alpha, d, theta = (_snap(value) for value in measure(previous, current))
        joint = axis.joint
        limit = joint.limit
        bounded = limit is not None and joint.type is not JointType.CONTINUOUS
        rows.append(DHRow(joint.name, a, alpha, d, theta, joint.type.value,
                          lower=limit.lower if bounded else None,  # type: ignore[union-attr]
                          upper=limit.upper if bounded else None,  # type: ignore[union-attr]
                          effort=limit.effort if limit is not None else None,
                          velocity=limit.velocity if limit is not None else None))
    table = cls(style, rows, base=origin_of(frames[0]),
                tool=origin_of(multiply(inverse(frames[-1]), tip_pose)))
    if snapped:
        distance, angle = _deviation(table, joints)
        if max(distance, angle) > _EXACT:
            _warn_parallel(snapped, distance, angle)
    return table


def _snap_parallel(axes: list[Axis]) -> list[tuple[str, str, float]]:
    """
    Turn each axis within :data:`NEARLY_PARALLEL` of the one before onto its direction.

    Return ``(joint before, joint, angle)`` for each axis turned.
    """
    snapped = []
    for previous, axis in zip(axes, axes[1:]):
        sine = norm(cross(previous.direction, axis.direction))
        if 0.0 < sine < NEARLY_PARALLEL:
            sense = 1.0 if dot(previous.direction, axis.direction) > 0.0 else -1.0
            axis.direction = tuple(sense * v for v in previous.direction)  # type: ignore
            snapped.append((previous.joint.name, axis.joint.name, math.asin(sine)))
    return snapped


def _deviation(table, joints: list[Joint]) -> tuple[float, float]:
    """Return the largest distance and angle between the table's tip and the chain's."""
    from urdfgenpy_ros.model.transforms import translation
    rng = random.Random(0)
    moving = [joint for joint in joints if joint.type is not JointType.FIXED]
    distance = angle = 0.0
    for sample in range(_SAMPLES):
        q = [0.0 if sample == 0 else rng.uniform(*_span(joint)) for joint in moving]
        values = iter(q)
        pose = IDENTITY4
        for joint in joints:
            pose = multiply(pose, joint.origin.matrix())
            if joint.type is JointType.PRISMATIC:
                x, y, z = (v * next(values) for v in unit(joint.effective_axis))
                pose = multiply(pose, translation(x, y, z))
            elif joint.type is not JointType.FIXED:
                pose = multiply(pose, _turn(unit(joint.effective_axis), next(values)))
        mine = table.flange(q)
        distance = max(distance, norm(sub(column(mine, 3), column(pose, 3))))
        turn = [[sum(mine[k][i] * pose[k][j] for k in range(3)) for j in range(3)]
                for i in range(3)]  # mine^T pose: its skew part is the sine of the angle
        angle = max(angle, norm((turn[2][1] - turn[1][2], turn[0][2] - turn[2][0],
                                 turn[1][0] - turn[0][1])) / 2.0)
    return distance, angle


def _span(joint: Joint) -> tuple[float, float]:
    """Return the range of ``joint``'s positions to sample: its limits, else a turn or 0.1 m."""
    limit = joint.limit
    if limit is not None and joint.type is not JointType.CONTINUOUS \
            and limit.lower < limit.upper:
        return limit.lower, limit.upper
    return (-0.1, 0.1) if joint.type is JointType.PRISMATIC else (-math.pi, math.pi)


def _turn(axis: Vec, angle: float) -> Matrix4:
    """Return the rotation by ``angle`` about the unit ``axis`` (Rodrigues)."""
    x, y, z = axis
    c, s = math.cos(angle), math.sin(angle)
    k = 1.0 - c
    return [[c + x * x * k, x * y * k - z * s, x * z * k + y * s, 0.0],
            [y * x * k + z * s, c + y * y * k, y * z * k - x * s, 0.0],
            [z * x * k - y * s, z * y * k + x * s, c + z * z * k, 0.0],
            [0.0, 0.0, 0.0, 1.0]]


def _warn_parallel(snapped: list[tuple[str, str, float]], distance: float,
                   angle: float) -> None:
    pairs = ', '.join(f'{a!r} and {b!r} ({turn:.1e} rad)' for a, b, turn in snapped)
    warnings.warn(f'dh: the axes of joints {pairs} are taken as parallel (their common '
                  'normal lies hundreds of metres away or more): the tip of the table is up '
                  f"to {distance:.1e} m and {angle:.1e} rad from the URDF's ({_SAMPLES} "
                  'configurations sampled within the limits)', stacklevel=4)
