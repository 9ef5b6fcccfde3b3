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

"""The review's checks run without the review: a target's refusals, nothing silenced."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from urdfgenpy_ros.model.findings import Findings
from urdfgenpy_ros.model.review import ReviewRecord

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def checked(robot: RobotModel, *checks: Callable[[RobotModel, Findings], None]
            ) -> ReviewRecord:
    """Return the record of ``checks`` run in turn on ``robot``, at their source lines."""
    from urdfgenpy_ros.formats.xacro_source import in_source
    findings = Findings(robot)
    for check in checks:
        check(robot, findings)
    refused = {consumer: in_source(items, robot) for consumer, items in findings.refused.items()}
    return ReviewRecord(robot, findings=in_source(findings.items, robot), refused=refused)
