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
The record of a review, data only: what it found, silenced and refused.

A format's ``prepare`` returns one (what its target refuses, with the ``lines`` a front end
says before writing); :class:`~urdfgenpy_ros.validation.checklist.Review`, what
``review()`` returns, is one with the options it ran with and the repairs it can make.
"""

from __future__ import annotations

from dataclasses import dataclass, field, KW_ONLY
from typing import NamedTuple, TYPE_CHECKING

from urdfgenpy_ros.model.errors import Severity, ValidationError

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

ENGINES = ('mujoco', 'gazebo')
"""The engines a review can pre-flight (``ReviewOptions.engines``, ``check --engines``)."""


class Suppressed(NamedTuple):
    """A finding silenced: ``reason`` is ``'external'`` (ignore option) or ``'inSource'``."""

    finding: ValidationError
    reason: str
    source: str
    """What silenced it: ``the ignore option``, ``an ignore-file comment`` or ``the ignore
    comment before line N``."""


@dataclass
class ReviewRecord:
    """
    What a review found about one robot, ready for any front end to render.

    ``findings`` stay (in check order); ``suppressed`` were silenced, with why;
    ``refused`` names, per consumer, the findings for which it refuses the robot
    (``'libsdformat'``, ``'mujoco'``); ``unknown_suppressions`` are (line, word) of comment
    words that are no finding code. A format's ``prepare`` adds the ``lines`` a front end
    says before writing and the ``refusal``, why nothing is written, when the target
    refuses the robot. Every field but ``robot`` is given by keyword.
    """

    robot: RobotModel
    _: KW_ONLY
    findings: list[ValidationError] = field(default_factory=list)
    suppressed: list[Suppressed] = field(default_factory=list)
    refused: dict[str, list[ValidationError]] = field(default_factory=dict)
    unknown_suppressions: list[tuple[int, str]] = field(default_factory=list)
    lines: list[str] = field(default_factory=list)
    refusal: str | None = None

    @property
    def errors(self) -> list[ValidationError]:
        """Return the findings that stay and are errors."""
        return [finding for finding in self.findings if finding.severity is Severity.ERROR]

    @property
    def warnings(self) -> list[ValidationError]:
        """Return the findings that stay and are warnings."""
        return [finding for finding in self.findings if finding.severity is Severity.WARNING]
