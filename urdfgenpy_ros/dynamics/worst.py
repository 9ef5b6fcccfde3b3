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
The worst gravity torque of a joint over the whole range of motion, and the pose.

A joint's gravity torque depends only on the joints above it (they turn gravity in its
frame) and below it (they move the mass it carries). The search climbs one joint at a time
from up to ``STARTS`` poses: the zero pose, the best points of a grid over those joints and
random ones (fewer when dozens of joints matter); after ``PRUNE`` sweeps the best quarter
climbs on. Along a joint that turns one link the torque is ``A cos q + B sin q + C``:
three evaluations give A, B and C, and the extremes inside the limits are among the
turning points and the ends, so each step is exact (and the whole search, for a single
joint); along a slider it is linear (the ends). A joint shared by mimic joints has several
frequencies: a dense set of samples along it joins the turning points. Each step is taken
in closed form on the pose's rigid-motion state (:mod:`.rigid`), without forward
kinematics; the torque itself is computed on the links that matter, those on fixed joints
merged (:func:`~.bound.lumped`). Of equal results the pose nearest zero is named, with
angles in (-pi, pi].
"""

from __future__ import annotations

from dataclasses import dataclass, field
import itertools
import math
from typing import TYPE_CHECKING

import numpy

from urdfgenpy_ros.dynamics.bound import lumped, restricted
from urdfgenpy_ros.dynamics.forward import link_frames
from urdfgenpy_ros.dynamics.gravity import MassModel
from urdfgenpy_ros.dynamics.model import ChainModel, PRISMATIC, REVOLUTE
from urdfgenpy_ros.dynamics.rigid import along, RigidTorque
from urdfgenpy_ros.model.joint import JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

GRID_POINTS = 4096
STARTS = 64
PRUNE = 3
TIE = 1e-9  # relative: torques this close are equal, the plainer pose is named
LONG_POSE = 8
SHORTER = 1e-3  # a pose of more joints gives this much up for joints at 0
SAMPLES = 17
SWEEPS = 12
PROBES = numpy.array([0.0, math.pi / 2.0, math.pi])


@dataclass(frozen=True)
class WorstCase:
    """The largest gravity torque of one joint: its value (signed) and where it happens."""

    joint: str
    torque: float
    pose: dict[str, float] = field(default_factory=dict)
    """The values of the joints that change this joint's torque (the rest do not)."""


def ranges(robot: RobotModel, model: ChainModel) -> numpy.ndarray:
    """Return (dof, 2) ranges: the limits, a full turn for continuous (or unlimited) joints."""
    bounds = numpy.zeros((len(model.movable), 2))
    for number, name in enumerate(model.movable):
        joint = robot.get_joint(name)
        limit = joint.limit
        if joint.type.needs_limit and limit is not None and limit.lower <= limit.upper:
            bounds[number] = (limit.lower, limit.upper)
        elif joint.type is JointType.PRISMATIC:
            bounds[number] = (0.0, 0.0)  # no range (validate() says J103 or J104)
        else:
            bounds[number] = (-math.pi, math.pi)
    return bounds


def relevant_links(model: ChainModel, column: int) -> numpy.ndarray:
    """Return the links column ``column`` carries, those above them and those below."""
    carried = numpy.flatnonzero(model.source == column)
    below = model.below
    kept = numpy.zeros(len(model.links), dtype=bool)
    for link in carried:
        current = int(link)
        while current >= 0:
            kept[current] = True
            current = int(model.parent[current])
        kept |= below[link] > 0
    return numpy.flatnonzero(kept)


def relevant(model: ChainModel, column: int) -> list[int]:
    """Return the columns of ``q`` that change the torque of column ``column``."""
    sources = model.source[relevant_links(model, column)]
    return sorted({int(value) for value in sources if value >= 0})


def _restricted(model: ChainModel, masses: MassModel, links: numpy.ndarray
                ) -> tuple[ChainModel, MassModel]:
    """Return the model and masses of ``links`` only (closed under parents)."""
    return restricted(model, links), MassModel(masses.mass[links], masses.moment[links])


