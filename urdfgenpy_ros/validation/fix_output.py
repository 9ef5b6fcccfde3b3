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
``urdfgenpy convert --fix``: check's repairs, made to the model a conversion writes.

The source (Xacro included) is not touched. The errors ``check --fix`` repairs are repaired
(I205's new root is a choice, not a repair, and is left out). A tensor on a link with no
shape to take one from (a cliff sensor's link, say) gets a stated default: the tensor of a
solid sphere of the link's mass and of radius ``radius``, its centre of mass kept.
"""

from __future__ import annotations

from collections.abc import Sequence
from os import PathLike
from typing import TYPE_CHECKING

from urdfgenpy_ros.model.errors import Severity, ValidationError
from urdfgenpy_ros.model.floats import fmt
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.validation.checklist import review, ReviewOptions
from urdfgenpy_ros.validation.fix import fix, Repair

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

DEFAULT_RADIUS = 0.05
"""Radius (m) of the solid sphere whose tensor a link without shapes gets."""
_TENSORS = ('I202', 'I203')


def fix_for_output(robot: RobotModel, radius: float = DEFAULT_RADIUS,
                   search_paths: Sequence[str | PathLike[str]] = (),
                   radius_option: str = '--fix-radius') -> list[str]:
    """
    Repair ``robot``'s fixable errors in place; return one line per repair (or refusal).

    A tensor comes from the link's shapes, meshes found through ``search_paths``; a
    link without one gets a sphere's of ``radius``, which ``radius_option`` sets.
    """
    found = review(robot, ReviewOptions(check_meshes=False, suppressions=False,
                                        search_paths=search_paths))
    errors = [finding for finding in found.repairable if finding.severity is Severity.ERROR]
    repairs = fix(robot, errors, search_paths=search_paths)
    done = {(repair.code, repair.element) for repair in repairs}
    lines = [str(repair) for repair in repairs]
    for finding in errors:
        if finding.code in _TENSORS and (finding.code, finding.element) not in done:
            lines.append(_sphere(robot, finding, radius, radius_option))
            done.add((finding.code, finding.element))
    return lines


def _sphere(robot: RobotModel, finding: ValidationError, radius: float, option: str) -> str:
    """Give a link without shapes the tensor of a solid sphere; return the line saying so."""
    name = finding.element.split("'", 2)[1]
    inertial = robot.get_link(name).inertial if robot.has_link(name) else None
    if inertial is None or not inertial.mass > 0.0:
        return (f'{finding.location}: not fixed {finding.code} {finding.element}: it has no '
                'positive mass to take a tensor from (give it a mass and inertia)')
    solid = Inertial.from_sphere(inertial.mass, radius)
    inertial.ixx, inertial.iyy, inertial.izz = solid.ixx, solid.iyy, solid.izz
    inertial.ixy = inertial.ixz = inertial.iyz = 0.0
    return str(Repair(finding.code, finding.element, finding.location,
                      f'inertia replaced by that of a solid sphere of radius {fmt(radius)} m '
                      f'with mass {fmt(inertial.mass)} (it has no shape to take one from: '
                      f'{option} sets the size)'))
