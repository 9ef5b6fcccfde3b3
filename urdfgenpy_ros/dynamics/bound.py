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
A bound on each joint's gravity torque over every pose, from the lengths and masses alone.

The torque of a turning joint is ``d . (g x z)``: ``d`` the first moment about the joint
of everything below it, ``z`` the axis. ``|d|`` is at most the sum, over the links below,
of each one's mass times the length of the path of origins to it (and of its own centre
of mass), whatever the pose; ``|g x z|`` is ``|g|`` unless every turning joint above has
the axis's direction, which then never changes. A joint whose effort passes the bound
needs no search. Links on fixed joints are merged first (:func:`lumped`): their moments
add as vectors.
"""

from __future__ import annotations

from dataclasses import replace

import numpy

from urdfgenpy_ros.dynamics.gravity import MassModel
from urdfgenpy_ros.dynamics.model import ChainModel, FIXED, PRISMATIC, REVOLUTE

PARALLEL = 1e-12  # sine of the angle between axes taken as one direction


def lumped(model: ChainModel, masses: MassModel) -> tuple[ChainModel, MassModel]:
    """Return ``model`` with each link on a fixed joint merged into its parent (same torques)."""
    count = len(model.links)
    host = numpy.arange(count)
    pose = numpy.tile(numpy.eye(4), (count, 1, 1))  # each link in its host's frame
    origin = model.origin.copy()
    for link in range(1, count):
        above = int(model.parent[link])
        origin[link] = pose[above] @ model.origin[link]
        if model.motion[link] == FIXED:
            host[link], pose[link] = host[above], origin[link]
    kept = numpy.flatnonzero(host == numpy.arange(count))
    mass = numpy.zeros(count)
    moment = numpy.zeros((count, 3))
    numpy.add.at(mass, host, masses.mass)
    numpy.add.at(moment, host, masses.mass[:, None] * pose[:, :3, 3]
                 + (pose[:, :3, :3] @ masses.moment[:, :, None])[..., 0])
    merged = replace(model, origin=origin, parent=host[numpy.maximum(model.parent, 0)])
    smaller = restricted(merged, kept)
    parent = smaller.parent.copy()
    parent[0] = -1
    return replace(smaller, parent=parent), MassModel(mass[kept], moment[kept])


def restricted(model: ChainModel, links: numpy.ndarray) -> ChainModel:
    """Return the model of ``links`` only (closed under parents: the root stays first)."""
    renumber = numpy.full(len(model.links) + 1, -1, dtype=numpy.intp)
    renumber[links] = numpy.arange(len(links))
    parent = renumber[model.parent[links]]
    depth = numpy.zeros(len(links), dtype=numpy.intp)
    for number in range(1, len(links)):
        depth[number] = depth[parent[number]] + 1
    return replace(model, links=tuple(model.links[link] for link in links),
                   joints=tuple(model.joints[link] for link in links), parent=parent,
                   origin=model.origin[links], axis=model.axis[links],
                   motion=model.motion[links], source=model.source[links],
                   multiplier=model.multiplier[links], offset=model.offset[links],
                   depth=int(numpy.max(depth)) if len(links) else 0)


def torque_bounds(model: ChainModel, masses: MassModel, bounds: numpy.ndarray,
                  gravity: numpy.ndarray) -> numpy.ndarray:
    """Return, per movable joint, a number its ``|torque|`` never exceeds within ``bounds``."""
    model, masses = lumped(model, masses)
    held = model.below @ masses.mass
    reach = numpy.linalg.norm(masses.moment, axis=1)  # |first moment| of each subtree, at most
    travel = numpy.zeros(len(model.links))
    sliding = model.motion == PRISMATIC
    travel[sliding] = (numpy.abs(bounds[model.source[sliding]]).max(axis=1)
                       * numpy.abs(model.multiplier[sliding]) + numpy.abs(model.offset[sliding]))
    for link in range(len(model.links) - 1, 0, -1):
        length = float(numpy.linalg.norm(model.origin[link, :3, 3])) + travel[link]
        reach[model.parent[link]] += held[link] * length + reach[link]
    axes = _axes(model)
    result = numpy.zeros(len(model.movable))
    for link in map(int, numpy.flatnonzero(model.source >= 0)):
        if model.motion[link] == REVOLUTE:
            size = reach[link] * _across(model, axes, link, gravity)
        else:
            size = held[link] * float(numpy.linalg.norm(gravity))
        result[model.source[link]] += abs(model.multiplier[link]) * size
    return result


def _axes(model: ChainModel) -> numpy.ndarray:
    """Return each link's joint axis in the root frame at the zero pose."""
    rotation = numpy.tile(numpy.eye(3), (len(model.links), 1, 1))
    for link in range(1, len(model.links)):
        rotation[link] = rotation[model.parent[link]] @ model.origin[link, :3, :3]
    return (rotation @ model.axis[:, :, None])[..., 0]


def _across(model: ChainModel, axes: numpy.ndarray, link: int, gravity: numpy.ndarray
            ) -> float:
    """Return ``|g x z|`` at most over every pose, for the joint of ``link``."""
    above = int(model.parent[link])
    while above > 0:
        turning = model.motion[above] == REVOLUTE
        if turning and numpy.linalg.norm(numpy.cross(axes[above], axes[link])) > PARALLEL:
            return float(numpy.linalg.norm(gravity))
        above = int(model.parent[above])
    return float(numpy.linalg.norm(numpy.cross(gravity, axes[link])))
