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
One joint's gravity torque along each other joint, in closed form, for many poses at once.

For a joint ``k`` turning a link, the torque is ``-d_k . (g x z_k)``: ``z_k`` its axis,
``d_k`` the first moment of everything below it about its origin (world axes). Moving one
joint ``l`` moves the subtree below ``l`` rigidly, so along ``l`` the torque is exactly
``P + Q cos t + R sin t`` (a turn by ``t``) or ``P + S t`` (a shift): below ``k`` only
``d_k`` changes (by ``d_l`` turned), above ``k`` the whole of ``z_k x d_k`` turns. The
state of a pose is ``z`` and ``d`` of the moving links that matter, updated by the same
rigid motion when the search moves a joint, so no step computes forward kinematics.
"""

from __future__ import annotations

from typing import Any

import numpy

from urdfgenpy_ros.dynamics.forward import link_frames
from urdfgenpy_ros.dynamics.gravity import MassModel
from urdfgenpy_ros.dynamics.model import ChainModel, REVOLUTE


def _cross(a: numpy.ndarray, b: numpy.ndarray) -> numpy.ndarray:
    """Return ``a x b`` over the last axis (numpy.cross costs more on small arrays)."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return numpy.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=-1)


def _turned(vectors: numpy.ndarray, axis: numpy.ndarray, angle: numpy.ndarray
            ) -> numpy.ndarray:
    """Return (N, K, 3) ``vectors`` turned about the (N, 3) unit ``axis`` by (N,) ``angle``."""
    cosine, sine = numpy.cos(angle)[:, None, None], numpy.sin(angle)[:, None, None]
    axis = axis[:, None, :]
    along = (vectors * axis).sum(axis=2, keepdims=True) * axis
    return along + cosine * (vectors - along) + sine * _cross(axis, vectors)


