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

"""Collect findings with their location: file:line:column, or the element path."""

from __future__ import annotations

from pathlib import Path
import re
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.codes import severity_of
from urdfgenpy_ros.model.errors import SourceLocation, ValidationError

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def link_path(name: str) -> str:
    """Return the element path of a link."""
    return f"/robot/link[@name='{name}']"


def joint_path(name: str) -> str:
    """Return the element path of a joint."""
    return f"/robot/joint[@name='{name}']"


class Findings:
    """The findings of one validation run, in the order they were found."""

    def __init__(self, robot: RobotModel) -> None:
        self.robot = robot
        self.items: list[ValidationError] = []
        self.refused: dict[str, list[ValidationError]] = {}
        """Consumer -> the findings for which it refuses the robot (``Review.refused``)."""
        self._lines: dict[str, list[str] | None] = {}

    def add(self, code: str, source: Any, element: str, path: str, message: str,
            hint: str, tag: str | None = None) -> None:
        """Record a finding about ``element`` (read at ``source``, or at ``path``)."""
        self.items.append(ValidationError(code, severity_of(code), element,
                                          self._where(source, path, tag), message, hint))

    def _where(self, source: Any, path: str, tag: str | None) -> SourceLocation:
        location = getattr(source, 'source', source)
        if not isinstance(location, SourceLocation) or location.line is None:
            return SourceLocation(path=path)
        if location.column is not None:
            return location._replace(path=path)
        tag = tag or path.rsplit('/', 1)[-1].split('[', 1)[0]
        line, column = self._find(location.file, location.line, tag)
        return SourceLocation(location.file, line, column, path)

    def _find(self, file: str | None, line: int, tag: str) -> tuple[int, int]:
        """Return line and column of ``<tag`` at or just after the element's line."""
        if not file:
            return line, 1
        if file not in self._lines:
            try:
                self._lines[file] = Path(file).read_text(
                    encoding='utf-8', errors='replace').splitlines()
            except OSError:
                self._lines[file] = None
        lines = self._lines[file] or []
        pattern = re.compile(f'<{re.escape(tag)}(?=[\\s/>])')
        for number in range(line, min(line + 12, len(lines) + 1)):
            found = pattern.search(lines[number - 1])
            if found:
                return number, found.start() + 1
        return line, 1
