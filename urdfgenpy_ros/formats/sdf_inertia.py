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
Which links' inertia libsdformat refuses ("A link named ... has invalid inertia").

libsdformat loads a link only if gz-math's ``MassMatrix3::IsValid`` holds: mass not
negative, the tensor positive semi-definite and its principal moments obeying the triangle
inequality, each within ten machine epsilons of twice the largest moment. A moment of zero
passes (MuJoCo's limit, finding I202, is stricter).
"""

from __future__ import annotations

import math
import sys

from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.transforms import symmetric_eigenvalues

_TOLERANCE = 10.0  # gz-math's IGN_MASSMATRIX3_DEFAULT_TOLERANCE


def _epsilon(moments: tuple[float, float, float]) -> float:
    return _TOLERANCE * sys.float_info.epsilon * 2.0 * max(moments)


def finite(inertial: Inertial) -> bool:
    """Return whether the mass and the six numbers of the tensor are finite numbers."""
    return all(math.isfinite(value) for value in (
        inertial.mass, inertial.ixx, inertial.ixy, inertial.ixz, inertial.iyy, inertial.iyz,
        inertial.izz))


def refusal(inertial: Inertial) -> tuple[str, str] | None:
    """Return the finding code and problem libsdformat refuses ``inertial`` for, or None."""
    if not finite(inertial):
        return 'R305', 'its mass or inertia is not a finite number (NaN or inf)'
    if inertial.mass < 0.0:
        return 'I210', f'mass is {inertial.mass:g}'
    (ixx, ixy, ixz), (_, iyy, iyz), (_, _, izz) = inertial.tensor
    epsilon = _epsilon((ixx, iyy, izz))
    determinant = (ixx * (iyy * izz - iyz * iyz) - ixy * (ixy * izz - iyz * ixz)
                   + ixz * (ixy * iyz - iyy * ixz))
    moments = symmetric_eigenvalues(inertial.tensor)
    listed = ', '.join(f'{m:.4g}' for m in moments)
    if not (ixx >= -epsilon and ixx * iyy - ixy * ixy >= -epsilon
            and determinant >= -epsilon):
        return 'I202', f'principal moments {listed} are not all positive or zero'
    epsilon = _epsilon(moments)
    a, b, c = moments
    if not (a + epsilon >= 0.0 and a + b + epsilon >= c and b + c + epsilon >= a
            and c + a + epsilon >= b):
        return 'I203', f'principal moments {listed} break the triangle inequality'
    return None


def sdformat_refuses(inertial: Inertial) -> bool:
    """Return whether libsdformat refuses a link with ``inertial``, as gz-math judges it."""
    return refusal(inertial) is not None
