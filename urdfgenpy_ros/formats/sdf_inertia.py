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

import sys
from typing import TYPE_CHECKING

from urdfgenpy_ros.errors import ValidationError
from urdfgenpy_ros.inertial import Inertial
from urdfgenpy_ros.lumping import lumps, WORLD
from urdfgenpy_ros.transforms import symmetric_eigenvalues

if TYPE_CHECKING:
    from urdfgenpy_ros.robot import Robot

_TOLERANCE = 10.0  # gz-math's IGN_MASSMATRIX3_DEFAULT_TOLERANCE


def _epsilon(moments: tuple[float, float, float]) -> float:
    return _TOLERANCE * sys.float_info.epsilon * 2.0 * max(moments)


def sdformat_refuses(inertial: Inertial) -> bool:
    """Return whether libsdformat refuses a link with ``inertial``, as gz-math judges it."""
    (ixx, ixy, ixz), (_, iyy, iyz), (_, _, izz) = inertial.tensor
    epsilon = _epsilon((ixx, iyy, izz))
    determinant = (ixx * (iyy * izz - iyz * iyz) - ixy * (ixy * izz - iyz * ixz)
                   + ixz * (ixy * iyz - iyy * ixz))
    near_positive = (inertial.mass >= 0.0 and ixx >= -epsilon
                     and ixx * iyy - ixy * ixy >= -epsilon and determinant >= -epsilon)
    moments = symmetric_eigenvalues(inertial.tensor)
    epsilon = _epsilon(moments)
    a, b, c = moments
    valid = (min(moments) + epsilon >= 0.0 and a + b + epsilon >= c
             and b + c + epsilon >= a and c + a + epsilon >= b)
    return not (near_positive and valid)


def refused_inertias(robot: Robot, lump_fixed: bool = False
                     ) -> list[tuple[ValidationError, str | None]]:
    """
    Return the I202/I203 findings on links SDF export writes that libsdformat refuses.

    Each comes with the parent of the link when ``lump_fixed`` would merge the link into it
    (as libsdformat's own URDF conversion does), else None.
    """
    from urdfgenpy_ros.lumping import lump_fixed_joints
    from urdfgenpy_ros.validation import validate
    written = lump_fixed_joints(robot) if lump_fixed else robot
    refused = {f'link {link.name!r}': link for link in written.links
               if link.name != WORLD and link.inertial is not None
               and sdformat_refuses(link.inertial)}
    if not refused:
        return []
    found = []
    for finding in validate(written, check_meshes=False):
        link = refused.get(finding.element)
        if finding.code in ('I202', 'I203') and link is not None:
            joint = written.parent_joint(link.name)
            found.append((finding, joint.parent if joint is not None and lumps(joint)
                          else None))
    return found
