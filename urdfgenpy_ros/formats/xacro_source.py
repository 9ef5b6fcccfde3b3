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
Findings in a Xacro file: the source line of their element, or no line at all.

A robot read from Xacro is read from xacro's expansion, so its line numbers are the
expansion's, which the user never sees; xacro keeps no source map. A finding's element
(``joint 'elbow'``) is given the line of the one tag that must have made it: a
``<joint name="elbow"`` written literally as a child of the file's ``<robot>`` (it is
always in the expansion, whose names are unique); else one written literally exactly once
in the file and the files it includes (comments left out), with no tag of that kind whose
name is an expression that could also evaluate to ``elbow`` (``${prefix}elbow``,
``${name}``). Otherwise, a name a macro or expression makes, the finding keeps the file, as
``FILE (expanded)``, and has no line: a wrong line would send the user to the wrong
element. ``xacro:element`` or a ``name`` set by ``xacro:attribute`` leaves every line out.
"""

from __future__ import annotations

from functools import lru_cache
import os
from pathlib import Path
import re
from typing import NamedTuple, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.model.errors import ParseError, SourceLocation, ValidationError

if TYPE_CHECKING:
    from urdfgenpy_ros.formats.xacro_map import XacroMap
    from urdfgenpy_ros.model import RobotModel

EXPANDED = ' (expanded)'
"""How a location in an expanded Xacro names its file (``arm.urdf.xacro (expanded)``)."""

_OWNER = re.compile(r"^/robot/([\w:.-]+)\[@name='(.*?)'\]")
_COMMENT = re.compile(r'<!--.*?-->|<!\[CDATA\[.*?\]\]>', re.DOTALL)
_NOT_XML = ('.py', '.yaml', '.yml', '.csv')
_EXPRESSION = re.compile(r'\$\{[^}]*\}|\$\([^)]*\)')


def in_source(findings: list[ValidationError], robot: RobotModel) -> list[ValidationError]:
    """
    Return ``findings`` with each location in a Xacro expansion moved to the source.

    With the expansion's source map (``Robot.from_xacro`` keeps it), a finding gets the
    file, line and column of its element's start tag where it was written, the macro
    calls and includes that brought it there, and for an attribute written as an
    expression, that attribute's place and the properties it reads (``via``). Without
    a map (an assembly of Xacro parts), a finding whose element has one literal source
    tag gets that tag; any other keeps ``FILE (expanded)`` without a line. Other
    findings are unchanged.
    """
    source_map = getattr(robot, 'source_map', None)
    if source_map is not None:
        from urdfgenpy_ros.formats.xacro_mapped import mapped  # a Xacro's findings only
        return [mapped(finding, source_map) for finding in findings]
    files = tuple(file for file in robot.included_files
                  if not file.lower().endswith(_NOT_XML))  # an assembly's YAML, a builder
    return [_moved(finding, files) for finding in findings]


def _moved(finding: ValidationError, files: tuple[str, ...]) -> ValidationError:
    where = finding.location
    if not (where.file or '').endswith(EXPANDED) or where.line is None:
        return finding
    source = where.file[:-len(EXPANDED)] if where.file else ''
    main = str(Path(source).resolve())
    owner = _OWNER.match(where.path or '')
    found = _tag(files or (main,), main, *owner.groups()) if owner else None
    if found is None:
        location = SourceLocation(where.file, None, None, where.path)
    else:
        file, line, column = found
        shown = source if file == main else _shown(file)
        location = SourceLocation(shown, line, column, where.path)
    return ValidationError(finding.code, finding.severity, finding.element, location,
                           finding.message, finding.hint)


def error_in_source(error: ParseError, expanded: str, files: list[str],
                    source: str, source_map: XacroMap | None = None) -> ParseError:
    """
    Return ``error``, found in the expansion of ``source``, placed at its source tag.

    With the expansion's ``source_map``, the tag the failing element was written as;
    without, the failing element's top-level owner (``<joint name="k">``) is looked up
    as findings are; when no single literal tag makes it, the error names
    ``FILE (expanded)`` and the element path, without a line.
    """
    where = error.location
    if where is None or where.line is None or not (where.file or '').endswith(EXPANDED):
        return error
    if source_map is not None and where.line in source_map.raw:
        from urdfgenpy_ros.formats.xacro_mapped import mapped_error
        return mapped_error(error, source_map)
    root = etree.fromstring(expanded.encode('utf-8'), etree.XMLParser(
        recover=True, resolve_entities=False, huge_tree=True))
    owner = None
    for element in root.iter(etree.Element) if root is not None else ():
        if element.sourceline == where.line:
            owner = next((node for node in (element, *element.iterancestors())
                          if node.getparent() is root and node.get('name') is not None), None)
            break
    if owner is None:
        return error
    kind, name = etree.QName(owner).localname, owner.get('name')
    main = str(Path(source).resolve())
    xml = tuple(file for file in files if not file.lower().endswith(_NOT_XML))
    found = _tag(xml or (main,), main, kind, name)
    path = f"/robot/{kind}[@name='{name}']"
    if found is None:
        location = SourceLocation(where.file, None, None, path)
    else:
        file, line, column = found
        location = SourceLocation(source if file == main else _shown(file), line, column, path)
    return ParseError(error.message, location, error.code)


def _shown(file: str) -> str:
    """Return an included file's name relative to the working directory when below it."""
    relative = os.path.relpath(file)
    return file if relative.startswith('..') else relative


