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
Statics: whether each joint's declared effort holds the robot against gravity everywhere.

For each movable joint, the worst gravity torque over the range of motion (the limits;
continuous joints over a full turn) is found by :func:`~urdfgenpy_ros.dynamics.worst.
worst_case` and compared with ``<limit effort>`` times the margin asked for: T801 at the
joint's ``<limit>`` line gives the torque, the pose and the effort that passes. Joints
gravity cannot load (a vertical axis, a wheel turning about its centre of mass) are
never reported; nor is a joint whose effort passes a bound on its torque over every pose
(:func:`~urdfgenpy_ros.dynamics.bound.torque_bounds`), which is not searched. The root is
held still; a floating joint stays at its origin.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
import math
from typing import TYPE_CHECKING

import numpy

from urdfgenpy_ros.dynamics import compiled
from urdfgenpy_ros.dynamics.bound import torque_bounds
from urdfgenpy_ros.dynamics.gravity import mass_model
from urdfgenpy_ros.dynamics.worst import is_prismatic, LONG_POSE, ranges, worst_case
from urdfgenpy_ros.dynamics.worst import WorstCase
from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.findings import Findings, joint_path
from urdfgenpy_ros.model.joint import Joint, JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

UNLOADED = 1e-9  # of the robot's weight times a metre: gravity cannot load the joint
SAFE = 1e-9  # relative: the bound is raised by this much against rounding


def check_statics(robot: RobotModel, findings: Findings,
                  payload: Mapping[str, object] | None = None, margin: float = 1.0,
                  gravity: Sequence[float] = (0.0, 0.0, -9.81)) -> None:
    """Add T801 for every joint whose effort cannot hold the robot somewhere in its range."""
    if not 0.0 < margin < math.inf:
        raise ModelError(f'statics_margin must be a factor > 0 (1.5: 50% spare), got {margin!r}')
    if len(robot.roots) != 1:
        return  # validate() reports it (S001, S002)
    model = compiled(robot)
    masses = mass_model(robot, model, payload)
    if not (numpy.isfinite(model.origin).all() and numpy.isfinite(masses.moment).all()):
        return  # R305 names the value that is not a number
    g = numpy.asarray(gravity, dtype=float)
    scale = UNLOADED * max(1.0, float(masses.mass.sum()) * float(numpy.linalg.norm(g)))
    bounds = ranges(robot, model)
    held = _held(robot)
    most = torque_bounds(model, masses, bounds, g) * (1.0 + SAFE) + SAFE * scale
    for column, name in enumerate(model.movable):
        limit = robot.get_joint(name).limit
        if limit is None or not math.isfinite(limit.effort) or limit.effort <= 0.0:
            continue  # J103, J105, J106 or R305 says what is wrong with it
        if most[column] <= scale or limit.effort >= most[column] * margin:
            continue  # no pose can need more: no search
        worst = worst_case(model, masses, bounds, column, g)
        need = abs(worst.torque) * margin
        if abs(worst.torque) <= scale or limit.effort >= need:
            continue
        unit = 'N' if is_prismatic(model, column) else 'N m'
        findings.add('T801', limit, f'joint {name!r}', joint_path(name) + '/limit',
                     _message(worst, unit, limit.effort, payload, held),
                     f'set effort="{_round_up(need)}" or more: the worst torque times margin '
                     f'{margin:g}; or check the masses it holds up', 'limit')


def _held(robot: RobotModel) -> str:
    """Return what the message says of a base that is held ('' for a fixed arm's)."""
    free = [joint for joint in robot.joints
            if joint.type in (JointType.FLOATING, JointType.PLANAR)]
    if free:
        names = ', '.join(repr(joint.name) for joint in free)
        return (f'; the floating base is held at {robot.root.name!r}: {free[0].type} joint '
                f'{names} at its origin')
    root = robot.root
    if root.inertial is None or root.inertial.mass <= 0.0:
        return ''
    limbs = sum(any(joint.type.is_movable for joint in _subtree(robot, child))
                for child in robot.joints if child.parent == root.name)
    if limbs < 2:
        return ''
    return f'; the root link {root.name!r} is held still, as if bolted down'


def _subtree(robot: RobotModel, joint: Joint) -> list[Joint]:
    """Return ``joint`` and every joint below it."""
    found, waiting = [], [joint]
    while waiting:
        current = waiting.pop()
        found.append(current)
        waiting += [below for below in robot.joints if below.parent == current.child]
    return found


def _message(worst: WorstCase, unit: str, effort: float,
             payload: Mapping[str, object] | None, held: str) -> str:
    values = {name: round(value, 4) + 0.0 for name, value in worst.pose.items()}
    shown = values if len(values) <= LONG_POSE else {
        name: value for name, value in values.items() if value != 0.0}
    pose = ', '.join(f'{name}={value:g}' for name, value in shown.items())
    if len(shown) < len(values):
        pose = f'{pose}, the other joints at 0'
    where = f'at {pose}' if pose else 'in every pose'
    carrying = (f' (with {payload["mass"]:g} kg at {payload["link"]!r})'
                if payload is not None else '')
    return (f'gravity needs {abs(worst.torque):.4g} {unit} {where}{carrying}; '
            f'<limit> effort is {effort:g}{held}')


def _round_up(value: float) -> str:
    """Return ``value`` rounded up to 3 significant digits, as text."""
    if value <= 0.0:
        return '0'
    step = 10.0 ** (math.floor(math.log10(value)) - 2)
    return f'{math.ceil(value / step - 1e-9) * step:.6g}'
