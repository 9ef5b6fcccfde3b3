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
from typing import Any

import numpy

from urdfgenpy_ros.dynamics.model import ChainModel, PRISMATIC, REVOLUTE
from urdfgenpy_ros.model.errors import ModelError


class _Turns:
    """Per-model constants: R_origin (a a^T, I - a a^T, [a]x) of turning joints, and more."""

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
        self.fixed_part = (turned @ outer)[:, None]
        self.cosine_part = turned[:, None] - self.fixed_part
        self.sine_part = (turned @ cross)[:, None]
        self.shift_axis = numpy.einsum('lij,lj->li', rotation[self.shifts],
                                       model.axis[self.shifts])[:, None, :]
        self.turn_values = tuple(part[self.links] for part in (
            model.source, model.multiplier[:, None], model.offset[:, None]))
        self.shift_values = tuple(part[self.shifts] for part in (
            model.source, model.multiplier[:, None], model.offset[:, None]))
        self.origin = model.origin[:, None]
        self.stacked = numpy.concatenate([model.origin, numpy.eye(4)[None]])[:, None]
        count = len(model.links)
        self.parent = [int(number) for number in model.parent]
        pointer = numpy.append(numpy.where(model.parent >= 0, model.parent, count), count)
        self.pointers: list[numpy.ndarray] = []  # where each link points, step by step
        for _ in range(math.ceil(math.log2(model.depth + 1)) if model.depth else 0):
            self.pointers.append(pointer)
            pointer = pointer[pointer]


_TURNS: dict[int, tuple[ChainModel, _Turns]] = {}
JUMPING_BELOW = 16  # configurations: fewer are composed by pointer jumping, more link by link


def _turns(model: ChainModel) -> _Turns:
    cached = _TURNS.get(id(model))
    if cached is None or cached[0] is not model:
        if len(_TURNS) > 32:
            _TURNS.clear()
        cached = _TURNS[id(model)] = (model, _Turns(model))
    return cached[1]


def rigid_pose(base: Any) -> numpy.ndarray:
    """Return ``base`` as a 4x4 rigid pose (a rotation and a shift), or a ModelError."""
    try:
        pose = numpy.asarray(base, dtype=float)
    except (TypeError, ValueError):
        raise ModelError(f'base must be a 4x4 pose, got {base!r}') from None
    if pose.shape != (4, 4):
        raise ModelError(f'base must be a 4x4 pose, got shape {pose.shape}')
    if not numpy.isfinite(pose).all():
        raise ModelError('base holds a value that is not a finite number (NaN or inf)')
    rotation = pose[:3, :3]
    if not (numpy.array_equal(pose[3], (0.0, 0.0, 0.0, 1.0))
            and numpy.allclose(rotation @ rotation.T, numpy.eye(3), atol=1e-6)
            and numpy.linalg.det(rotation) > 0.0):
        raise ModelError('base must be a rigid pose: a rotation (orthonormal, determinant 1) '
                         'and a shift, with the last row 0 0 0 1')
    return pose


def link_matrices(model: ChainModel, q: numpy.ndarray, base: numpy.ndarray | None = None
                  ) -> numpy.ndarray:
    """
    Return every link's 4x4 pose in the root frame, an (N, L, 4, 4) array.

    ``q`` is an (N, dof) array over ``model.movable``; ``base``, a 4x4 pose of the root
    (default: the identity), puts the root there instead.
    """
    turns = _turns(model)
    pose = None if base is None else rigid_pose(base)
    count, links = q.shape[0], len(model.links)
    if count >= JUMPING_BELOW:
        return _link_by_link(model, turns, q, pose)
    poses = turns.stacked.repeat(count, axis=1)  # the identity after the links, where
    if len(turns.links):  # the root's pointer points
        source, multiplier, offset = turns.turn_values
        angle = (q[:, source].T * multiplier + offset)[:, :, None, None]
        poses[turns.links, :, :3, :3] = (turns.fixed_part + numpy.cos(angle) * turns.cosine_part
                                         + numpy.sin(angle) * turns.sine_part)
    if len(turns.shifts):
        source, multiplier, offset = turns.shift_values
        value = q[:, source].T * multiplier + offset
        poses[turns.shifts, :, :3, 3] += value[:, :, None] * turns.shift_axis
    if pose is not None:
        poses[0] = pose  # the root comes first; its own origin is the identity
    for pointer in turns.pointers:  # a few products of every link at once
        poses = poses[pointer] @ poses
    return numpy.swapaxes(poses[:links], 0, 1)


