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

"""The links whose inertia an SDF loader refuses: the review's ``libsdformat`` check."""

from __future__ import annotations

from typing import TYPE_CHECKING

from urdfgenpy_ros.formats.sdf_inertia import refusal
from urdfgenpy_ros.model.errors import Severity, SourceLocation, ValidationError
from urdfgenpy_ros.model.findings import Findings, link_path
from urdfgenpy_ros.model.joint import JointType
from urdfgenpy_ros.reshape.lumping import lumps, WORLD

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


_SAME = {'I202': ('I202', 'I203'), 'I203': ('I202', 'I203'), 'I210': ('I201', 'I210'),
         'R305': ('R305',)}  # the inertia check's codes for what libsdformat refuses
_HINTS = {'I201': 'give it a positive mass (kg)', 'I210': 'give it a positive mass (kg)',
          'R305': 'write finite numbers in its <inertial>'}


def sdformat_refusals(robot: RobotModel, findings: Findings) -> list[ValidationError]:
    """
    Return a finding for each link of ``robot`` libsdformat refuses.

    I202 or I203 for a tensor, I201 or I210 for a negative mass, R305 for NaN or inf: the
    inertia check's finding when it made one (with the file and line: that check runs
    first), else one made here, at the ``<inertial>``.
    """
    made = {(finding.element, finding.code): finding for finding in findings.items}
    refused = []
    for link in robot.links:
        problem = refusal(link.inertial) if link.inertial is not None and \
            link.name != WORLD else None
        if problem is None:
            continue
        element = f'link {link.name!r}'
        found = next(filter(None, (made.get((element, code)) for code in _SAME[problem[0]])),
                     None)
        if found is None:
            code, message = problem
            if code == 'I210' and _moves(robot, link.name):
                code = 'I201'  # the inertia check's code for a link that moves
            source = link.inertial.source if link.inertial is not None else None
            where = (source if source is not None and source.line is not None
                     else SourceLocation(path=link_path(link.name) + '/inertial/inertia'))
            found = ValidationError(code, Severity.ERROR, element, where, message,
                                    _HINTS.get(code, 'libsdformat refuses it'))
        refused.append(found)
    return refused


def _moves(robot: RobotModel, name: str) -> bool:
    """Return whether link ``name`` hangs on a joint that moves."""
    joint = robot.parent_joint(name)
    return joint is not None and joint.type is not JointType.FIXED


def check_libsdformat(robot: RobotModel, findings: Findings) -> None:
    """Name the links libsdformat refuses in ``findings.refused['libsdformat']``."""
    findings.refused['libsdformat'] = sdformat_refusals(robot, findings)


def lumped_into(robot: RobotModel, finding: ValidationError) -> str | None:
    """Return the link a fixed joint would lump the finding's link into, or None."""
    name = finding.element.split("'", 2)[1]
    joint = robot.parent_joint(name) if robot.has_link(name) else None
    return joint.parent if joint is not None and lumps(joint) else None
