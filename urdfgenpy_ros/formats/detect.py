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
import re
from typing import Any, NamedTuple

from urdfgenpy_ros.model.errors import ParseError, ReadWarning, SourceLocation

XACRO_NAMESPACES = frozenset((
    'http://www.ros.org/wiki/xacro', 'http://ros.org/wiki/xacro', 'http://wiki.ros.org/xacro',
    'https://www.ros.org/wiki/xacro', 'https://ros.org/wiki/xacro',
    'https://wiki.ros.org/xacro'))
_FOREIGN = frozenset(('gazebo', 'transmission', 'ros2_control'))
_SUBSTITUTIONS = ('${', '$(')
_DIRECTIVES = frozenset(('arg', 'attribute', 'call', 'element', 'if', 'include',
                         'insert_block', 'macro', 'property', 'unless'))
_COMMENT = re.compile(rb'<!--.*?-->', re.DOTALL)
_BINDING = re.compile(rb'xmlns(?::([^\s=]+))?\s*=\s*(?:"([^"]*)"|\'([^\']*)\')')


class XacroEvidence(NamedTuple):
    """
    What makes a file Xacro: where, and a few words saying what (``uses ${...}``).

    ``weak``: the only sign is a ``$(...)`` in a mesh's or texture's filename, in a file
    that does not declare the xacro namespace. urdfdom reads such a file (the filename
    just does not resolve), so readers warn instead of refusing it.
    """

    location: SourceLocation
    what: str
    weak: bool = False


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
    if not _may_be_xacro(data):
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
    declared = any(uri in XACRO_NAMESPACES for uri in _bindings(_uncommented(data)).values())
    weak = None
    for element in root.iter(etree.Element):  # in document order
        found = _sign(element, declared)
        if found is not None:
            token, what = found
            line = element.sourceline
            column = None
            if line is not None and 0 < line <= len(lines):
                index = lines[line - 1].decode('utf-8', 'replace').find(token)
                column = index + 1 if index >= 0 else None
            evidence = XacroEvidence(SourceLocation(file, line, column), what,
                                     _is_weak(element, token, declared))
            if not evidence.weak:
                return evidence
            weak = weak or evidence
    return weak


def _is_weak(element: Any, attribute: str, declared: bool) -> bool:
    """Return whether the sign is only a ``$(...)`` in a mesh's or texture's filename."""
    value = element.get(attribute) if attribute == 'filename' else None
    return (not declared and value is not None and _local(element.tag) in ('mesh', 'texture')
            and '${' not in value)


def _may_be_xacro(data: bytes) -> bool:
    """
    Return False when ``data`` certainly shows no sign of Xacro (True: look closer).

    Without ``${``/``$(`` the only signs are elements and attributes in the xacro namespace
    (or with an undeclared ``xacro:`` prefix): each is written with a prefix bound to it,
    right after ``<`` or white space. Most URDF files that mention xacro (a "generated by
    xacro" comment, an unused ``xmlns:xacro``) are decided here without parsing them.
    """
    if b'$' not in data and b'xacro' not in data:  # most files: two quick scans decide
        return False  # (without a '$' or the name, no sign can be in the file at all)
    data = _uncommented(data)  # what comments say is no sign
    if b'${' in data or b'$(' in data:
        return True
    if b'xacro' not in data:
        return False
    prefixes = {b'xacro'}
    for prefix, uri in _bindings(data).items():
        if uri in XACRO_NAMESPACES:
            if not prefix:
                return True  # the default namespace is xacro's
            prefixes.add(prefix.encode())
    return any(re.search(rb'[<\s]' + re.escape(prefix) + rb':', data) for prefix in prefixes)


def _uncommented(data: bytes) -> bytes:
    return _COMMENT.sub(b'', data) if b'<!--' in data else data


def _bindings(data: bytes) -> dict[str, str]:
    """Return the namespace URIs the document binds, by prefix ('' for a default one)."""
    return {prefix.decode('utf-8', 'replace'): (double or single).decode('utf-8', 'replace')
            for prefix, double, single in _BINDING.findall(data)}


def _local(tag: str) -> str:
    return tag.rsplit('}', 1)[-1].rsplit(':', 1)[-1]


def _sign(element: Any, declared: bool) -> tuple[str, str] | None:
    """
    Return ``(text to point at, description)`` when ``element`` shows Xacro.

    ``declared``: the document declares the xacro namespace (then substitutions inside
    ``<gazebo>``, ``<transmission>`` and ``<ros2_control>`` count too).
    """
    tag = element.tag
    if ':' in tag or '}' in tag:
        in_xacro = tag.startswith('xacro:') or (
            tag.startswith('{') and tag[1:].split('}', 1)[0] in XACRO_NAMESPACES)
        if in_xacro and _local(tag) in _DIRECTIVES:
            return f'<{element.prefix or "xacro"}:', f'it has <xacro:{_local(tag)}> elements'
    for name, value in element.attrib.items():
        if name.startswith('{') and name[1:].split('}', 1)[0] in XACRO_NAMESPACES:
            return _local(name), f'it has xacro:{_local(name)} attributes'
        if '$' in value and any(mark in value for mark in _SUBSTITUTIONS) and (
                declared or not _in_foreign_block(element)):
            return name, f'<{_local(tag)} {name}> uses {_kind(value)} substitutions'
    text = element.text
    if text and '$' in text and any(mark in text for mark in _SUBSTITUTIONS) and (
            declared or not _in_foreign_block(element)):
        return '$', f'<{_local(tag)}> text uses {_kind(text)} substitutions'
    return None


def _in_foreign_block(element: Any) -> bool:
    """Return whether ``element`` is inside a gazebo, transmission or ros2_control block."""
    return any(_local(outer.tag) in _FOREIGN for outer in element.iterancestors())


def _kind(value: str) -> str:
    return '${...}' if '${' in value else '$(...)'


def is_xacro(path: str | PathLike[str]) -> bool:
    """Return whether the file ``path`` is Xacro (whatever its suffix)."""
    return xacro_evidence(path) is not None


def weak_evidence_warning(evidence: XacroEvidence) -> ReadWarning:
    """Return the warning (X104) of a URDF read as it is though a filename needs xacro."""
    return ReadWarning(evidence.location, 'X104', (
        f'{evidence.what}: read as URDF, as urdfdom reads it, but the filename resolves '
        'only once xacro expands it (Robot.from_xacro, or name the file .urdf.xacro)'))


def refuse_xacro(data: bytes, file: str) -> ReadWarning | None:
    """
    Raise ParseError (X002) when the document ``data`` (of ``file``) is Xacro.

    Weak evidence (see :class:`XacroEvidence`) is returned as a warning instead.

    :raises ParseError: one line: where, what makes it Xacro, what to call instead
        (``Robot.from_xacro``).
    """
    evidence = xacro_evidence_in(data, file)
    if evidence is not None and evidence.weak:
        return weak_evidence_warning(evidence)
    if evidence is not None:
        raise ParseError(f'this file is Xacro ({evidence.what}): read it with '
                         'Robot.from_xacro(path, mappings), not Robot.from_urdf',
                         evidence.location, 'X002')
    return None