class RigidTorque:
    """The torque of one joint (one link, not mimicked) and its rigid-motion state per pose."""

    def __init__(self, model: ChainModel, masses: MassModel, gravity: numpy.ndarray,
                 column: int) -> None:
        self.model, self.masses, self.gravity = model, masses, gravity
        self.links = numpy.flatnonzero(model.source >= 0)  # the state's links
        self.target = int(numpy.flatnonzero(model.source[self.links] == column)[0])
        below = model.below[numpy.ix_(self.links, self.links)] > 0  # [a, b]: b below a
        self.subtree = [numpy.flatnonzero(row) for row in below]
        self.above = [numpy.flatnonzero(below[:, number] & (numpy.arange(len(self.links))
                                                            != number))
                      for number in range(len(self.links))]
        self.held = (model.below[self.links] @ masses.mass)  # mass below each link
        self.turning = model.motion[self.links] == REVOLUTE
        over = below[:, self.target].copy()
        over[self.target] = False
        self.relation = numpy.where(below[self.target], 1, 0) + numpy.where(over, 2, 0)
        self.subtree_set = [set(found.tolist()) for found in self.subtree]
        self.above_set = [set(found.tolist()) for found in self.above]
        self.multiplier = model.multiplier[self.links]
        self.columns: dict[int, list[int]] = {}
        for number, source in enumerate(model.source[self.links]):
            self.columns.setdefault(int(source), []).append(number)

    def link_of(self, column: int) -> int | None:
        """Return the one state link ``column`` moves, None when it moves several."""
        found = self.columns.get(column, [])
        return found[0] if len(found) == 1 else None

    def state(self, q: numpy.ndarray) -> tuple[numpy.ndarray, numpy.ndarray]:
        """Return the axes ``z`` and moments ``d`` (N, K, 3) of the state's links at ``q``."""
        model, masses = self.model, self.masses
        rotation, position = link_frames(model, q)
        first = masses.mass[:, None] * position + (rotation @ masses.moment[:, :, None])[..., 0]
        held = numpy.einsum('kl,nlj->nkj', model.below[self.links], first)
        axes = (rotation[:, self.links] @ model.axis[self.links][:, :, None])[..., 0]
        return axes, held - self.held[:, None] * position[:, self.links]

    def value(self, z: numpy.ndarray, d: numpy.ndarray) -> numpy.ndarray:
        """Return the torque (N,) of the state's poses."""
        return self._value(z[:, self.target], d[:, self.target])

    def _value(self, axis: numpy.ndarray, moment: numpy.ndarray) -> numpy.ndarray:
        k = self.target
        if not self.turning[k]:
            return -self.held[k] * (axis @ self.gravity)
        return -(moment * _cross(self.gravity, axis)).sum(axis=1)

    def coefficients(self, z: numpy.ndarray, d: numpy.ndarray, link: int
                     ) -> tuple[numpy.ndarray, ...]:
        """Return P, Q, R, S (N,) of the torque along ``link``'s joint value t."""
        k, g = self.target, self.gravity
        zero = numpy.zeros(len(z))
        current = self.value(z, d)
        relation = self.relation[link]  # 1: at or below the target, 2: above it
        if self.turning[link] and relation == 2:
            axis = z[:, link]
            turned = (_cross(z[:, k], d[:, k]) if self.turning[k]
                      else self.held[k] * z[:, k])
            along = (axis * turned).sum(axis=1) * (axis @ g)
            return -along, along - turned @ g, -(_cross(axis, turned) @ g), zero
        if not self.turning[k] or relation != 1:
            return current, zero, zero, zero
        across = _cross(g, z[:, k])
        axis, moment = z[:, link], d[:, link]
        if not self.turning[link]:
            return current, zero, zero, -self.held[link] * (axis * across).sum(axis=1)
        along = (axis * moment).sum(axis=1) * (axis * across).sum(axis=1)
        rest = ((d[:, k] - moment) * across).sum(axis=1)
        return (-(rest + along), along - (moment * across).sum(axis=1),
                -(_cross(axis, moment) * across).sum(axis=1), zero)

    def move(self, z: numpy.ndarray, d: numpy.ndarray, rows: numpy.ndarray, column: int,
             step: numpy.ndarray) -> None:
        """Move ``column`` by ``step`` (N,) in poses ``rows`` of the state, in place."""
        if not len(rows):
            return
        moved_z, moved_d = z[rows], d[rows]
        for link in self.columns[column]:
            self._shift(moved_z, moved_d, link, self.subtree[link], self.above[link],
                        self.multiplier[link] * step)
        z[rows], d[rows] = moved_z, moved_d

    def sweep(self, z: numpy.ndarray, d: numpy.ndarray, column: int, steps: numpy.ndarray
              ) -> numpy.ndarray:
        """Return the torque (N, T) with ``column`` moved by each of ``steps`` (N, T)."""
        links = self.columns[column]
        keep = sorted({*links, self.target})
        where = {link: number for number, link in enumerate(keep)}
        count = steps.shape[1]
        moved_z = numpy.repeat(z[:, keep], count, axis=0)
        moved_d = numpy.repeat(d[:, keep], count, axis=0)
        for link in links:
            below = [where[other] for other in keep if other in self.subtree_set[link]]
            above = [where[other] for other in keep if other in self.above_set[link]]
            self._shift(moved_z, moved_d, where[link], below, above,
                        self.multiplier[link] * steps.ravel(), self.turning[link],
                        self.held[link])
        target = where[self.target]
        return self._value(moved_z[:, target], moved_d[:, target]).reshape(len(z), count)

    def _shift(self, z: numpy.ndarray, d: numpy.ndarray, link: int, below: Any,
               above: Any, step: numpy.ndarray, turning: bool | None = None,
               held: float | None = None) -> None:
        """Move the joint of state link ``link`` by ``step`` in every pose, in place."""
        turning = bool(self.turning[link]) if turning is None else turning
        held = float(self.held[link]) if held is None else held
        axis = z[:, link].copy()
        if not turning:
            d[:, above] += (held * step[:, None] * axis)[:, None, :]
            return
        before = d[:, link].copy()
        turned = _turned(z[:, below], axis, step)  # unit again: errors would grow each turn
        z[:, below] = turned / numpy.sqrt((turned * turned).sum(axis=2, keepdims=True))
        d[:, below] = _turned(d[:, below], axis, step)
        d[:, above] += (d[:, link] - before)[:, None, :]


def along(coefficients: tuple[numpy.ndarray, ...], step: numpy.ndarray) -> numpy.ndarray:
    """Return the torque (N, T) at joint steps ``step`` (N, T) from :meth:`coefficients`."""
    p, q, r, s = (part[:, None] for part in coefficients)
    return p + q * numpy.cos(step) + r * numpy.sin(step) + s * step
