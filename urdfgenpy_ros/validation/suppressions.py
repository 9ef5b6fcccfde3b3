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
Suppression comments: ``<!-- urdfgenpy: ignore I205 -->`` and ``ignore-file``.

``<!-- urdfgenpy: ignore CODE [CODE...] -->`` directly before an element (other comments
may stand between) silences those codes for findings about that element and everything
inside it: a comment before ``<link name="arm">`` silences the link's ``inertial``,
``visual[1]/geometry``, ... findings, one before its ``<inertial>`` only those. A finding
is "about" an element when its element path starts with the element's path (findings
without a path, such as the reader's, when their line lies inside the element).
``<!-- urdfgenpy: ignore-file CODE... -->`` before the first element (above ``<robot>`` or
first inside it) silences the codes in the whole file. The comments are ordinary XML
comments: they survive reading and writing, ``check --fix`` included.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
import re
from typing import TYPE_CHECKING

from urdfgenpy_ros.model.codes import CODES
from urdfgenpy_ros.model.errors import ValidationError

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

_DIRECTIVE = re.compile(r'^\s*urdfgenpy\s*:\s*(ignore-file|ignore)\b(.*)$', re.DOTALL)
_CODE = re.compile(r'[A-Z]\d{3}')
_CODE_LIKE = re.compile(r'[A-Za-z][0-9A-Za-z]{3}')  # I205, and typos such as I2O5 or i205


@dataclass(frozen=True)
class Scope:
    """Codes silenced for one element: its path and the lines it spans."""

    path: str
    first: int
    last: int
    codes: frozenset[str]


@dataclass
class Suppressions:
    """The suppression comments of one file, and the codes ``--ignore`` gives."""

    file_codes: frozenset[str] = frozenset()
    scopes: list[Scope] = field(default_factory=list)
    ignored: frozenset[str] = frozenset()
    unknown: list[tuple[int, str]] = field(default_factory=list)
    """(line, word) of what a suppression comment names that is no finding code."""

    def reason(self, finding: ValidationError) -> str | None:
        """Return why ``finding`` is silenced (``'inSource'``, ``'external'``) or None."""
        found = self.silencer(finding)
        return found[0] if found is not None else None

    def source(self, finding: ValidationError) -> str:
        """Return what silences ``finding`` (the ignore option, or which comment)."""
        found = self.silencer(finding)
        return found[1] if found is not None else ''

    def silencer(self, finding: ValidationError) -> tuple[str, str] | None:
        """Return (reason, what silences it) for a silenced ``finding``, else None."""
        if finding.code in self.ignored:
            return 'external', 'the ignore option'
        if finding.code in self.file_codes:
            return 'inSource', 'an ignore-file comment'
        where = finding.location
        for scope in self.scopes:
            if finding.code not in scope.codes:
                continue
            if where.path is not None and (where.path == scope.path
                                           or where.path.startswith(scope.path + '/')):
                return 'inSource', f'the ignore comment before line {scope.first}'
            if where.path is None and where.line is not None \
                    and scope.first <= where.line <= scope.last:
                return 'inSource', f'the ignore comment before line {scope.first}'
        return None

    def split(self, findings: Iterable[ValidationError]
              ) -> tuple[list[ValidationError], list[tuple[ValidationError, str]]]:
        """Return the findings that stay, and the silenced ones with their reason."""
        kept: list[ValidationError] = []
        silenced: list[tuple[ValidationError, str]] = []
        for finding in findings:
            reason = self.reason(finding)
            if reason is None:
                kept.append(finding)
            else:
                silenced.append((finding, reason))
        return kept, silenced


def parse_codes(text: str) -> frozenset[str]:
    """Return the codes in ``I205,R307`` or ``I205 R307``; refuse anything else."""
    parts = [part.upper() for part in re.split(r'[\s,]+', text.strip()) if part]
    bad = [part for part in parts if part not in CODES]
    if bad:
        raise ValueError(f'{", ".join(bad)} is not a finding code (like I205; docs/validation.md '
                         'lists them under "Every code")')
    return frozenset(parts)


def read_suppressions(robot: RobotModel, ignored: Iterable[str] = ()) -> Suppressions:
    """Return the suppression comments of the file ``robot`` was read from."""
    result = Suppressions(ignored=frozenset(ignored))
    document = robot.extras
    if document is None:
        return result
    file_codes: set[str] = set()
    for comment in document.directives:
        found = _directive(comment.text)
        if found is None:
            continue
        if found[0] == 'ignore-file' and comment.leading:
            file_codes |= found[1]
        result.unknown += [(comment.line, word) for word in _unknown(comment.text)]
        if found[0] == 'ignore' and comment.path:
            result.scopes.append(Scope(comment.path, comment.first, comment.last, found[1]))
    result.file_codes = frozenset(file_codes)
    return result


def _directive(text: str) -> tuple[str, frozenset[str]] | None:
    match = _DIRECTIVE.match(text)
    if match is None:
        return None
    return match.group(1), frozenset(_CODE.findall(match.group(2)))


def _unknown(text: str) -> list[str]:
    """Return the words of a directive that look like finding codes but are none."""
    match = _DIRECTIVE.match(text)
    words = re.split(r'[\s,]+', match.group(2).strip()) if match else []
    return [word for word in words if _CODE_LIKE.fullmatch(word) and word not in CODES
            and sum(char.isdigit() for char in word) >= 2]
