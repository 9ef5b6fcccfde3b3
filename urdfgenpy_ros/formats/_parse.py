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
Safe, tolerant XML loading with exact locations for every error.

Untrusted files cannot reach the network or the file system (no DTD, no external
entity) and cannot blow up memory (a DOCTYPE is refused before parsing). Sloppiness that
urdfdom accepts is accepted too, with a warning: a malformed or misplaced XML
declaration, a trailing NUL byte.
"""

from __future__ import annotations

from dataclasses import dataclass
import re
from typing import Any

from lxml import etree

from urdfgenpy_ros.model.errors import ParseError, ReadWarning, SourceLocation

PARSER = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False,
                         huge_tree=False, collect_ids=False)
_DECLARATION = re.compile(rb'^\s*<\?xml\b[^>]*\?>')
_DOCTYPE = re.compile(rb'<!DOCTYPE', re.IGNORECASE)  # searched for where a '<!' is
# A DOCTYPE that declares and names nothing else (<!DOCTYPE robot>): urdfdom and yourdfpy
# read such files. An internal subset can declare entities, an identifier names a file
_BARE_DOCTYPE = re.compile(rb'<!DOCTYPE\s+[^\s\[>]+\s*>', re.IGNORECASE)
_DECLARATIONS = re.compile(rb'<![^-\[]')  # '<!' opening no comment, no CDATA: quick to find
_UNDECLARED = re.compile(r'Namespace prefix (\S+) (?:for \S+ )?on \S+ is not defined')


@dataclass(slots=True)
class Source:
    """The text of a file being read, to point at lines and columns."""

    file: str | None
    data: bytes

    def line_text(self, line: int) -> str:
        """Return line ``line`` (1-based) as text, or ''."""
        lines = self.data.split(b'\n')
        if 1 <= line <= len(lines):
            return lines[line - 1].decode('utf-8', 'replace')
        return ''

    def locate(self, line: int | None, needle: str | None = None,
               column: int | None = None) -> SourceLocation:
        """Return a location; find the column of ``needle`` on or after ``line``."""
        if line is not None and column is None:
            column = 1
            if needle is not None:
                for number in range(line, line + 20):
                    found = self.line_text(number).find(needle)
                    if found >= 0:
                        line, column = number, found + 1
                        break
        return SourceLocation(self.file, line, column)

    def at(self, node: Any, attribute: str | None = None) -> SourceLocation:
        """Return the location of ``node``, or of one of its attributes."""
        needle = f'{attribute}=' if attribute else f'<{node.tag}'
        line = node.sourceline
        if attribute:
            start = self.locate(line, f'<{node.tag}')
            return self.locate(start.line, needle)
        return self.locate(line, needle)


def parse_xml(data: bytes, file: str | None) -> tuple[Any, Source, list[ReadWarning]]:
    """
    Parse ``data`` and return the root element, the source and any warnings.

    :raises ParseError: on malformed XML (P001, with file:line:col) or a DOCTYPE (P008).
    """
    source = Source(file, data)
    warnings: list[ReadWarning] = []
    match = _DOCTYPE.search(data) if b'!' in data and _DECLARATIONS.search(data) else None
    if match and _BARE_DOCTYPE.match(data, match.start()) \
            and not _DOCTYPE.search(data, match.end()):
        match = None  # declares nothing: read as urdfdom reads it
    if match:
        line = data.count(b'\n', 0, match.start()) + 1
        raise ParseError('<!DOCTYPE> is not allowed in a robot description (it can declare '
                         'entities that read files or expand without bound): remove it',
                         source.locate(line, '<!DOCTYPE'), 'P008')
    stripped = data.rstrip(b'\x00')
    if len(stripped) != len(data):
        line = stripped.count(b'\n') + 1
        warnings.append(ReadWarning(source.locate(line, None, len(stripped.split(b'\n')[-1])
                                                  + 1), 'P103',
                                    'NUL byte after the document ignored (remove it)'))
        data = stripped
    try:
        return etree.fromstring(data, PARSER), source, warnings
    except etree.XMLSyntaxError as error:
        if _UNDECLARED.match(str(error.msg)):
            return _with_undeclared_prefixes(data, source, warnings)
        declaration = _DECLARATION.match(data)
        if declaration is None or not _is_declaration_error(error, data, declaration):
            raise _syntax_error(error, source) from None
    # Blank the declaration out (keeping newlines, so lines and columns stay right).
    blanked = re.sub(rb'[^\n]', b' ', declaration.group(0))
    text = declaration.group(0).decode('utf-8', 'replace').strip()
    warnings.append(ReadWarning(source.locate(1, '<?xml'), 'P102',
                                f'XML declaration {text!r} is malformed or misplaced; '
                                'ignored (write <?xml version="1.0"?> on the first line)'))
    try:
        return etree.fromstring(blanked + data[declaration.end():], PARSER), source, warnings
    except etree.XMLSyntaxError as error:
        raise _syntax_error(error, source) from None


def _with_undeclared_prefixes(data: bytes, source: Source, warnings: list[ReadWarning]
                              ) -> tuple[Any, Source, list[ReadWarning]]:
    """
    Read a file whose only fault is an undeclared prefix (``drake:acceleration="..."``).

    urdfdom, yourdfpy and MuJoCo read such files: the prefixed names are kept as written
    (``drake:member`` is an element of that literal name) and written back unchanged.
    """
    parser = etree.XMLParser(recover=True, resolve_entities=False, no_network=True,
                             load_dtd=False, huge_tree=False, collect_ids=False)
    root = etree.fromstring(data, parser)
    errors = list(parser.error_log)
    other = [entry for entry in errors if entry.type_name != 'NS_ERR_UNDEFINED_NAMESPACE']
    if other or root is None:
        first = other[0] if other else errors[0]
        raise ParseError(f'XML syntax: {first.message}',
                         SourceLocation(source.file, first.line, first.column or 1), 'P001')
    prefixes = sorted({_UNDECLARED.match(entry.message).group(1)  # type: ignore[union-attr]
                       for entry in errors})
    first = errors[0]
    warnings.append(ReadWarning(
        SourceLocation(source.file, first.line, first.column or 1), 'P105',
        f'undeclared namespace prefix(es) {", ".join(prefixes)} ({len(errors)} use(s)) kept '
        'as written; declare them on <robot> (xmlns:PREFIX="...") for strict XML tools'))
    return root, source, warnings


def _is_declaration_error(error: Any, data: bytes, declaration: Any) -> bool:
    line = error.lineno or 0
    return line <= data.count(b'\n', 0, declaration.end()) + 1


def _syntax_error(error: Any, source: Source) -> ParseError:
    message = re.sub(r', line \d+, column \d+$', '', str(error.msg))
    hint = ''
    tag = re.match(r'Opening and ending tag mismatch: (\S+) line (\d+)', message)
    if tag:
        hint = f' (check the <{tag.group(1)}> opened at line {tag.group(2)})'
    column = error.offset if error.offset else 1
    return ParseError(f'XML syntax: {message}{hint}',
                      SourceLocation(source.file, error.lineno, column), 'P001')
