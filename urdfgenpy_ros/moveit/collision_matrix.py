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
The collision matrix as MoveIt's Setup Assistant computes it, without MoveIt.

The algorithm of moveit2's ``compute_default_collisions.cpp``, step by step, over the
links that have collision geometry:

1. **Adjacent**: a parent and its child; a link without geometry is collapsed, so that
   every two of its neighbours are adjacent (repeated until nothing changes).
2. **Default**: pairs in contact in the default state (each joint 0, or mid-range where 0
   is outside its limits; or a named state).
3. **Always**: rounds of 200 random states; a pair in contact in more than 95% of a round
   (191 or more) is disabled; rounds go on until one disables nothing.
4. **Never**: ``samples`` random states more; a pair never seen in contact in any round
   is disabled.

Pairs disabled by a step are not tested by the later ones (MoveIt's allowed collision
matrix), and a pair seen in contact once is not tested again. Continuous joints turn over
[-pi, pi]; mimic joints follow their leaders. The states come from ``numpy``'s generator
seeded with ``seed``: the same robot and seed give the same matrix.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from enum import Enum
from itertools import combinations
from typing import Any, TYPE_CHECKING

import numpy

from urdfgenpy_ros.dynamics import compiled
from urdfgenpy_ros.moveit import sampling
from urdfgenpy_ros.moveit.contacts import Pair, ShapeSet, States
from urdfgenpy_ros.moveit.shapes import link_shapes

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

ALWAYS_ABOVE = int(sampling.ROUND * 0.95)  # MoveIt: more than 190 of 200
CHUNK = 1000  # states per batch of forward kinematics in the "Never" step


class Reason(str, Enum):
    """Why a pair is disabled: the ``reason`` attribute of ``<disable_collisions>``."""

    ADJACENT = 'Adjacent'
    DEFAULT = 'Default'
    ALWAYS = 'Always'
    NEVER = 'Never'


@dataclass
class CollisionMatrix:
    """The disabled pairs (sorted link names) and why, with what they were computed from."""

    disabled: dict[Pair, Reason]
    links: tuple[str, ...]
    """The links with collision geometry, in the robot's order."""
    samples: int
    seed: int
    rounds: int
    """How many rounds of 200 states the "Always" step drew before the ``samples``."""
    rates: dict[Pair, float] = field(default_factory=dict)
    """The share of the ``samples`` states in which each Default pair is in contact (when
    asked for)."""

    def reason(self, one: str, two: str) -> Reason | None:
        """Return why the pair is disabled, or None if it is checked."""
        return self.disabled.get(pair(one, two))


def pair(one: str, two: str) -> Pair:
    """Return the pair in MoveIt's order: the smaller name first."""
    return (one, two) if one < two else (two, one)


def adjacent_pairs(robot: RobotModel, with_geometry: Iterable[str]) -> set[Pair]:
    """Return the adjacent pairs: joined, or joined through links without geometry."""
    solid = set(with_geometry)
    graph: dict[str, set[str]] = {link.name: set() for link in robot.links}
    for joint in robot.joints:
        if joint.parent in graph and joint.child in graph:
            graph[joint.parent].add(joint.child)
            graph[joint.child].add(joint.parent)
    changed = True
    while changed:
        changed = False
        for link, neighbours in graph.items():
            if link in solid:
                continue
            for one, two in combinations(sorted(neighbours), 2):
                if two not in graph[one]:
                    graph[one].add(two)
                    graph[two].add(one)
                    changed = True
    return {pair(link, other) for link, neighbours in graph.items() if link in solid
            for other in neighbours if other in solid}


def compute_matrix(robot: RobotModel, samples: int = 10000, seed: int = 0,
                   default_values: Mapping[str, float] | None = None,
                   search_paths: Any = (), rates: bool = False) -> CollisionMatrix:
    """
    Return the collision matrix of ``robot`` (see the module docstring).

    ``rates``: also count, over the ``samples`` states, how often each Default pair is in
    contact (every state tested for those pairs: the costly part on a humanoid).
    """
    if samples < 0:
        from urdfgenpy_ros.model.errors import ModelError
        raise ModelError(f'samples must be 0 or more, got {samples}')
    model = compiled(robot)
    shapes = ShapeSet(model, link_shapes(robot, search_paths))
    links = tuple(shapes.of_link)
    disabled = {key: Reason.ADJACENT for key in adjacent_pairs(robot, links)}
    candidates = [pair(a, b) for a, b in combinations(links, 2)]
    default = sampling.default_state(robot, default_values)[None, :]
    for key in shapes.poses(default).first_contacts(_open(candidates, disabled)):
        disabled[key] = Reason.DEFAULT
    generator, ranges = sampling.generator(seed), sampling.bounds(robot)
    seen: set[Pair] = set()
    rounds = 0
    while True:
        rounds += 1
        states = shapes.poses(sampling.random_states(ranges, sampling.ROUND, generator))
        always = _always_round(states, _open(candidates, disabled), seen)
        disabled.update((key, Reason.ALWAYS) for key in always)
        if not always:
            break
    counted = _never(shapes, ranges, generator, samples, candidates, disabled, seen, rates)
    for key in candidates:
        if key not in disabled and key not in seen:
            disabled[key] = Reason.NEVER
    return CollisionMatrix(dict(sorted(disabled.items())), links, samples, seed, rounds,
                           counted)


def _open(candidates: list[Pair], disabled: Mapping[Pair, Reason]) -> list[Pair]:
    return [key for key in candidates if key not in disabled]


def _always_round(states: States, pairs: list[Pair], seen: set[Pair]) -> list[Pair]:
    """Return the pairs in contact in more than 95% of the round; add those seen to seen."""
    always = []
    for key, (indices, which) in zip(pairs, states.near(pairs)):
        if len(indices) <= ALWAYS_ABOVE:  # cannot be "Always": only whether it is seen
            if key not in seen and _first(states, key, indices, which):
                seen.add(key)
            continue
        hits = 0
        for number, (state, mask) in enumerate(zip(indices, which)):
            if states.touch(key, int(state), mask):
                hits += 1
                seen.add(key)
            if key in seen and hits + len(indices) - number - 1 <= ALWAYS_ABOVE:
                break
        if hits > ALWAYS_ABOVE:
            always.append(key)
    return always


def _first(states: States, key: Pair, indices: numpy.ndarray, which: numpy.ndarray) -> bool:
    return any(states.touch(key, int(state), mask) for state, mask in zip(indices, which))


def _never(shapes: ShapeSet, ranges: numpy.ndarray, generator: numpy.random.Generator,
           samples: int, candidates: list[Pair], disabled: Mapping[Pair, Reason],
           seen: set[Pair], rates: bool) -> dict[Pair, float]:
    """Test the open pairs not yet seen over ``samples`` states; count the Default pairs."""
    defaults = [key for key in candidates if rates and disabled.get(key) is Reason.DEFAULT]
    hits = dict.fromkeys(defaults, 0)
    for start in range(0, samples, CHUNK):
        q = sampling.random_states(ranges, min(CHUNK, samples - start), generator)
        states = shapes.poses(q)
        unseen = [key for key in _open(candidates, disabled) if key not in seen]
        seen.update(states.first_contacts(unseen))
        for key, count in states.counts(defaults).items():
            hits[key] += count
    return {key: count / samples for key, count in hits.items()} if samples and rates else {}