class _Torque:
    """The torque of one column at many configurations, on the links that change it."""

    def __init__(self, model: ChainModel, masses: MassModel, gravity: numpy.ndarray,
                 column: int) -> None:
        model, masses = lumped(*_restricted(model, masses, relevant_links(model, column)))
        self.model, self.masses, self.gravity, self.column = model, masses, gravity, column
        self.carried = numpy.flatnonzero(model.source == column)
        self.under = numpy.flatnonzero(model.below[self.carried].any(axis=0))
        self.below = model.below[numpy.ix_(self.carried, self.under)]
        self.held = self.below @ masses.mass[self.under]
        self.factor = model.multiplier[self.carried]
        self.turning = model.motion[self.carried] == REVOLUTE

    def __call__(self, q: numpy.ndarray) -> numpy.ndarray:
        """Return the torque of the column at each of the (N, dof) configurations ``q``."""
        rotation, position = link_frames(self.model, q)
        under = self.under
        first = (self.masses.mass[under, None] * position[:, under]
                 + (rotation[:, under] @ self.masses.moment[under, :, None])[..., 0])
        lever = (numpy.einsum('cl,nlj->ncj', self.below, first)
                 - self.held[:, None] * position[:, self.carried])
        axes = (rotation[:, self.carried] @ self.model.axis[self.carried, :, None])[..., 0]
        g = self.gravity
        across = numpy.stack([g[1] * axes[..., 2] - g[2] * axes[..., 1],
                              g[2] * axes[..., 0] - g[0] * axes[..., 2],
                              g[0] * axes[..., 1] - g[1] * axes[..., 0]], axis=-1)
        torque = numpy.where(self.turning, (lever * across).sum(axis=2), self.held * (axes @ g))
        return -(torque @ self.factor)


def _grid(bounds: numpy.ndarray, columns: list[int], base: numpy.ndarray) -> numpy.ndarray:
    """Return the starting points: a grid with the ends, or random ones for many joints."""
    per = int(GRID_POINTS ** (1.0 / len(columns)) + 1e-9)
    if per >= 2:
        axes = [numpy.linspace(bounds[column, 0], bounds[column, 1], per)
                for column in columns]
        points = numpy.array(list(itertools.product(*axes)))
    else:  # 13 joints or more: 2 values each would be too many points
        points = numpy.random.default_rng(0).uniform(
            bounds[columns, 0], bounds[columns, 1], (GRID_POINTS, len(columns)))
    grid = numpy.repeat(base[None, :], len(points), axis=0)
    grid[:, columns] = points
    return grid


def _turning_points(torque: _Torque, seeds: numpy.ndarray, column: int,
                    low: float, high: float) -> numpy.ndarray:
    """Return, per seed, the extremes of ``A cos q + B sin q + C`` inside [low, high]."""
    probes = numpy.repeat(seeds, 3, axis=0)
    probes[:, column] = numpy.tile(PROBES, len(seeds))
    return _extremes(torque(probes).reshape(len(seeds), 3), low, high)


def _extremes(values: numpy.ndarray, low: float, high: float) -> numpy.ndarray:
    """Return the turning points inside [low, high] of the sinusoids through ``values``."""
    a = (values[:, 0] - values[:, 2]) / 2.0
    b = values[:, 1] - (values[:, 0] + values[:, 2]) / 2.0
    phase = numpy.arctan2(b, a)
    found = []
    for turn in (phase, phase + math.pi):  # the maximum and the minimum of the sinusoid
        shift = numpy.ceil((low - turn) / (2.0 * math.pi))
        found.append(numpy.clip(turn + 2.0 * math.pi * shift, low, high))
    return numpy.stack(found, axis=1)


def _kinds(model: ChainModel) -> tuple[set[int], set[int]]:
    """
    Return the columns whose torques are one sinusoid of them, and those linear in them.

    A column that moves one link, turning at multiplier 1, changes every torque as
    ``A cos q + B sin q + C`` (its rotation enters linearly); one that slides one link,
    linearly. Columns shared by mimic joints mix several frequencies: they are sampled.
    """
    single: set[int] = set()
    linear: set[int] = set()
    for column in range(len(model.movable)):
        links = numpy.flatnonzero(model.source == column)
        if len(links) != 1:
            continue
        if model.motion[links[0]] == REVOLUTE and model.multiplier[links[0]] == 1.0:
            single.add(column)
        elif model.motion[links[0]] == PRISMATIC:
            linear.add(column)
    return single, linear


