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
``check --fix`` on Xacro: the repairs as edits of attribute values in the Xacro text.

The repaired robot is written as the expansion would be (one changed value, one changed
line); each changed attribute of the expansion leads, through the source map, to the
attribute of the tag it was written in: a literal is edited there, ``${name}`` of a
property at the property's ``value``. The edited files are expanded again by the real
xacro, in memory, and must give the repaired robot; otherwise nothing is written.
A repair that adds or removes elements is not an attribute edit: the file is left alone.
"""

from __future__ import annotations

from collections.abc import Mapping
import copy
import difflib
from pathlib import Path
import re
from typing import NamedTuple, TYPE_CHECKING

from urdfgenpy_ros.formats.urdf import urdf_file_bytes
from urdfgenpy_ros.formats.xacro_tags import attributes, source_text
from urdfgenpy_ros.model.errors import ValidationError
from urdfgenpy_ros.validation.fix import fix, Repair

if TYPE_CHECKING:
    from urdfgenpy_ros.formats.xacro_map import XacroMap
    from urdfgenpy_ros.validation.checklist import Review

_ATTRIBUTE = re.compile(r'([^\s=/>]+)\s*=\s*"([^"]*)"')
_PROPERTY = re.compile(r'\$\{\s*([A-Za-z_]\w*)\s*\}')


class XacroEdit(NamedTuple):
    """One value to change in a Xacro file: the attribute at line and column of file."""

    file: str
    line: int
    column: int
    name: str
    old: str
    new: str
    made: int  # how many elements of the robot this tag makes (its macro's instances)
    macro: str | None  # the call (``<xacro:arm>``) that instantiates the tag, if any


def plan(source_map: XacroMap, before: str, after: str) -> tuple[list[XacroEdit], str | None]:
    """Return the edits of the Xacro files that turn expansion ``before`` into ``after``."""
    old, new = before.split('\n'), after.split('\n')
    edits: dict[tuple[str, int, int, str], XacroEdit] = {}
    for kind, first, last, other, _ in difflib.SequenceMatcher(
            None, old, new, autojunk=False).get_opcodes():
        if kind == 'equal':
            continue
        if kind != 'replace' or last - first != _ - other:
            return [], 'a repair adds or removes elements, which is no edit of a value'
        for offset in range(last - first):
            problem = _line_edits(source_map, first + offset + 1, old[first + offset],
                                  new[other + offset], edits)
            if problem is not None:
                return [], problem
    return list(edits.values()), None


def _line_edits(source_map: XacroMap, line: int, before: str, after: str,
                edits: dict[tuple[str, int, int, str], XacroEdit]) -> str | None:
    origin = source_map.at(line)
    file = origin.where.file if origin is not None else None
    if origin is None or file is None:
        return f'line {line} of the expansion comes from no tag of the files'
    was, now = _values(before), _values(after)
    if set(was) != set(now) or before.split('>')[0].split()[0] != after.split('>')[0].split()[0]:
        return 'a repair adds or removes attributes, which is no edit of a value'
    where = origin.where
    written = {item.name: item
               for item in attributes(file, where.line or 0, where.column or 0)}
    made = sum(1 for raw in source_map.raw.values() if raw[:3] == where[:3])
    macro = origin.via[0].path if origin.via and origin.via[0].path != '<xacro:include>' \
        else None
    for name in (name for name in now if now[name] != was[name]):
        item = written.get(name)
        if item is None:
            return f'{name}= of {file}:{where.line} is not written in its tag'
        target: tuple[str, int, int, str, str, int] = (
            file, item.line, item.column, name, item.value, made)
        if '$' in item.value:
            target = _property(source_map, item.value, file) or target
            if '$' in target[4]:
                return f'{name}="{item.value}" at {file}:{item.line} is an expression'
        key = target[:4]
        if key in edits and edits[key].new != now[name]:
            return (f'{name}= at {target[0]}:{target[1]} makes elements that need '
                    'different values')
        file, row, column, _, value, count = target
        edits[key] = XacroEdit(file, row, column, name if count else 'value', value,
                               now[name], count, macro)
    return None


def _property(source_map: XacroMap, value: str, file: str
              ) -> tuple[str, int, int, str, str, int] | None:
    """Return the place of the ``value`` of the one property ``${name}`` reads, if so."""
    found = _PROPERTY.fullmatch(value.strip())
    places = source_map.properties.get(found.group(1), []) if found else []
    if len(places) > 1:
        places = [place for place in places if place.file == file]
    found_file = places[0].file if len(places) == 1 else None
    if found_file is None:
        return None
    place = places[0]
    for item in attributes(found_file, place.line or 0, place.column or 0):
        if item.name == 'value':
            return found_file, item.line, item.column, 'value', item.value, 0
    return None


def _values(line: str) -> dict[str, str]:
    """Return the attributes of the one start tag of an expansion's line."""
    start = line.find('<')
    end = line.find('>', start)
    return dict(_ATTRIBUTE.findall(line[start:end if end >= 0 else len(line)]))


def edited(edits: list[XacroEdit]) -> Mapping[str, str] | None:
    """Return each edited file's new text (by absolute path), or None if a value moved."""
    texts: dict[str, list[str]] = {}
    for edit in sorted(edits, key=lambda edit: (edit.file, edit.line, -edit.column)):
        if edit.file not in texts:
            text = source_text(edit.file)
            if text is None:
                return None
            texts[edit.file] = text.split('\n')
        rows = texts[edit.file]
        row, start = rows[edit.line - 1], edit.column - 1
        written = re.compile(rf'{re.escape(edit.name)}(\s*=\s*)(["\']){re.escape(edit.old)}\2')
        found = written.match(row, start)
        if found is None:
            return None
        rows[edit.line - 1] = (f'{row[:start]}{edit.name}{found.group(1)}{found.group(2)}'
                               f'{edit.new}{found.group(2)}{row[found.end():]}')
    return {str(Path(file).resolve()): '\n'.join(rows) for file, rows in texts.items()}


def plan_fix(found: Review, source_map: XacroMap
             ) -> tuple[list[ValidationError], list[tuple[ValidationError, str]],
                        dict[tuple[str, int, int, str], XacroEdit]]:
    """
    Return the repairs that are value edits, the others with why, and the edits.

    Each of ``found``'s repairable findings is repaired alone, on a copy of the robot.
    """
    robot, defaults = found.robot, dict(found.options.limit_defaults)
    accepted: list[ValidationError] = []
    refused: list[tuple[ValidationError, str]] = []
    edits: dict[tuple[str, int, int, str], XacroEdit] = {}
    robot.source_map = None  # not copied for each trial
    try:
        for finding in found.repairable:
            trial = copy.deepcopy(robot)
            if not fix(trial, [finding], defaults):
                continue
            after = urdf_file_bytes(trial, mend=False).decode('utf-8', 'surrogateescape')
            made, problem = plan(source_map, source_map.text, after)
            clash = [edit for edit in made if edit[:4] in edits and edits[edit[:4]] != edit]
            if problem is None and clash:
                problem = f'{clash[0].name}= at line {clash[0].line} needs two values'
            if problem is not None:
                refused.append((finding, problem))
                continue
            accepted.append(finding)
            edits.update((edit[:4], edit) for edit in made)
    finally:
        robot.source_map = source_map
    return accepted, refused, edits


def apply_fix(found: Review, accepted: list[ValidationError]) -> list[Repair]:
    """Repair the ``accepted`` findings in ``found``'s robot, in place."""
    return fix(found.robot, accepted, dict(found.options.limit_defaults))
