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
An independent collision matrix: pinocchio's URDF reader and FK, coal, plain loops.

Nothing of urdfgenpy's is used: the URDF is read with lxml (limits, mimic joints, which
links have collision geometry) and with ``pinocchio.buildModelsFromUrdf`` (kinematics,
collision meshes). The steps are moveit2's ``compute_default_collisions.cpp`` written out
plainly: every open pair tested in every state of a round. The random states are drawn
as the documented convention says (``numpy.random.default_rng(seed)``, uniform within
each independent joint's bounds, in document order; rounds of 200, then ``samples``).
"""

from __future__ import annotations

from itertools import combinations
import math
from pathlib import Path

from lxml import etree
import numpy


def _bounds(joint: etree._Element) -> tuple[float, float]:
    """Return MoveIt's sampling range of a joint (limit narrowed by soft limits)."""
    limit, safety = joint.find('limit'), joint.find('safety_controller')
    kind = joint.get('type')
    if kind == 'continuous' or limit is None:
        return (0.0, 0.0) if kind == 'prismatic' else (-math.pi, math.pi)
    lower, upper = float(limit.get('lower', 0)), float(limit.get('upper', 0))
    if safety is not None:
        lower = max(lower, float(safety.get('soft_lower_limit', lower)))
        upper = min(upper, float(safety.get('soft_upper_limit', upper)))
    return lower, upper


class UrdfFacts:
    """What the matrix needs from the URDF text, read with lxml."""

    def __init__(self, path: Path) -> None:
        root = etree.parse(str(path)).getroot()
        links = root.findall('link')
        self.solid = [link.get('name') for link in links if link.find('collision') is not None]
        self.edges = [(joint.find('parent').get('link'), joint.find('child').get('link'))
                      for joint in root.findall('joint')]
        movable = [joint for joint in root.findall('joint')
                   if joint.get('type') in ('revolute', 'continuous', 'prismatic')]
        self.free = [joint for joint in movable if joint.find('mimic') is None]
        self.mimic = {joint.get('name'): (
            joint.find('mimic').get('joint'), float(joint.find('mimic').get('multiplier', 1)),
            float(joint.find('mimic').get('offset', 0)))
            for joint in movable if joint.find('mimic') is not None}
        self.ranges = numpy.array([_bounds(joint) for joint in self.free]).reshape(-1, 2)

    def adjacent(self) -> set[tuple[str, str]]:
        """Return pairs of solid links whose tree path passes only links without geometry."""
        solid, near = set(self.solid), {}
        for parent, child in self.edges:
            near.setdefault(parent, set()).add(child)
            near.setdefault(child, set()).add(parent)
        found = set()
        for start in solid:
            stack, seen = list(near.get(start, ())), {start}
            while stack:
                link = stack.pop()
                if link in seen:
                    continue
                seen.add(link)
                if link in solid:
                    found.add(tuple(sorted((start, link))))
                else:
                    stack.extend(near.get(link, ()))
        return found

    def values(self, row: numpy.ndarray) -> dict[str, float]:
        """Return every movable joint's value for one row over the independent joints."""
        values = {joint.get('name'): float(value) for joint, value in zip(self.free, row)}
        for name in self.mimic:  # leaders first: follow the chain of mimics
            leader, factor, offset, current = name, 1.0, 0.0, name
            while leader in self.mimic:
                parent, scale, shift = self.mimic[leader]
                factor, offset, leader = factor * scale, offset + factor * shift, parent
            values[current] = factor * values.get(leader, 0.0) + offset
        return values


class PinocchioWorld:
    """The robot in pinocchio: place every collision object at a state, test two links."""

    def __init__(self, path: Path, package_dirs: list[str]) -> None:
        import coal
        import pinocchio
        self.coal, self.pin = coal, pinocchio
        self.model, self.geometry, _ = pinocchio.buildModelsFromUrdf(str(path), package_dirs)
        self.data = self.model.createData()
        self.placed = pinocchio.GeometryData(self.geometry)
        self.objects: dict[str, list[int]] = {}
        for number, thing in enumerate(self.geometry.geometryObjects):
            link = self.model.frames[thing.parentFrame].name
            self.objects.setdefault(link, []).append(number)
        self.request = coal.CollisionRequest()

    def place(self, values: dict[str, float]) -> None:
        """Put every collision object where it is at ``values``."""
        q = self.pin.neutral(self.model)
        for index in range(1, self.model.njoints):
            name, joint = self.model.names[index], self.model.joints[index]
            value = values.get(name, 0.0)
            if joint.nq == 1:
                q[joint.idx_q] = value
            elif joint.nq == 2:  # continuous: cos, sin
                q[joint.idx_q:joint.idx_q + 2] = (math.cos(value), math.sin(value))
        self.pin.updateGeometryPlacements(self.model, self.data, self.geometry, self.placed, q)

    def touch(self, one: str, two: str) -> bool:
        """Return whether the two links are in contact where they were placed."""
        for a in self.objects[one]:
            for b in self.objects[two]:
                result = self.coal.CollisionResult()
                if self.coal.collide(
                        self.geometry.geometryObjects[a].geometry, self._at(a),
                        self.geometry.geometryObjects[b].geometry, self._at(b),
                        self.request, result):
                    return True
        return False

    def _at(self, number: int):
        pose = self.placed.oMg[number]
        return self.coal.Transform3s(pose.rotation, pose.translation)


def oracle_matrix(path: Path, package_dirs: list[str], samples: int, seed: int
                  ) -> tuple[dict[tuple[str, str], str], numpy.ndarray, PinocchioWorld]:
    """Return the disabled pairs and reasons, the ``samples`` states, and the world."""
    facts, world = UrdfFacts(path), PinocchioWorld(path, package_dirs)
    pairs = [tuple(sorted(pair)) for pair in combinations(facts.solid, 2)]
    disabled = dict.fromkeys(facts.adjacent(), 'Adjacent')
    low, high = facts.ranges[:, 0], facts.ranges[:, 1]
    default = numpy.where((low <= 0) & (high >= 0), 0.0, (low + high) / 2)
    world.place(facts.values(default))
    for pair in [p for p in pairs if p not in disabled]:
        if world.touch(*pair):
            disabled[pair] = 'Default'
    generator, seen = numpy.random.default_rng(seed), set()
    while True:
        rows = low + generator.random((200, len(low))) * (high - low)
        counts = dict.fromkeys((p for p in pairs if p not in disabled), 0)
        for row in rows:
            world.place(facts.values(row))
            for pair in counts:
                if world.touch(*pair):
                    counts[pair] += 1
                    seen.add(pair)
        always = [pair for pair, count in counts.items() if count > 190]
        disabled.update((pair, 'Always') for pair in always)
        if not always:
            break
    rows = low + generator.random((samples, len(low))) * (high - low)
    for row in rows:
        world.place(facts.values(row))
        for pair in pairs:
            if pair not in disabled and pair not in seen and world.touch(*pair):
                seen.add(pair)
    disabled.update((pair, 'Never') for pair in pairs if pair not in disabled
                    and pair not in seen)
    return disabled, rows, world


def rate(world: PinocchioWorld, facts: UrdfFacts, rows: numpy.ndarray,
         pair: tuple[str, str]) -> float:
    """Return the share of ``rows`` in which the pair is in contact."""
    hits = 0
    for row in rows:
        world.place(facts.values(row))
        hits += world.touch(*pair)
    return hits / len(rows)