def _starts(grid: numpy.ndarray, size: numpy.ndarray, bounds: numpy.ndarray,
            columns: list[int], home: numpy.ndarray) -> numpy.ndarray:
    """Return the zero pose, the best grid points and random points (the same each run)."""
    count = min(STARTS, max(STARTS // 8, STARTS * 8 // len(columns)))  # fewer for many joints
    rng = numpy.random.default_rng(len(columns))
    scattered = numpy.repeat(home[None, :], count - count // 4, axis=0)
    scattered[:, columns] = rng.uniform(bounds[columns, 0], bounds[columns, 1],
                                        (len(scattered), len(columns)))
    return numpy.concatenate([home[None, :],
                              grid[numpy.argsort(-size, kind='stable')[:count // 4]],
                              scattered])


def worst_case(model: ChainModel, masses: MassModel, bounds: numpy.ndarray, column: int,
               gravity: numpy.ndarray) -> WorstCase:
    """Return the largest ``|torque|`` of movable joint ``column`` over ``bounds``."""
    torque = _Torque(model, masses, gravity, column)
    columns = relevant(model, column)
    base = bounds.mean(axis=1)
    grid = _grid(bounds, columns, base)
    size = numpy.abs(torque(grid))
    home = numpy.clip(numpy.zeros(len(bounds)), bounds[:, 0], bounds[:, 1])  # ties go to it
    seeds = _starts(grid, size, bounds, columns, home) if columns else home[None, :]
    best = numpy.abs(torque(seeds))
    seeds, best = _climb(torque, model, seeds, best, bounds, columns)
    winner = _plainest(torque, seeds, best, bounds, columns)
    value = float(torque(winner[None, :])[0])
    return WorstCase(model.movable[column], value,
                     {model.movable[moved]: float(winner[moved])
                      for moved in _mattering(torque, winner, bounds, columns, value)})


def _rigid(torque: _Torque) -> RigidTorque | None:
    """Return the closed-form torque of a joint that turns or shifts one link, else None."""
    carried = numpy.flatnonzero(torque.model.source == torque.column)
    if len(carried) != 1:
        return None
    return RigidTorque(torque.model, torque.masses, torque.gravity, torque.column)


def _climb(torque: _Torque, model: ChainModel, seeds: numpy.ndarray, best: numpy.ndarray,
           bounds: numpy.ndarray, columns: list[int]) -> tuple[numpy.ndarray, numpy.ndarray]:
    """
    Return the seeds climbed one joint at a time, and their ``|torque|``.

    A joint that moves one of the links that matter is stepped in closed form on each
    pose's rigid-motion state (:mod:`.rigid`); one that moves several (mimic) by evaluating
    the torque along it.
    """
    single, linear = _kinds(model)
    turning = {int(model.source[link]) for link in numpy.flatnonzero(model.motion == REVOLUTE)}
    rigid = _rigid(torque)
    z, d = rigid.state(seeds) if rigid is not None else (seeds, seeds)
    active = numpy.arange(len(seeds))  # the seeds still climbing
    for sweep in range(SWEEPS):
        if sweep == PRUNE:  # keep the most promising climbs
            kept = numpy.argsort(-best, kind='stable')[:max(4, len(best) // 4)]
            seeds, best, z, d = seeds[kept], best[kept], z[kept], d[kept]
            active = numpy.arange(len(seeds))
        before = best[active].copy()
        for moved in columns:
            low, high = bounds[moved]
            tries, values = _try_column(torque, rigid, seeds[active], z[active], d[active],
                                        moved, (low, high), moved in turning,
                                        moved in single or moved in linear)
            pick = values.argmax(axis=1)
            top = values[numpy.arange(len(active)), pick]
            better = top > best[active]
            rows, chosen = active[better], tries[better, pick[better]]
            if rigid is not None:
                rigid.move(z, d, rows, moved, chosen - seeds[rows, moved])
            seeds[rows, moved] = chosen
            best[active] = numpy.maximum(best[active], top)
        moving = best[active] - before > 1e-12 * max(1.0, float(best.max()))
        active = active[moving]
        if not len(active):
            break
    return seeds, best


def _try_column(torque: _Torque, rigid: RigidTorque | None, climbing: numpy.ndarray,
                z: numpy.ndarray, d: numpy.ndarray, moved: int, bounds: tuple[float, float],
                turning: bool, ends_only: bool) -> tuple[numpy.ndarray, numpy.ndarray]:
    """Return the values column ``moved`` tries from each climbing seed, and ``|torque|`` there."""
    low, high = bounds
    count = len(climbing)
    if ends_only:
        tries = numpy.array([[low, high]]).repeat(count, axis=0)
    else:
        tries = numpy.linspace(low, high, SAMPLES)[None, :].repeat(count, axis=0)
    link = rigid.link_of(moved) if rigid is not None else None
    current = climbing[:, moved, None]
    if rigid is None:
        if turning:
            tries = numpy.concatenate(
                [tries, _turning_points(torque, climbing, moved, low, high)], axis=1)
        trial = numpy.repeat(climbing, tries.shape[1], axis=0)
        trial[:, moved] = tries.ravel()
        return tries, numpy.abs(torque(trial)).reshape(count, -1)
    if link is None:  # a column that moves several links: each moved in turn
        if turning:
            probes = rigid.sweep(z, d, moved, PROBES[None, :] - current)
            tries = numpy.concatenate([tries, _extremes(probes, low, high)], axis=1)
        return tries, numpy.abs(rigid.sweep(z, d, moved, tries - current))
    factor = float(rigid.multiplier[link])
    shape = rigid.coefficients(z, d, link)
    if turning:
        probes = along(shape, factor * (PROBES[None, :] - current))
        tries = numpy.concatenate([tries, _extremes(probes, low, high)], axis=1)
    return tries, numpy.abs(along(shape, factor * (tries - current)))


def _wrapped(values: numpy.ndarray, bounds: numpy.ndarray) -> numpy.ndarray:
    """Return ``values`` turned by whole turns into (-pi, pi] where the bounds allow it."""
    turned = values - 2.0 * math.pi * numpy.round(values / (2.0 * math.pi))
    inside = (turned >= bounds[:, 0]) & (turned <= bounds[:, 1])
    return numpy.where(inside, turned, values)


def _plainest(torque: _Torque, seeds: numpy.ndarray, best: numpy.ndarray,
              bounds: numpy.ndarray, columns: list[int]) -> numpy.ndarray:
    """
    Return the plainest of the best poses: nearest the zero pose, angles in (-pi, pi].

    Of poses within ``TIE`` of the best, the one of smallest angles wins; then each joint
    is set to 0, or turned by whole turns, where that loses no more than ``TIE``.
    """
    floor = best.max() - max(TIE * best.max(), 1e-12)
    tied = numpy.flatnonzero(best >= floor)
    candidates = numpy.array([_wrapped(seed, bounds) for seed in seeds[tied]])
    keep = numpy.abs(torque(candidates)) >= floor
    candidates = numpy.where(keep[:, None], candidates, seeds[tied])
    winner = candidates[int(numpy.argmin(numpy.abs(candidates[:, columns]).sum(axis=1)))]
    for moved in columns:
        if bounds[moved, 0] <= 0.0 <= bounds[moved, 1] and winner[moved] != 0.0:
            trial = winner.copy()
            trial[moved] = 0.0
            if abs(float(torque(trial[None, :])[0])) >= floor:
                winner = trial
    return _shortened(torque, winner, bounds, columns, best.max() * (1.0 - SHORTER))


def _shortened(torque: _Torque, winner: numpy.ndarray, bounds: numpy.ndarray,
               columns: list[int], floor: float) -> numpy.ndarray:
    """Return ``winner`` with joints of least effect at 0, for a pose of many joints."""
    moved = [column for column in columns
             if winner[column] != 0.0 and bounds[column, 0] <= 0.0 <= bounds[column, 1]]
    if len(moved) <= LONG_POSE:
        return winner
    trials = numpy.repeat(winner[None, :], len(moved), axis=0)
    trials[numpy.arange(len(moved)), moved] = 0.0
    for number in numpy.argsort(-numpy.abs(torque(trials)), kind='stable'):
        trial = winner.copy()
        trial[moved[number]] = 0.0
        if abs(float(torque(trial[None, :])[0])) >= floor:
            winner = trial
    return winner


def _mattering(torque: _Torque, winner: numpy.ndarray, bounds: numpy.ndarray,
               columns: list[int], value: float) -> list[int]:
    """Return the columns whose value changes the torque at ``winner`` (not a pan, a lift)."""
    probes = numpy.repeat(winner[None, :], 5 * len(columns), axis=0)
    for number, moved in enumerate(columns):
        probes[5 * number:5 * number + 5, moved] = numpy.linspace(bounds[moved, 0],
                                                                  bounds[moved, 1], 5)
    change = numpy.abs(torque(probes) - value).reshape(len(columns), 5).max(axis=1)
    return [moved for moved, amount in zip(columns, change)
            if amount > max(1e-9 * abs(value), 1e-12)]


def is_prismatic(model: ChainModel, column: int) -> bool:
    """Return whether movable joint ``column`` slides (its effort is a force)."""
    links = numpy.flatnonzero(model.source == column)
    return bool(len(links)) and bool((model.motion[links] == PRISMATIC).all())
