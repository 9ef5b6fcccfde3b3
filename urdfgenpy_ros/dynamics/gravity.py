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

import numpy

from urdfgenpy_ros.dynamics.forward import link_frames
from urdfgenpy_ros.dynamics.model import ChainModel, REVOLUTE
from urdfgenpy_ros.errors import ModelError
from urdfgenpy_ros.robot import Robot


@dataclass(frozen=True)
class MassModel:
    """Each link's mass (L,) and first moment ``mass * com`` (L, 3) in its own frame."""

    mass: numpy.ndarray
    moment: numpy.ndarray


def mass_model(robot: Robot, model: ChainModel, payload: Mapping[str, object] | None = None
               ) -> MassModel:
    """
    Return the masses of ``robot``'s links, with ``payload`` added to its link.

    ``payload`` is ``{'link': 'tool0', 'mass': 2.0, 'com': (0, 0, 0.05)}`` (``com`` in the
    link's frame, default its origin).
    """
    mass, moment = numpy.zeros(len(model.links)), numpy.zeros((len(model.links), 3))
    for number, name in enumerate(model.links):
        inertial = robot.get_link(name).inertial
        if inertial is not None:
            mass[number] = inertial.mass
            moment[number] = numpy.multiply(inertial.mass, inertial.origin.xyz)
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
    if com.shape != (3,) or not numpy.isfinite(com).all() or not numpy.isfinite(weight):
        raise ModelError(f'payload {dict(payload)!r}: com must be three finite numbers (m)')
    return model.links.index(str(link)), weight, com


def subtree_matrix(model: ChainModel) -> numpy.ndarray:
    """Return S (L, L): S[j, b] = 1 when link b is link j or below it."""
    count = len(model.links)
    below = numpy.eye(count)
    for number in range(count - 1, 0, -1):  # children come after their parents
        below[model.parent[number]] += below[number]
    return below


def gravity_torques(model: ChainModel, masses: MassModel, q: numpy.ndarray,
                    gravity: Sequence[float] | numpy.ndarray = (0.0, 0.0, -9.81),
                    subtree: numpy.ndarray | None = None) -> numpy.ndarray:
    """Return the (N, dof) torques (N m) or forces (N) that hold the robot at ``q``."""
    g = numpy.asarray(gravity, dtype=float)
    if g.shape != (3,):
        raise ModelError(f'gravity must be three numbers (m/s^2), got {gravity!r}')
    rotation, position = link_frames(model, q)
    below = subtree_matrix(model) if subtree is None else subtree
    first = (masses.mass[:, None] * position
             + numpy.einsum('nlij,lj->nli', rotation, masses.moment))
    moving = numpy.flatnonzero(model.source >= 0)
    held_moment = below[moving] @ first  # (N, moving, 3)
    held_mass = below[moving] @ masses.mass
    axes = numpy.einsum('nkij,kj->nki', rotation[:, moving], model.axis[moving])
    lever = held_moment - held_mass[:, None] * position[:, moving]
    turning = numpy.einsum('nki,nki->nk', axes, numpy.cross(lever, g))
    sliding = held_mass * (axes @ g)
    torque = -numpy.where(model.motion[moving] == REVOLUTE, turning, sliding)
    spread = numpy.zeros((len(moving), len(model.movable)))
    spread[numpy.arange(len(moving)), model.source[moving]] = model.multiplier[moving]
    return torque @ spread
