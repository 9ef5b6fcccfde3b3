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

"""Linear-algebra helpers that need no numpy: 4x4 transforms, rpy, quaternions, eigenvalues."""

from __future__ import annotations

import math

Matrix3 = tuple[tuple[float, float, float], ...]
Matrix4 = list[list[float]]

IDENTITY4: Matrix4 = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0],
                      [0.0, 0.0, 0.0, 1.0]]


def _compose(a: Matrix4, b: Matrix4) -> Matrix4:
    """Return ``a b`` for rigid transforms (last row 0 0 0 1), unrolled."""
    (a00, a01, a02, a03), (a10, a11, a12, a13), (a20, a21, a22, a23) = a[0], a[1], a[2]
    (b00, b01, b02, b03), (b10, b11, b12, b13), (b20, b21, b22, b23) = b[0], b[1], b[2]
    return [[a00 * b00 + a01 * b10 + a02 * b20, a00 * b01 + a01 * b11 + a02 * b21,
             a00 * b02 + a01 * b12 + a02 * b22, a00 * b03 + a01 * b13 + a02 * b23 + a03],
            [a10 * b00 + a11 * b10 + a12 * b20, a10 * b01 + a11 * b11 + a12 * b21,
             a10 * b02 + a11 * b12 + a12 * b22, a10 * b03 + a11 * b13 + a12 * b23 + a13],
            [a20 * b00 + a21 * b10 + a22 * b20, a20 * b01 + a21 * b11 + a22 * b21,
             a20 * b02 + a21 * b12 + a22 * b22, a20 * b03 + a21 * b13 + a22 * b23 + a23],
            [0.0, 0.0, 0.0, 1.0]]


def multiply(*matrices: Matrix4) -> Matrix4:
    """Return the product of rigid 4x4 homogeneous transforms, left to right."""
    result = matrices[0] if matrices else IDENTITY4
    for matrix in matrices[1:]:
        result = _compose(result, matrix)
    return result


def rotation_x(angle: float) -> Matrix4:
    """Return a rotation about x."""
    c, s = math.cos(angle), math.sin(angle)
    return [[1.0, 0.0, 0.0, 0.0], [0.0, c, -s, 0.0], [0.0, s, c, 0.0], [0.0, 0.0, 0.0, 1.0]]


def rotation_y(angle: float) -> Matrix4:
    """Return a rotation about y."""
    c, s = math.cos(angle), math.sin(angle)
    return [[c, 0.0, s, 0.0], [0.0, 1.0, 0.0, 0.0], [-s, 0.0, c, 0.0], [0.0, 0.0, 0.0, 1.0]]


def rotation_z(angle: float) -> Matrix4:
    """Return a rotation about z."""
    c, s = math.cos(angle), math.sin(angle)
    return [[c, -s, 0.0, 0.0], [s, c, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]]


def translation(x: float = 0.0, y: float = 0.0, z: float = 0.0) -> Matrix4:
    """Return a translation."""
    return [[1.0, 0.0, 0.0, x], [0.0, 1.0, 0.0, y], [0.0, 0.0, 1.0, z], [0.0, 0.0, 0.0, 1.0]]


def from_xyz_rpy(xyz: tuple[float, float, float],
                 rpy: tuple[float, float, float]) -> Matrix4:
    """Return the transform of a URDF origin: translate, then Rz(yaw) Ry(pitch) Rx(roll)."""
    return multiply(translation(*xyz), rotation_z(rpy[2]), rotation_y(rpy[1]),
                    rotation_x(rpy[0]))


def to_xyz_rpy(matrix: Matrix4, snap: float = 1e-15) -> tuple[tuple[float, float, float],
                                                              tuple[float, float, float]]:
    """
    Return the URDF ``xyz`` and fixed-axis ``rpy`` of a homogeneous transform.

    At the pitch = +-pi/2 singularity, roll is 0 and yaw carries the whole rotation about
    z. Values within ``snap`` of 0 are written as 0 (cos(pi/2) is 6e-17 in floating point).
    """
    def clean(value: float) -> float:
        return 0.0 if abs(value) < snap else value

    (r00, r01, r02, x), (r10, r11, r12, y), (r20, r21, r22, z) = matrix[:3]
    cosine = math.hypot(r00, r10)
    if cosine > 1e-12:
        roll, pitch, yaw = math.atan2(r21, r22), math.atan2(-r20, cosine), math.atan2(r10, r00)
    else:  # gimbal lock: pitch = +-pi/2
        pitch = math.copysign(math.pi / 2.0, -r20)
        roll, yaw = 0.0, math.atan2(-r01, r11)
    return ((clean(x), clean(y), clean(z)), (clean(roll), clean(pitch), clean(yaw)))