class _Tag(NamedTuple):
    kind: str
    name: str  # as written: a literal or an expression
    line: int
    column: int
    top: bool  # a child of <robot>: always in the expansion


@lru_cache(maxsize=64)
def _tags(file: str, stamp: float) -> tuple[_Tag, ...] | None:
    """Return the named tags of a source file; None when unreadable or names are made."""
    try:
        text = Path(file).read_bytes()
        root = etree.fromstring(text, etree.XMLParser(remove_comments=True,
                                                      resolve_entities=False))
    except (OSError, etree.XMLSyntaxError):
        return None
    blank = _COMMENT.sub(lambda match: re.sub(r'[^\n]', ' ', match.group()),
                         text.decode('utf-8', 'replace'))
    tags = []
    starts: dict[str, list[re.Match[str]]] = {}
    seen: dict[str, int] = {}
    for element in root.iter(etree.Element):
        qname = etree.QName(element)
        if 'xacro' in (qname.namespace or ''):
            if qname.localname == 'element' or (
                    qname.localname == 'attribute' and element.get('name') == 'name'):
                return None  # an element or a name made by xacro: no tag to trust
            continue
        name = element.get('name')
        if qname.namespace is not None or name is None:
            continue
        found = starts.setdefault(qname.localname, list(re.finditer(
            rf'<{re.escape(qname.localname)}(?=[\s/>])', blank)))
        index = seen[qname.localname] = seen.get(qname.localname, -1) + 1
        if index >= len(found):
            return None
        offset = found[index].start()
        tags.append(_Tag(qname.localname, name, blank.count('\n', 0, offset) + 1,
                         offset - blank.rfind('\n', 0, offset), element.getparent() is root))
    return tuple(tags)


def _tag(files: tuple[str, ...], main: str, kind: str, name: str
         ) -> tuple[str, int, int] | None:
    """Return (file, line, column) of the only tag that can make ``kind`` ``name``."""
    literal: list[tuple[str, _Tag]] = []
    made = False  # an expression that can evaluate to ``name``
    for file in files:
        try:
            tags = _tags(file, os.stat(file).st_mtime)
        except OSError:
            return None
        if tags is None:
            return None
        for tag in tags:
            if tag.kind != kind:
                continue
            if not _EXPRESSION.search(tag.name):
                if tag.name == name:
                    if tag.top and Path(file) == Path(main):  # expanded; names are unique
                        return file, tag.line, tag.column
                    literal.append((file, tag))
                continue
            template = ''.join('.*' if _EXPRESSION.fullmatch(part) else re.escape(part)
                               for part in re.split(f'({_EXPRESSION.pattern})', tag.name))
            made = made or re.fullmatch(template, name, re.DOTALL) is not None
    if made or len(literal) != 1:
        return None
    file, tag = literal[0]
    return file, tag.line, tag.column
