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
Gravity torques: what each movable joint must give to hold the robot still.

For a joint carrying the links below it (mass M, first moment F about the root), the
torque is ``-z . ((F - M p) x g)`` for a turning joint at ``p`` with axis ``z``, and
``-M z . g`` for a sliding one: the derivative of the potential energy, as pinocchio's
``computeGeneralizedGravity`` gives it. A mimic joint's torque is added to its leader's,
times its multiplier.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
import math
from typing import TYPE_CHECKING

import numpy

from urdfgenpy_ros.dynamics.forward import link_frames
from urdfgenpy_ros.dynamics.model import ChainModel, REVOLUTE
from urdfgenpy_ros.model.errors import ModelError

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


@dataclass(frozen=True)
class MassModel:
    """Each link's mass (L,) and first moment ``mass * com`` (L, 3) in its own frame."""

    mass: numpy.ndarray
    moment: numpy.ndarray


def mass_model(robot: RobotModel, model: ChainModel, payload: Mapping[str, object] | None = None
               ) -> MassModel:
    """
    Return the masses of ``robot``'s links, with ``payload`` added to its link.

    ``payload`` is ``{'link': 'tool0', 'mass': 2.0, 'com': (0, 0, 0.05)}`` (``com`` in the
    link's frame, default its origin).
    """
    links = {link.name: link.inertial for link in robot.links}
    values = numpy.array([(inertial.mass, *inertial.origin.xyz) if inertial is not None
                          else (0.0, 0.0, 0.0, 0.0)
                          for inertial in map(links.__getitem__, model.links)], dtype=float)
    mass = values[:, 0].copy()
    moment = values[:, 1:] * values[:, :1]
    if payload is not None:
        number, weight, com = _payload(model, payload)
        mass[number] += weight
        moment[number] += weight * com
    return MassModel(mass, moment)


def _payload(model: ChainModel, payload: Mapping[str, object]
             ) -> tuple[int, float, numpy.ndarray]:
    unknown = set(payload) - {'link', 'mass', 'com'}
    if unknown or 'link' not in payload or 'mass' not in payload:
        raise ModelError(f'payload {dict(payload)!r}: give link, mass and optionally com, e.g. '
                         "{'link': 'tool0', 'mass': 2.0, 'com': (0, 0, 0.05)}")
    link = payload['link']
    if link not in model.links:
        raise ModelError(f'payload: {link!r} is not a link of the robot')
    try:
        weight = float(payload['mass'])  # type: ignore[arg-type]
        com = numpy.asarray(payload.get('com', (0.0, 0.0, 0.0)), dtype=float)
    except (TypeError, ValueError):
        raise ModelError(f'payload {dict(payload)!r}: mass is a number of kg, com three '
                         'numbers of metres') from None
    if com.shape != (3,) or not numpy.isfinite(com).all() or not 0.0 <= weight < math.inf:
        raise ModelError(f'payload {dict(payload)!r}: mass must be a finite number >= 0 (kg), '
                         'com three finite numbers (m)')
    return model.links.index(str(link)), weight, com


def gravity_vector(gravity: Sequence[float] | numpy.ndarray) -> numpy.ndarray:
    """Return ``gravity`` as a 3-vector, or a ModelError."""
    try:
        g = numpy.asarray(gravity, dtype=float)
    except (TypeError, ValueError):
        g = numpy.zeros(0)
    if g.shape != (3,) or not all(map(math.isfinite, g.tolist())):
        raise ModelError(f'gravity must be three finite numbers (m/s^2), got {gravity!r}')
    return g


def gravity_torques(model: ChainModel, masses: MassModel, q: numpy.ndarray,
                    gravity: Sequence[float] | numpy.ndarray = (0.0, 0.0, -9.81)
                    ) -> numpy.ndarray:
    """Return the (N, dof) torques (N m) or forces (N) that hold the robot at ``q``."""
    g = gravity_vector(gravity)
    rotation, position = link_frames(model, q)
    count, links = position.shape[:2]
    first = masses.mass[:, None] * position + (rotation @ masses.moment[:, :, None])[..., 0]
    moving = model.moving
    held = model.below[moving]
    # the first moment of everything each joint holds: one product for all configurations
    held_moment = (held @ first.transpose(1, 0, 2).reshape(links, 3 * count)).reshape(
        len(moving), count, 3).transpose(1, 0, 2)
    held_mass = held @ masses.mass
    axes = (rotation[:, moving] @ model.axis[moving][:, :, None])[..., 0]
    lever = held_moment - held_mass[:, None] * position[:, moving]
    across = numpy.array([[0.0, -g[2], g[1]], [g[2], 0.0, -g[0]], [-g[1], g[0], 0.0]])
    turning = (lever * (axes @ across.T)).sum(axis=2)  # z.(l x g) = l.(g x z)
    sliding = held_mass * (axes @ g)
    torque = -numpy.where(model.motion[moving] == REVOLUTE, turning, sliding)
    return torque @ model.spread