def quaternion_matrix(quat_xyzw: tuple[float, float, float, float]) -> Matrix4:
    """
    Return the rotation of a quaternion ``(x, y, z, w)`` as a 4x4 transform.

    The quaternion is normalised first, as urdfdom does; a zero quaternion is no rotation.
    """
    x, y, z, w = quat_xyzw
    norm = math.sqrt(x * x + y * y + z * z + w * w)
    if norm == 0.0 or norm - norm != 0.0:
        return [row[:] for row in IDENTITY4]
    x, y, z, w = x / norm, y / norm, z / norm, w / norm
    return [[1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - z * w), 2.0 * (x * z + y * w), 0.0],
            [2.0 * (x * y + z * w), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - x * w), 0.0],
            [2.0 * (x * z - y * w), 2.0 * (y * z + x * w), 1.0 - 2.0 * (x * x + y * y), 0.0],
            [0.0, 0.0, 0.0, 1.0]]


def matrix_rpy(matrix: Matrix4) -> tuple[float, float, float]:
    """
    Return fixed-axis roll, pitch, yaw with ``Rz(yaw) Ry(pitch) Rx(roll)`` = the rotation.

    Each angle is peeled off the rotation in turn (yaw, then pitch from what is left, then
    roll), so the three give back the rotation to rounding even next to pitch = +-pi/2,
    where angles read independently from tiny matrix entries would not.
    """
    (r00, r01, _), (r10, r11, _), (r20, r21, _) = (row[:3] for row in matrix[:3])
    yaw = math.atan2(r10, r00)
    c, s = math.cos(yaw), math.sin(yaw)
    pitch = math.atan2(-r20, c * r00 + s * r10)
    cp, sp = math.cos(pitch), math.sin(pitch)
    roll = math.atan2(sp * (c * r01 + s * r11) + cp * r21, c * r11 - s * r01)
    return roll + 0.0, pitch + 0.0, yaw + 0.0  # no -0.0


def rpy_quaternion(rpy: tuple[float, float, float]) -> tuple[float, float, float, float]:
    """Return the unit quaternion ``(x, y, z, w)`` of fixed-axis roll, pitch, yaw (w >= 0)."""
    hr, hp, hy = rpy[0] / 2.0, rpy[1] / 2.0, rpy[2] / 2.0
    cr, sr, cp, sp, cy, sy = (math.cos(hr), math.sin(hr), math.cos(hp), math.sin(hp),
                              math.cos(hy), math.sin(hy))
    quat = (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)
    return quat if quat[3] >= 0.0 else (-quat[0], -quat[1], -quat[2], -quat[3])


def symmetric_eigenvalues(matrix: Matrix3) -> tuple[float, float, float]:
    """
    Return the eigenvalues of a symmetric 3x3 matrix, smallest first, to rounding.

    Jacobi rotations: unlike the closed form, they keep two nearly equal eigenvalues (a
    rod's moments, a disc turned off its axes) and a tiny one accurate, which the engines'
    inertia limits (formats/inertia_check.py) need.
    """
    a = [list(row) for row in matrix]
    for _ in range(32):
        turned = False
        for p, q in ((0, 1), (0, 2), (1, 2)):
            apq = a[p][q]
            if abs(apq) <= 1e-18 * (abs(a[p][p]) + abs(a[q][q])):
                continue
            turned = True
            theta = (a[q][q] - a[p][p]) / (2.0 * apq)
            t = (1.0 / (2.0 * theta) if abs(theta) > 1e150 else
                 math.copysign(1.0, theta) / (abs(theta) + math.sqrt(theta * theta + 1.0)))
            c = 1.0 / math.sqrt(t * t + 1.0)
            s = t * c
            a[p][p] -= t * apq
            a[q][q] += t * apq
            a[p][q] = a[q][p] = 0.0
            r = 3 - p - q
            arp, arq = a[r][p], a[r][q]
            a[r][p] = a[p][r] = c * arp - s * arq
            a[r][q] = a[q][r] = s * arp + c * arq
        if not turned:
            break
    small, middle, large = sorted((a[0][0], a[1][1], a[2][2]))
    return small, middle, large
