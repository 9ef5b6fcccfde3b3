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
Kinematics and statics of a robot, vectorised with numpy.

What ``robot.fk``, ``robot.jacobian`` and ``robot.gravity_torques`` call. The robot is
compiled to arrays once (:mod:`.model`) and again only when its joints or links change.
Where pinocchio is installed, Jacobians, gravity torques and one configuration's poses
are computed by it on a model built from those arrays (:mod:`.accelerated`): the same
numbers, to rounding.
``q`` is a mapping of joint names, an array over :func:`movable_joints`, or an (N, dof)
array of configurations, which gives N results at once.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any, TYPE_CHECKING
import weakref

import numpy

from urdfgenpy_ros.dynamics.accelerated import accelerated as _accelerated
from urdfgenpy_ros.dynamics.forward import jacobian as _jacobian, link_matrices
from urdfgenpy_ros.dynamics.forward import LinkPoses
from urdfgenpy_ros.dynamics.gravity import gravity_torques as _gravity, gravity_vector
from urdfgenpy_ros.dynamics.gravity import mass_model
from urdfgenpy_ros.dynamics.model import ChainModel, compile_robot, fingerprint, positions
from urdfgenpy_ros.model import edits

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

__all__ = ['compiled', 'fk', 'gravity_torques', 'jacobian', 'LinkPoses', 'movable_joints']

_CACHE: dict[int, list] = {}  # id: [weak reference, fingerprint, edit count, model]


def compiled(robot: RobotModel) -> ChainModel:
    """Return the arrays of ``robot``, compiled again only when its joints changed."""
    count = edits.count
    entry = _CACHE.get(id(robot))
    if entry is not None and entry[0]() is robot:
        if entry[2] == count:  # no robot's tree was edited since: one read
            return entry[3]
        key = fingerprint(robot)
        if entry[1] == key:
            entry[2] = count
            return entry[3]
    else:
        key = fingerprint(robot)
    model = compile_robot(robot)
    if len(_CACHE) > 64:
        for number in [number for number, item in _CACHE.items() if item[0]() is None]:
            del _CACHE[number]
    _CACHE[id(robot)] = [weakref.ref(robot), key, count, model]
    return model


def movable_joints(robot: RobotModel) -> list[str]:
    """Return the joints ``q`` gives values for: movable, not mimic, in the robot's order."""
    return list(compiled(robot).movable)


def fk(robot: RobotModel, q: Any = None, base: Any = None, strict: bool = False) -> LinkPoses:
    """Return every link's 4x4 pose (N x 4 x 4 for N configurations) in the root frame."""
    model = compiled(robot)
    values, single = positions(model, q, strict)
    if single and base is None:
        fast = _accelerated(model, robot, masses=False)
        if fast is not None:  # pinocchio: the same numbers, each pose made when read
            return fast.poses(values)
    matrices = link_matrices(model, values, base)
    return LinkPoses(model.links, matrices[0] if single else matrices, model.index)


def jacobian(robot: RobotModel, link: str, q: Any = None, frame: str = 'world',
             base: Any = None, strict: bool = False) -> numpy.ndarray:
    """Return the geometric Jacobian (6 x dof, or N x 6 x dof) of ``link``."""
    model = compiled(robot)
    values, single = positions(model, q, strict)
    fast = None
    if base is None and frame in ('world', 'local') and link in model.index:
        fast = _accelerated(model, robot, masses=False)
    if fast is not None:  # pinocchio: the same numbers
        result = fast.jacobian(model.index[link], values, frame == 'local')
    else:
        result = _jacobian(model, link, values, frame, base)
    return result[0] if single else result


def gravity_torques(robot: RobotModel, q: Any = None,
                    gravity: Sequence[float] = (0.0, 0.0, -9.81),
                    payload: Mapping[str, object] | None = None, strict: bool = False
                    ) -> numpy.ndarray:
    """Return the torque or force (dof, or N x dof) each movable joint needs to hold still."""
    model = compiled(robot)
    values, single = positions(model, q, strict)
    fast = _accelerated(model, robot, masses=True) if payload is None else None
    if fast is not None:  # pinocchio: the same numbers
        result = fast.gravity_torques(values, gravity_vector(gravity))
    else:
        result = _gravity(model, mass_model(robot, model, payload), values, gravity)
    return result[0] if single else result
