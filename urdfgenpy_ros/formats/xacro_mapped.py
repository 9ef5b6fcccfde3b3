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
A finding on a Xacro expansion, placed by the expansion's source map.

The line of the finding's element in the expansion leads to the start tag it was written
as (``formats.xacro_map``). When the finding names an attribute that the tag writes as an
expression (``ixx="${m*(h*h)/12}"``), the place is that attribute's, and ``via`` also
names where the values it reads are written: a parameter at the macro call, else the one
``<xacro:property>`` of that name.
"""

from __future__ import annotations

import os
from pathlib import Path
import re
from typing import TYPE_CHECKING

from urdfgenpy_ros.formats.xacro_tags import Attribute, attributes, is_expression, names_read
from urdfgenpy_ros.model.errors import ParseError, SourceLocation, ValidationError

if TYPE_CHECKING:
    from urdfgenpy_ros.formats.xacro_map import Origin, XacroMap

EXPANDED = ' (expanded)'


def mapped(finding: ValidationError, source_map: XacroMap) -> ValidationError:
    """Return ``finding`` placed where its element (or expression) is written."""
    where = finding.location
    if not (where.file or '').endswith(EXPANDED) or where.line is None:
        return finding
    steps = _steps(where.path)
    line = source_map.line_of(where.line, steps)
    if line not in source_map.raw or not _is_on_path(source_map, line, where.path, steps):
        location = SourceLocation(where.file, None, None, where.path)
    else:
        location = place(line, (where.file or '')[:-len(EXPANDED)], source_map, where.path,
                         f'{finding.message} {finding.hint}')
    return ValidationError(finding.code, finding.severity, finding.element, location,
                           finding.message, finding.hint)


_OWNER = re.compile(r"^/robot/[\w:.-]+\[@name='.*?'\]")
_STEP = re.compile(r"([\w:.-]+)(?:\[(\d+)\]|(\[@name='.*'\]))?$")


def _steps(path: str | None) -> list[tuple[str, int]]:
    """
    Return the steps of an element path below its owner: ``/inertial/inertia``.

    Each is (tag, 1-based index); a step chosen by name (``sensor[@name='gps']``) has 0.
    """
    owner = _OWNER.match(path or '')
    if owner is None or path is None:
        return []
    steps = []
    for part in path[owner.end():].strip('/').split('/'):
        step = _STEP.match(part)
        if step is None:
            break
        steps.append((step.group(1), 0 if step.group(3) else int(step.group(2) or 1)))
    return steps


def _is_on_path(source_map: XacroMap, line: int, path: str | None,
                steps: list[tuple[str, int]]) -> bool:
    """
    Return whether the expansion's line holds an element of the finding's path.

    A finding on a robot edited since it was read (``convert --fix``) can carry a line of
    the edited text: one that is no element of its path gets no place rather than a wrong one.
    """
    owner = _OWNER.match(path or '')
    if owner is None:
        return True  # a finding on the robot, or a block: nothing to compare
    kind = owner.group(0)[len('/robot/'):].split('[', 1)[0]
    return source_map.tags.get(line) in {kind, *(tag for tag, _ in steps)}


def mapped_error(error: ParseError, source_map: XacroMap) -> ParseError:
    """Return a read error in an expansion, placed where its element is written."""
    where = error.location
    assert where is not None and where.file is not None and where.line is not None
    location = place(where.line, where.file[:-len(EXPANDED)], source_map, where.path,
                     error.message)
    return ParseError(error.message, location, error.code)


def place(expanded: int, main: str, source_map: XacroMap, path: str | None,
          text: str) -> SourceLocation:
    """
    Return where the element on line ``expanded`` of the expansion is written.

    Files are named as the user names them (``main`` as given). ``text`` is what the
    finding says: an expression attribute it names (of the element, or of a child it
    names: ``mass`` for ``<mass value="${m}"/>``) is the place.
    """
    origin = source_map.at(expanded)
    assert origin is not None
    where, via = origin.where, origin.via
    line, column = where.line, where.column
    chosen = _named(origin, text, expanded not in source_map.children)  # a leaf: its value
    for tag, row in source_map.children.get(expanded, ()) if chosen is None else ():
        child = source_map.at(row)
        if child is not None and _mentions(text, tag):
            chosen = _named(child, text, True)
            if chosen is not None:
                origin = child
                break
    if chosen is not None:
        line, column = chosen.line, chosen.column
        via = (*_read_by(chosen, origin, source_map), *via)
    return SourceLocation(shown(origin.where.file, main), line, column, path,
                          tuple(step._replace(file=shown(step.file, main)) for step in via))


def _mentions(text: str, name: str) -> bool:
    return re.search(rf'(?<![\w-]){re.escape(name)}(?![\w-])', text) is not None


def _named(origin: Origin, text: str, alone: bool) -> Attribute | None:
    """
    Return the expression attribute of the tag at ``origin`` that ``text`` names.

    With ``alone``, the tag's only expression attribute also counts as named. A ``name``
    is the element's identity, not a value a finding is about: it is never chosen.
    """
    where = origin.where
    if where.file is None or where.line is None or where.column is None:
        return None
    made = [attribute for attribute in attributes(where.file, where.line, where.column)
            if is_expression(attribute.value) and attribute.name != 'name']  # not a value
    named = [attribute for attribute in made if _mentions(text, attribute.name)]
    if named:
        return named[0]
    return made[0] if alone and len(made) == 1 else None


def _read_by(attribute: Attribute, origin: Origin, source_map: XacroMap
             ) -> list[SourceLocation]:
    """Return where the values an expression reads are written (a call's, a property's)."""
    call = origin.via[0] if origin.via and origin.via[0].path != '<xacro:include>' else None
    given = {}
    if call is not None and call.file and call.line and call.column:
        given = {item.name: item for item in attributes(call.file, call.line, call.column)}
    found = []
    for name in names_read(attribute.value):
        if name in given:
            item = given[name]
            found.append(SourceLocation(call.file if call else None, item.line, item.column,
                                        f'{name}="{item.value}" of {call.path if call else ""}'))
            continue
        written = source_map.properties.get(name, [])
        if len(written) > 1:
            written = [one for one in written if one.file == origin.where.file]
        if len(written) == 1:
            found.append(written[0])
    return found


def shown(file: str | None, main: str) -> str | None:
    """Return a source file's name: ``main`` as given, else relative to the working folder."""
    if file is None:
        return None
    absolute = Path(file).resolve()
    if absolute == Path(main).resolve():
        return main
    relative = os.path.relpath(absolute)
    return str(absolute) if relative.startswith('..') else relative
