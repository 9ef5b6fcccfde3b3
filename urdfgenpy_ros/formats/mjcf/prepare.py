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
What MuJoCo refuses of a robot, found before anything is written.

:func:`prepare` checks the options (a bad one is a :class:`ModelError` at once) and
returns a :class:`~urdfgenpy_ros.model.review.ReviewRecord` whose ``refused['mujoco']``
lists what stops the export: not one tree (S002), a joint naming a link that does not
exist (S004, S005), and the masses and tensors MuJoCo refuses to compile (I201-I203,
I207: the review's inertia check, nothing silenced). :func:`raise_refused` raises from
such a review what ``write_mjcf`` raises.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, NamedTuple, TYPE_CHECKING

from urdfgenpy_ros.formats.mjcf.actuators import ACTUATOR_TYPES
from urdfgenpy_ros.formats.mjcf.bodies import WORLD
from urdfgenpy_ros.formats.mjcf.fusing import fused
from urdfgenpy_ros.formats.mjcf.gains import Gains
from urdfgenpy_ros.model.errors import ModelError, Severity, SourceLocation, UrdfgenpyError
from urdfgenpy_ros.model.errors import ValidationError
from urdfgenpy_ros.model.review import ReviewRecord

if TYPE_CHECKING:
    from urdfgenpy_ros.formats.mjcf.fusing import Sites
    from urdfgenpy_ros.model import RobotModel

BASES = ('fixed', 'floating')
REFUSED = ('I201', 'I202', 'I203', 'I207')  # what MuJoCo refuses to compile
TENSORS = ('I202', 'I203')  # of these, what convert --fix repairs
MINIMUM_MASS = 1e-15  # MuJoCo's mjMINVAL: a moving body needs this much
STRUCTURE = ('S002', 'S004', 'S005')  # refused as a ModelError, not a mass or tensor
CONSUMER = 'mujoco'  # the key of the refusals in Review.refused


class MjcfRefusedError(UrdfgenpyError):
    """The robot has what MuJoCo refuses (an inertia, a mass): nothing was written."""

    def __init__(self, message: str, findings: list[ValidationError]) -> None:
        super().__init__(message)
        self.findings = findings


class Fused(NamedTuple):
    """The robot as the MJCF writes it: fixed links fused, or the robot itself."""

    robot: RobotModel
    sites: Sites
    owners: dict[str, list[str]]


def prepare(robot: RobotModel, options: Mapping[str, Any]) -> ReviewRecord:
    """
    Return the review of what MuJoCo refuses of ``robot`` written with ``options``.

    ``options`` are :func:`~urdfgenpy_ros.formats.mjcf.write_mjcf`'s keywords (others
    are ignored); the refusals are the review's findings and its ``refused['mujoco']``.

    :raises ModelError: for a bad ``base``, ``actuators``, ``kp`` or ``kv``.
    """
    return prepared(robot, options)[0]


def prepared(robot: RobotModel, options: Mapping[str, Any]
             ) -> tuple[ReviewRecord, Fused | None]:
    """Return the review and the robot the MJCF is written from (None when refused)."""
    check_options(options)
    refused = _structure(robot)
    written = None
    if not refused:
        fuse_fixed = bool(options.get('fuse_fixed', False))
        written = Fused(*fused(robot)) if fuse_fixed else Fused(robot, {}, {})
        refused = _masses(written.robot, options.get('base') == 'floating')
    review = ReviewRecord(robot, findings=list(refused),
                          refused={CONSUMER: refused} if refused else {})
    return review, written if not refused else None


def check_options(options: Mapping[str, Any]) -> None:
    """Refuse a ``base``, ``actuators`` or gain that the MJCF writer does not take."""
    base, actuators = options.get('base'), options.get('actuators')
    if base not in (None, *BASES):
        raise ModelError(f'base {base!r}: use fixed or floating')
    if actuators not in (None, *ACTUATOR_TYPES):
        raise ModelError(f"actuators {actuators!r}: use {', '.join(ACTUATOR_TYPES)}")
    Gains.of('kp', options.get('kp'), True)
    Gains.of('kv', options.get('kv'), False)


def _structure(robot: RobotModel) -> list[ValidationError]:
    """Return the first of: not one root link, a joint naming a link that does not exist."""
    if len(robot.roots) != 1:
        return [_refusal('S002', f'robot {robot.name!r}', robot.source,
                         f'robot {robot.name!r} has {len(robot.roots)} root links: MJCF '
                         'needs one tree (urdfgenpy check says why)')]
    for joint in robot.joints:
        for role, code in (('parent', 'S004'), ('child', 'S005')):
            if not robot.has_link(getattr(joint, role)):
                return [_refusal(code, f'joint {joint.name!r}', joint.source,
                                 f'joint {joint.name!r}: {role} link '
                                 f'{getattr(joint, role)!r} does not exist: define the link '
                                 'or fix the name')]
    return []


def _refusal(code: str, element: str, source: SourceLocation | None, message: str
             ) -> ValidationError:
    return ValidationError(code, Severity.ERROR, element, source or SourceLocation(),
                           message, '')


def _masses(written: RobotModel, floating: bool) -> list[ValidationError]:
    """Return the findings of ``written`` whose mass or tensor MuJoCo refuses."""
    from urdfgenpy_ros.formats.inertia_check import check_inertia, non_finite_inertials
    from urdfgenpy_ros.formats.checked import checked
    refused = non_finite_inertials(written)  # MuJoCo compiles NaN, then refuses the body
    refused += [finding for finding in checked(written, check_inertia).findings
                if finding.code in REFUSED]
    root = written.root
    if floating and root.name != WORLD and _welded_mass(written, root.name) < MINIMUM_MASS:
        refused.append(ValidationError(
            'I201', Severity.ERROR, f'link {root.name!r}',
            root.source or SourceLocation(path=f"/robot/link[@name='{root.name}']"),
            'the root link moves (a floating base) but has no mass, nor anything welded '
            'to it', 'give it a mass and inertia (Inertial.from_geometry), or keep the base '
            'fixed: MuJoCo refuses a massless moving body'))
    return refused


def raise_refused(review: ReviewRecord, fuse_fixed: bool) -> None:
    """
    Raise what ``write_mjcf`` raises for the refusals of ``review``; nothing if none.

    :raises ModelError: for a robot that is not one tree, or a dangling joint link.
    :raises MjcfRefusedError: for the masses and tensors MuJoCo refuses.
    """
    refused = review.refused.get(CONSUMER, [])
    if not refused:
        return
    if refused[0].code in STRUCTURE:
        raise ModelError(refused[0].message)
    raise MjcfRefusedError(
        f'robot {review.robot.name!r}: MuJoCo refuses the mass or inertia of '
        f'{len(refused)} link(s): {_advice(refused, fuse_fixed)}; nothing written', refused)


def _advice(refused: list[ValidationError], fuse_fixed: bool) -> str:
    """Return what repairs the refused links: convert --fix for a tensor, else the URDF."""
    tensors = sorted({finding.element for finding in refused if finding.code in TENSORS})
    numbers = sorted({finding.element for finding in refused if finding.code == 'R305'})
    massless = sorted({finding.element for finding in refused
                       if finding.code not in TENSORS} - set(numbers))
    said = [f"write finite numbers in the <inertial> of {', '.join(numbers)}"] if numbers else []
    if tensors:
        said.append(f"urdfgenpy convert --fix repairs the tensor of {', '.join(tensors)}")
    if massless:
        said.append(f"give {', '.join(massless)} an <inertial> with a positive mass (urdfgenpy "
                    'inertia MESH --mass KG prints one; Inertial.from_geometry in Python)'
                    + ('' if fuse_fixed else ', or pass --fuse-fixed / fuse_fixed if they '
                       'are fixed links'))
    return '; '.join(said)


def _welded_mass(robot: RobotModel, name: str) -> float:
    """Return the mass of link ``name`` and of every link welded to it below."""
    link = robot.get_link(name)
    mass = link.inertial.mass if link.inertial is not None else 0.0
    return mass + sum(_welded_mass(robot, joint.child) for joint in robot.child_joints(name)
                      if joint.type.value == 'fixed')
