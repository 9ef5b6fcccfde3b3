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
Tell Xacro from URDF by content, whatever the file's suffix.

A file is Xacro when it has xacro's elements (``<xacro:arg>``, ``<xacro:property>``,
``<xacro:include>``, ``<xacro:macro>``, ...) or attributes, or uses ``${...}`` /
``$(...)`` substitutions. ROS launch files run xacro on any description file, so
TurtleBot3's ``.urdf`` files are Xacro, and so is every file like them. Substitutions in
``<gazebo>``, ``<transmission>`` and ``<ros2_control>`` blocks count only when the file
declares the xacro namespace (without it, their text belongs to the tools that read those
blocks). A file that only declares the namespace (as many xacro outputs do) is plain URDF:
xacro would give the same model, and reading it directly keeps its line numbers. So is a
file whose only xacro elements are calls of macros it never defines (urdf's own
``pr2_desc.urdf`` test file): xacro could not expand it, URDF readers skip them.
"""

from __future__ import annotations

from os import PathLike
from pathlib import Path
from typing import Any, NamedTuple

from urdfgenpy_ros.errors import ParseError, SourceLocation

XACRO_NAMESPACES = frozenset((
    'http://www.ros.org/wiki/xacro', 'http://ros.org/wiki/xacro', 'http://wiki.ros.org/xacro',
    'https://www.ros.org/wiki/xacro', 'https://ros.org/wiki/xacro',
    'https://wiki.ros.org/xacro'))
_FOREIGN = frozenset(('gazebo', 'transmission', 'ros2_control'))
_SUBSTITUTIONS = ('${', '$(')
_DIRECTIVES = frozenset(('arg', 'attribute', 'call', 'element', 'if', 'include',
                         'insert_block', 'macro', 'property', 'unless'))


class XacroEvidence(NamedTuple):
    """What makes a file Xacro: where, and a few words saying what (``uses ${...}``)."""

    location: SourceLocation
    what: str


def xacro_evidence(path: str | PathLike[str]) -> XacroEvidence | None:
    """
    Return the first sign that the file ``path`` is Xacro, or None for plain URDF.

    Files that cannot be read or parsed return None: the URDF reader reports them.
    """
    try:
        data = Path(path).read_bytes()
    except OSError:
        return None
    return xacro_evidence_in(data, str(path))


def xacro_evidence_in(data: bytes, file: str | None = None) -> XacroEvidence | None:
    """Return the first sign that the document ``data`` is Xacro, or None."""
    if b'xacro' not in data and b'${' not in data and b'$(' not in data:
        return None  # the common case, decided without parsing
    from lxml import etree
    parser = etree.XMLParser(huge_tree=True, resolve_entities=False, no_network=True,
                             recover=True)
    try:
        root = etree.fromstring(data, parser)
    except (etree.XMLSyntaxError, ValueError):
        return None
    if root is None:
        return None
    lines = data.split(b'\n')
    declared = any(uri in XACRO_NAMESPACES for element in root.iter()
                   if isinstance(element.tag, str) for uri in element.nsmap.values())
    for element, foreign in _elements(root):
        found = _sign(element, foreign and not declared)
        if found is not None:
            token, what = found
            line = element.sourceline
            column = None
            if line is not None and 0 < line <= len(lines):
                index = lines[line - 1].decode('utf-8', 'replace').find(token)
                column = index + 1 if index >= 0 else None
            return XacroEvidence(SourceLocation(file, line, column), what)
    return None


def _elements(root: Any) -> Any:
    """Yield ``(element, inside a foreign block)`` for every element, in document order."""
    stack = [(root, False)]
    while stack:
        element, foreign = stack.pop()
        if not isinstance(element.tag, str):
            continue
        yield element, foreign
        inner = foreign or _local(element.tag) in _FOREIGN
        stack.extend((child, inner) for child in reversed(element))


def _local(tag: str) -> str:
    return tag.rsplit('}', 1)[-1].rsplit(':', 1)[-1]


def _sign(element: Any, foreign: bool) -> tuple[str, str] | None:
    """Return ``(text to point at, description)`` when ``element`` shows Xacro."""
    tag = element.tag
    in_xacro = tag.startswith('xacro:') or (
        tag.startswith('{') and tag[1:].split('}', 1)[0] in XACRO_NAMESPACES)
    if in_xacro and _local(tag) in _DIRECTIVES:
        return f'<{element.prefix or "xacro"}:', f'it has <xacro:{_local(tag)}> elements'
    for name, value in element.attrib.items():
        if name.startswith('{') and name[1:].split('}', 1)[0] in XACRO_NAMESPACES:
            return _local(name), f'it has xacro:{_local(name)} attributes'
        if not foreign and any(mark in value for mark in _SUBSTITUTIONS):
            return name, f'<{_local(tag)} {name}> uses {_kind(value)} substitutions'
    if not foreign and element.text and any(mark in element.text for mark in _SUBSTITUTIONS):
        return '$', f'<{_local(tag)}> text uses {_kind(element.text)} substitutions'
    return None


def _kind(value: str) -> str:
    return '${...}' if '${' in value else '$(...)'


def is_xacro(path: str | PathLike[str]) -> bool:
    """Return whether the file ``path`` is Xacro (whatever its suffix)."""
    return xacro_evidence(path) is not None


def refuse_xacro(path: str | PathLike[str]) -> None:
    """
    Raise ParseError (X002) when the file ``path`` is Xacro, naming ``Robot.from_xacro``.

    :raises ParseError: one line: where, what makes it Xacro, what to call instead.
    """
    evidence = xacro_evidence(path)
    if evidence is not None:
        raise ParseError(f'this file is Xacro ({evidence.what}): read it with '
                         'Robot.from_xacro(path, mappings), not Robot.from_urdf',
                         evidence.location, 'X002')
