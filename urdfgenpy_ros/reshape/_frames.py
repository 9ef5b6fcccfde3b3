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

"""Points, directions and rigid frames as plain tuples, for the reshaping modules."""

from __future__ import annotations

import math
from typing import Any

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.geometry import Origin
from urdfgenpy_ros.model.transforms import Matrix4, matrix_rpy, rpy_quaternion

Vec = tuple[float, float, float]


def dot(a: Vec, b: Vec) -> float:
    """Return the dot product."""
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a: Vec, b: Vec) -> Vec:
    """Return the cross product."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def add(a: Vec, b: Vec, scale: float = 1.0) -> Vec:
    """Return ``a + scale b``."""
    return (a[0] + scale * b[0], a[1] + scale * b[1], a[2] + scale * b[2])


def sub(a: Vec, b: Vec) -> Vec:
    """Return ``a - b``."""
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def norm(a: Vec) -> float:
    """Return the length."""
    return math.sqrt(dot(a, a))


def unit(a: Vec) -> Vec:
    """Return ``a`` scaled to length 1."""
    length = norm(a)
    return (a[0] / length, a[1] / length, a[2] / length)


def column(matrix: Matrix4, index: int) -> Vec:
    """Return a column of the rotation (0, 1, 2) or the translation (3)."""
    return (matrix[0][index], matrix[1][index], matrix[2][index])


def frame(origin: Vec, x: Vec, z: Vec) -> Matrix4:
    """Return the frame at ``origin`` with unit axes ``x`` and ``z`` (y completes it)."""
    y = cross(z, x)
    return [[x[0], y[0], z[0], origin[0]], [x[1], y[1], z[1], origin[1]],
            [x[2], y[2], z[2], origin[2]], [0.0, 0.0, 0.0, 1.0]]


def inverse(matrix: Matrix4) -> Matrix4:
    """Return the inverse of a rigid transform."""
    r = [row[:3] for row in matrix[:3]]
    t = column(matrix, 3)
    rows = [[r[0][i], r[1][i], r[2][i]] for i in range(3)]
    return [[*rows[i], -(rows[i][0] * t[0] + rows[i][1] * t[1] + rows[i][2] * t[2])]
            for i in range(3)] + [[0.0, 0.0, 0.0, 1.0]]


def general_multiply(*matrices: Matrix4) -> Matrix4:
    """Return the product of 4x4 matrices that need not be rotations (reflections too)."""
    result = [row[:] for row in matrices[0]]
    for matrix in matrices[1:]:
        result = [[sum(result[i][k] * matrix[k][j] for k in range(4)) for j in range(4)]
                  for i in range(4)]
    return result


def origin_of(matrix: Matrix4, like: Origin | None = None) -> Origin:
    """
    Return the Origin of a rigid transform, its rotation in the form ``like`` has.

    ``like``'s source and extras are kept, so a lossless writer edits it in place.
    """
    xyz = tuple(_snap(value) for value in column(matrix, 3))
    source = like.source if like is not None else None
    extras = like.extras if like is not None else None
    roll, pitch, yaw = matrix_rpy(matrix)
    rpy = (_snap(roll), _snap(pitch), _snap(yaw))
    if like is not None and like.quat_xyzw is not None:
        return Origin(xyz, quat_xyzw=rpy_quaternion(rpy), source=source, extras=extras)
    return Origin(xyz, rpy, source=source, extras=extras)


def _snap(value: float) -> float:
    """Return 0 for a value within rounding (1e-15) of it, else the value."""
    return 0.0 if abs(value) < 1e-15 else value + 0.0


def max_difference(a: Matrix4, b: Matrix4) -> float:
    """Return the largest entry-wise difference of two transforms."""
    return max(abs(a[i][j] - b[i][j]) for i in range(3) for j in range(4))


def require_link(robot: Any, name: str, role: str) -> str:
    """Return ``name`` if ``robot`` has such a link; else raise one line naming a close one."""
    try:
        return str(robot.get_link(name).name)
    except KeyError as error:
        raise ModelError(f'{role}: {error.args[0]} (name one of its links)') from None
