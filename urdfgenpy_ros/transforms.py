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

"""Small linear-algebra helpers that need no numpy: symmetric 3x3 eigenvalues."""

from __future__ import annotations

import math

Matrix3 = tuple[tuple[float, float, float], ...]


def symmetric_eigenvalues(matrix: Matrix3) -> tuple[float, float, float]:
    """Return the eigenvalues of a symmetric 3x3 matrix, smallest first (closed form)."""
    (a, d, e), (_, b, f), (_, _, c) = matrix
    off = d * d + e * e + f * f
    if off == 0.0:
        return tuple(sorted((a, b, c)))  # type: ignore[return-value]
    mean = (a + b + c) / 3.0
    spread = math.sqrt(((a - mean) ** 2 + (b - mean) ** 2 + (c - mean) ** 2 + 2.0 * off)
                       / 6.0)
    if spread == 0.0:
        return (mean, mean, mean)
    # B = (A - mean I) / spread; its determinant / 2 is cos(3 phi).
    ba, bb, bc = (a - mean) / spread, (b - mean) / spread, (c - mean) / spread
    bd, be, bf = d / spread, e / spread, f / spread
    half_det = (ba * (bb * bc - bf * bf) - bd * (bd * bc - bf * be)
                + be * (bd * bf - bb * be)) / 2.0
    phi = math.acos(min(1.0, max(-1.0, half_det))) / 3.0
    largest = mean + 2.0 * spread * math.cos(phi)
    smallest = mean + 2.0 * spread * math.cos(phi + 2.0 * math.pi / 3.0)
    middle = 3.0 * mean - largest - smallest
    return (smallest, middle, largest)