def _link_by_link(model: ChainModel, turns: _Turns, q: numpy.ndarray,
                  base: numpy.ndarray | None) -> numpy.ndarray:
    """
    Return the (N, L, 4, 4) poses of many configurations, each link's from its parent's.

    The configurations are the last axis (L, 4, 4, N), so that each entry of a pose is one
    contiguous row: a product is 36 multiplications of rows, not N small matrix products.
    A turning link's rotation is made just before its product, while its rows are in the
    cache, not for every link at once beforehand.
    """
    count, links = q.shape[0], len(model.links)
    poses = numpy.empty((links, 4, 4, count))
    poses[:] = model.origin[..., None]
    if len(turns.shifts):
        source, multiplier, offset = turns.shift_values
        value = q[:, source].T * multiplier + offset
        poses[turns.shifts, :3, 3] += value[:, None, :] * turns.shift_axis[:, 0, :, None]
    if base is not None:
        poses[0] = base[..., None]  # the root comes first; its own origin is the identity
    turning = _Turning(turns, q)
    terms = numpy.empty((3, 3, 4, count))
    for link in range(1, links):  # parents come first: each is already in the root frame
        parent, own = poses[turns.parent[link]], poses[link, :3]
        turning.rotate(link, own[:, :3])
        numpy.multiply(parent[:3, :3, None, :], own[None, :, :, :], out=terms)
        terms[:, 0, 3] += parent[:3, 3]
        numpy.sum(terms, axis=1, out=own)
    return poses.transpose(3, 0, 1, 2)


class _Turning:
    """The rotations of the turning links at N configurations, one link at a time."""

    def __init__(self, turns: _Turns, q: numpy.ndarray) -> None:
        self.number = {int(link): number for number, link in enumerate(turns.links)}
        if self.number:
            source, multiplier, offset = turns.turn_values
            angle = q[:, source].T * multiplier + offset
            self.cosine, self.sine = numpy.cos(angle), numpy.sin(angle)
            self.fixed, self.cosine_part, self.sine_part = (
                part[:, 0, ..., None] for part in (
                    turns.fixed_part, turns.cosine_part, turns.sine_part))
            self.spare = numpy.empty((3, 3, q.shape[0]))

    def rotate(self, link: int, rotation: numpy.ndarray) -> None:
        """Put into ``rotation`` (3, 3, N) the origin's turned by ``link``'s angles, if any."""
        number = self.number.get(link)
        if number is not None:  # fixed + cos C + sin S, added in that order
            numpy.multiply(self.cosine_part[number], self.cosine[number], out=rotation)
            rotation += self.fixed[number]
            numpy.multiply(self.sine_part[number], self.sine[number], out=self.spare)
            rotation += self.spare


def link_frames(model: ChainModel, q: numpy.ndarray, base: numpy.ndarray | None = None
                ) -> tuple[numpy.ndarray, numpy.ndarray]:
    """Return every link's rotation (N, L, 3, 3) and position (N, L, 3) in the root frame."""
    poses = link_matrices(model, q, base)
    return poses[..., :3, :3], poses[..., :3, 3]


class LinkPoses(Mapping[str, numpy.ndarray]):
    """
    Every link's pose in the root frame: ``poses['tool0']`` is a 4x4 (or N x 4 x 4) array.

    ``array`` holds them all, (L, 4, 4) or (N, L, 4, 4), links in ``links`` order.
    """

    def __init__(self, links: tuple[str, ...], array: numpy.ndarray,
                 index: Mapping[str, int] | None = None) -> None:
        self.links = links
        self.array = array
        self._index = index if index is not None else {
            name: number for number, name in enumerate(links)}

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
