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
Forward kinematics and geometric Jacobians of many configurations at once (numpy).

Each joint's transform is its origin times a turn (Rodrigues' formula, vectorised over
the configurations and the joints) or a shift. Link poses are composed by pointer jumping:
at each step every link takes the pose of the ancestor it points at and then points at
that ancestor's ancestor, so a tree of depth D needs ceil(log2(D + 1)) batched products.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
import math

import numpy

from urdfgenpy_ros.dynamics.model import ChainModel, joint_values, PRISMATIC, REVOLUTE
from urdfgenpy_ros.errors import ModelError


class _Turns:
    """Per-model constants of the turning joints: R_origin (a a^T, I - a a^T, [a]x)."""

    def __init__(self, model: ChainModel) -> None:
        self.links = numpy.flatnonzero(model.motion == REVOLUTE)
        self.shifts = numpy.flatnonzero(model.motion == PRISMATIC)
        rotation = model.origin[:, :3, :3]
        axis = model.axis[self.links]
        outer = axis[:, :, None] * axis[:, None, :]
        cross = numpy.zeros((len(self.links), 3, 3))
        cross[:, 0, 1], cross[:, 0, 2], cross[:, 1, 2] = -axis[:, 2], axis[:, 1], -axis[:, 0]
        cross[:, 1, 0], cross[:, 2, 0], cross[:, 2, 1] = axis[:, 2], -axis[:, 1], axis[:, 0]
        turned = rotation[self.links]
        self.fixed_part = turned @ outer
        self.cosine_part = turned - self.fixed_part
        self.sine_part = turned @ cross
        self.shift_axis = numpy.einsum('lij,lj->li', rotation[self.shifts],
                                       model.axis[self.shifts])
        count = len(model.links)
        self.pointer = numpy.append(numpy.where(model.parent >= 0, model.parent, count), count)
        self.steps = math.ceil(math.log2(model.depth + 1)) if model.depth else 0


_TURNS: dict[int, tuple[ChainModel, _Turns]] = {}


def _turns(model: ChainModel) -> _Turns:
    cached = _TURNS.get(id(model))
    if cached is None or cached[0] is not model:
        if len(_TURNS) > 32:
            _TURNS.clear()
        cached = _TURNS[id(model)] = (model, _Turns(model))
    return cached[1]


def link_frames(model: ChainModel, q: numpy.ndarray, base: numpy.ndarray | None = None
                ) -> tuple[numpy.ndarray, numpy.ndarray]:
    """
    Return every link's rotation (N, L, 3, 3) and position (N, L, 3) in the root frame.

    ``q`` is an (N, dof) array over ``model.movable``; ``base``, a 4x4 pose of the root
    (default: the identity), puts the root there instead.
    """
    turns = _turns(model)
    values = joint_values(model, q)
    count, links = q.shape[0], len(model.links)
    rotation = numpy.empty((count, links + 1, 3, 3))
    rotation[:, :links] = model.origin[:, :3, :3]
    rotation[:, links] = numpy.eye(3)
    position = numpy.zeros((count, links + 1, 3))
    position[:, :links] = model.origin[:, :3, 3]
    if len(turns.links):
        angle = values[:, turns.links][:, :, None, None]
        rotation[:, turns.links] = (turns.fixed_part + numpy.cos(angle) * turns.cosine_part
                                    + numpy.sin(angle) * turns.sine_part)
    if len(turns.shifts):
        position[:, turns.shifts] += values[:, turns.shifts, None] * turns.shift_axis
    if base is not None:
        pose = numpy.asarray(base, dtype=float)
        if pose.shape != (4, 4):
            raise ModelError(f'base must be a 4x4 pose, got shape {pose.shape}')
        rotation[:, 0], position[:, 0] = pose[:3, :3], pose[:3, 3]  # the root comes first
    pointer = turns.pointer
    for _ in range(turns.steps):
        above = rotation[:, pointer]
        position = numpy.einsum('nlij,nlj->nli', above, position) + position[:, pointer]
        rotation = above @ rotation
        pointer = pointer[pointer]
    return rotation[:, :links], position[:, :links]


def homogeneous(rotation: numpy.ndarray, position: numpy.ndarray) -> numpy.ndarray:
    """Return 4x4 transforms (..., 4, 4) of rotations (..., 3, 3) and positions (..., 3)."""
    matrix = numpy.zeros((*rotation.shape[:-2], 4, 4))
    matrix[..., :3, :3] = rotation
    matrix[..., :3, 3] = position
    matrix[..., 3, 3] = 1.0
    return matrix


class LinkPoses(Mapping[str, numpy.ndarray]):
    """
    Every link's pose in the root frame: ``poses['tool0']`` is a 4x4 (or N x 4 x 4) array.

    ``array`` holds them all, (L, 4, 4) or (N, L, 4, 4), links in ``links`` order.
    """

    def __init__(self, links: tuple[str, ...], array: numpy.ndarray) -> None:
        self.links = links
        self.array = array
        self._index = {name: number for number, name in enumerate(links)}

    def __getitem__(self, link: str) -> numpy.ndarray:
        """Return the pose of ``link``."""
        try:
            return self.array[..., self._index[link], :, :]
        except KeyError:
            raise KeyError(f'{link!r} is not a link of the robot') from None

    def __iter__(self) -> Iterator[str]:
        """Iterate over the link names, root first."""
        return iter(self.links)

    def __len__(self) -> int:
        """Return the number of links."""
        return len(self.links)


def _ancestors(model: ChainModel, link: int) -> list[int]:
    """Return ``link`` and its ancestors that a movable joint carries."""
    found = []
    while link >= 0:
        if model.source[link] >= 0:
            found.append(link)
        link = int(model.parent[link])
    return found


def jacobian(model: ChainModel, link: str, q: numpy.ndarray, frame: str = 'world',
             base: numpy.ndarray | None = None) -> numpy.ndarray:
    """
    Return the geometric Jacobians (N, 6, dof) of ``link``'s frame at configurations ``q``.

    Rows are the linear velocity of the frame's origin, then the angular velocity; in the
    root's axes with ``frame='world'``, in the link's own with ``frame='local'``. A mimic
    joint adds its multiplier times its column to its leader's.
    """
    if frame not in ('world', 'local'):
        raise ModelError(f"frame must be 'world' or 'local', got {frame!r}")
    try:
        target = model.links.index(link)
    except ValueError:
        raise ModelError(f'{link!r} is not a link of the robot') from None
    rotation, position = link_frames(model, q, base)
    joints = _ancestors(model, target)
    count, dof = q.shape[0], len(model.movable)
    result = numpy.zeros((count, 6, dof))
    if joints:
        axes = numpy.einsum('nkij,kj->nki', rotation[:, joints], model.axis[joints])
        columns = numpy.zeros((count, len(joints), 6))
        turning = model.motion[joints] == REVOLUTE
        lever = position[:, target, None, :] - position[:, joints]
        columns[:, :, :3] = numpy.where(turning[None, :, None], numpy.cross(axes, lever), axes)
        columns[:, :, 3:] = numpy.where(turning[None, :, None], axes, 0.0)
        spread = numpy.zeros((len(joints), dof))
        spread[numpy.arange(len(joints)), model.source[joints]] = model.multiplier[joints]
        result = numpy.swapaxes(columns, 1, 2) @ spread
    if frame == 'local':
        back = numpy.swapaxes(rotation[:, target], 1, 2)
        result = numpy.concatenate([back @ result[:, :3], back @ result[:, 3:]], axis=1)
    return result
