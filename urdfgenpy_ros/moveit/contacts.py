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
Which pairs of links touch in which states: coal on the shapes, numpy before it.

The states come as an (N, dof) array; one batched forward kinematics gives every shape's
pose in all of them. Bounding spheres then say, for every pair at once, in which states
two shapes may touch; coal's ``collide`` runs only there, in the states' order, and each
question stops as soon as it is answered (the first contact, or a count that can no longer
cross a threshold).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy

from urdfgenpy_ros.dynamics.forward import link_matrices
from urdfgenpy_ros.dynamics.model import ChainModel
from urdfgenpy_ros.moveit.shapes import import_coal, Shape

Pair = tuple[str, str]


class ShapeSet:
    """The shapes of the links with collision geometry, as arrays over the shapes."""

    def __init__(self, model: ChainModel, shapes: dict[str, list[Shape]]) -> None:
        self.coal = import_coal()
        self.model = model
        index = model.index
        flat = [shape for link in shapes for shape in shapes[link]]
        self.geometry = [shape.geometry for shape in flat]
        self.row = numpy.array([index[shape.link] for shape in flat], dtype=numpy.intp)
        self.origin = numpy.array([shape.origin for shape in flat]).reshape(-1, 4, 4)
        self.center = numpy.array([shape.center for shape in flat]).reshape(-1, 3)
        self.radius = numpy.array([shape.radius for shape in flat])
        self.of_link: dict[str, list[int]] = {}
        for number, shape in enumerate(flat):
            self.of_link.setdefault(shape.link, []).append(number)
        self.request = self.coal.CollisionRequest()
        self.request.enable_contact = False
        self.request.num_max_contacts = 1

    def poses(self, q: numpy.ndarray) -> States:
        """Return the shapes' poses in the states ``q`` (N, dof)."""
        links = link_matrices(self.model, q)  # (N, L, 4, 4)
        world = links[:, self.row] @ self.origin
        centers = numpy.einsum('ngij,gj->ngi', world[..., :3, :3], self.center) \
            + world[..., :3, 3]
        return States(self, world, centers)


class States:
    """A batch of states: every shape's pose, and the pair questions asked over them."""

    def __init__(self, shapes: ShapeSet, world: numpy.ndarray, centers: numpy.ndarray
                 ) -> None:
        self.shapes = shapes
        self.world = world
        self.centers = centers
        self.count = world.shape[0]
        self._placed: dict[tuple[int, int], Any] = {}  # (state, shape): coal's transform
        self._pairs: dict[Pair, list[tuple[int, int]]] = {}

    def near(self, pairs: Sequence[Pair]) -> list[tuple[numpy.ndarray, numpy.ndarray]]:
        """
        Return, for each pair, the states where some two of its shapes' spheres meet.

        Each entry: the state indices (ascending), and per such state and shape pair
        whether those two spheres meet (a bool array, states x the pair's shape pairs).
        """
        of_link = self.shapes.of_link
        first: list[int] = []
        second: list[int] = []
        starts: list[int] = []
        for link_one, link_two in pairs:
            starts.append(len(first))
            for a in of_link[link_one]:
                for b in of_link[link_two]:
                    first.append(a)
                    second.append(b)
        if not first:
            return []
        one, two = numpy.array(first), numpy.array(second)
        reach = (self.shapes.radius[one] + self.shapes.radius[two]) ** 2
        gap = self.centers[:, one] - self.centers[:, two]
        meets = numpy.einsum('nki,nki->nk', gap, gap) <= reach
        bounds = [*starts, len(first)]
        result = []
        for number in range(len(pairs)):
            block = meets[:, bounds[number]:bounds[number + 1]]
            states = numpy.flatnonzero(block.any(axis=1))
            result.append((states, block[states]))
        return result

    def touch(self, pair: Pair, state: int, which: numpy.ndarray) -> bool:
        """Return whether the links of ``pair`` touch in ``state`` (``which`` shape pairs)."""
        coal, shapes = self.shapes.coal, self.shapes
        pairs = self._pairs.get(pair)
        if pairs is None:
            pairs = self._pairs[pair] = [(a, b) for a in shapes.of_link[pair[0]]
                                         for b in shapes.of_link[pair[1]]]
        result = coal.CollisionResult()
        for (a, b), maybe in zip(pairs, which):
            if maybe and coal.collide(shapes.geometry[a], self._place(state, a),
                                      shapes.geometry[b], self._place(state, b),
                                      shapes.request, result):
                return True
        return False

    def _place(self, state: int, shape: int) -> Any:
        """Return coal's transform of ``shape`` in ``state``, made once."""
        placed = self._placed.get((state, shape))
        if placed is None:
            matrix = self.world[state, shape]
            placed = self._placed[(state, shape)] = self.shapes.coal.Transform3s(
                matrix[:3, :3], matrix[:3, 3])
        return placed

    def first_contacts(self, pairs: Sequence[Pair]) -> dict[Pair, int]:
        """Return each pair that touches in some state, with the first such state."""
        found = {}
        for pair, (states, which) in zip(pairs, self.near(pairs)):
            for state, mask in zip(states, which):
                if self.touch(pair, int(state), mask):
                    found[pair] = int(state)
                    break
        return found

    def counts(self, pairs: Sequence[Pair]) -> dict[Pair, int]:
        """Return in how many states each pair touches."""
        return {pair: sum(self.touch(pair, int(state), mask) for state, mask in zip(*near))
                for pair, near in zip(pairs, self.near(pairs))}
