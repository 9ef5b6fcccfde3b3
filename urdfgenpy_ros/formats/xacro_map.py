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
A source map of the real xacro's expansion: where each element of the result was written.

xacro parses with ``xml.dom.minidom``, whose nodes carry no line. While one expansion runs
(under ``xacro_read``'s lock), xacro's ``parse`` builds its documents with an expat builder
that notes expat's position at each start tag; the elements it makes are ``_Placed``, a
minidom ``Element`` whose ``cloneNode`` carries the places over to the copy, so macro bodies
and blocks keep them. Wrapping xacro's ``handle_macro_call`` and ``process_include`` records
the call or include site that brought each copy there, and ``grab_property`` where each
property is written. xacro's own code does every expansion step; nothing here changes what
it makes, so the text is byte for byte the text xacro prints.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
import os
from typing import Any, NamedTuple
from xml.dom import expatbuilder, minidom, Node

from lxml import etree

from urdfgenpy_ros.errors import SourceLocation


class Origin(NamedTuple):
    """Where an element was written, and the call and include sites that brought it."""

    where: SourceLocation
    via: tuple[SourceLocation, ...] = ()  # innermost first: macro calls and includes


class XacroMap(NamedTuple):
    """A map from the lines of an expansion to the source of the element on each."""

    lines: dict[int, Origin]
    properties: dict[str, list[SourceLocation]]  # name as written -> its definitions
    children: dict[int, list[tuple[str, int]]]  # line -> (tag, line) of each child element

    tags: dict[int, str]  # line -> the tag of the element on it

    def line_of(self, line: int, steps: list[tuple[str, int]]) -> int:
        """
        Return the line of the element ``steps`` (tag, 1-based index) name below an owner.

        ``line`` is the owner's, or of an element on the way (the steps after its tag).
        """
        here = [number for number, (tag, _) in enumerate(steps) if tag == self.tags.get(line)]
        for tag, index in steps[here[-1] + 1:] if here else steps:
            below = [row for name, row in self.children.get(line, ()) if name == tag]
            if len(below) < index:
                break
            line = below[index - 1]
        return line


class _Recorder:
    """The places of one expansion's elements, by ``id()`` (each node is kept alive)."""

    def __init__(self) -> None:
        self.origins: dict[int, tuple[Any, Origin]] = {}
        self.calls: list[list[Any]] = []  # [call site's via, body copied yet]
        self.included: list[tuple[SourceLocation, ...]] = []
        self.properties: dict[str, list[SourceLocation]] = {}

    def origin(self, node: Any) -> Origin | None:
        found = self.origins.get(id(node))
        return found[1] if found is not None and found[0] is node else None

    def site(self, node: Any, label: str) -> tuple[SourceLocation, ...]:
        """Return the chain of an element that calls or includes: itself, then its own."""
        origin = self.origin(node)
        if origin is None:
            return ()
        return (origin.where._replace(path=label), *origin.via)

    def cloned(self, original: Any, clone: Any) -> None:
        via = None
        if original.tagName == 'xacro:macro' and self.calls and not self.calls[-1][1]:
            self.calls[-1][1] = True  # the body xacro copies for this call
            via = self.calls[-1][0]
        pairs = [(original, clone)]
        origins = self.origins
        while pairs:
            one, copy = pairs.pop()
            if one.nodeType != Node.ELEMENT_NODE:
                continue
            origin = self.origin(one)
            if origin is not None:
                copy.__class__ = _Placed
                origins[id(copy)] = (copy, origin if via is None else origin._replace(via=via))
            pairs.extend(zip(one.childNodes, copy.childNodes))


_ACTIVE: list[_Recorder] = []


class _Placed(minidom.Element):
    """A minidom element whose copies keep the place it was written at."""

    __slots__ = ()

    def cloneNode(self, deep: bool) -> Any:  # noqa: N802 - minidom's name
        """Return xacro's copy, with the places of this element and its children."""
        clone = super().cloneNode(deep)
        if _ACTIVE:
            _ACTIVE[-1].cloned(self, clone)
        return clone


class _Builder(expatbuilder.ExpatBuilderNS):
    """minidom's builder, noting expat's position at each start tag."""

    def __init__(self, file: str, via: tuple[SourceLocation, ...], recorder: _Recorder):
        super().__init__()
        self._file, self._via, self._recorder = file, via, recorder

    def start_element_handler(self, name: str, attributes: Any) -> None:
        parser = self._parser
        line, column = parser.CurrentLineNumber, parser.CurrentColumnNumber + 1
        super().start_element_handler(name, attributes)
        node = self.curNode
        node.__class__ = _Placed
        self._recorder.origins[id(node)] = (
            node, Origin(SourceLocation(self._file, line, column), self._via))


@contextmanager
def recording(xacro: Any) -> Iterator[_Recorder]:
    """Record the places of the elements of the expansions run inside (hold the lock)."""
    recorder = _Recorder()
    saved = {name: getattr(xacro, name)
             for name in ('parse', 'handle_macro_call', 'process_include', 'grab_property')}

    def parse(inp: Any, filename: str | None = None) -> Any:
        if inp is not None:
            return saved['parse'](inp, filename)
        try:
            opened = open(os.path.join(xacro.root_dir, filename))  # as xacro.parse opens it
        except OSError:
            return saved['parse'](inp, filename)  # xacro raises its own error
        via = recorder.included[-1] if recorder.included else ()
        with opened:
            return _Builder(str(filename), via, recorder).parseFile(opened)

    def handle_macro_call(node: Any, macros: Any, symbols: Any) -> Any:
        recorder.calls.append([recorder.site(node, f'<{node.tagName}>'), False])
        try:
            return saved['handle_macro_call'](node, macros, symbols)
        finally:
            recorder.calls.pop()

    def process_include(elt: Any, macros: Any, symbols: Any, func: Any) -> Any:
        recorder.included.append(recorder.site(elt, '<xacro:include>'))
        try:
            return saved['process_include'](elt, macros, symbols, func)
        finally:
            recorder.included.pop()

    def grab_property(elt: Any, table: Any) -> Any:
        origin = recorder.origin(elt)
        if origin is not None:
            name = elt.getAttribute('name')
            recorder.properties.setdefault(name, []).append(
                origin.where._replace(path=f"<xacro:property name='{name}'>"))
        return saved['grab_property'](elt, table)

    for name, function in (('parse', parse), ('handle_macro_call', handle_macro_call),
                           ('process_include', process_include),
                           ('grab_property', grab_property)):
        setattr(xacro, name, function)
    _ACTIVE.append(recorder)
    try:
        yield recorder
    finally:
        _ACTIVE.pop()
        for name, function in saved.items():
            setattr(xacro, name, function)


def source_map(recorder: _Recorder, document: Any, text: str) -> XacroMap:
    """Return the map of ``text``, xacro's pretty print of ``document``, to the sources."""
    lines: dict[int, Origin] = {}
    children: dict[int, list[tuple[str, int]]] = {}
    tags: dict[int, str] = {}
    root = etree.fromstring(text.encode('utf-8'), etree.XMLParser(
        resolve_entities=False, huge_tree=True, remove_comments=True, remove_pis=True))
    printed = root.iter(etree.Element)
    for node in _elements(document.documentElement):
        element = next(printed, None)
        if element is None:
            break
        line = element.sourceline
        origin = recorder.origin(node)
        if origin is not None and line is not None:
            lines[line] = origin
            tag = tags[line] = etree.QName(element).localname
            parent = element.getparent()
            if parent is not None and parent.sourceline is not None:
                children.setdefault(parent.sourceline, []).append((tag, line))
    return XacroMap(lines, recorder.properties, children, tags)


def _elements(node: Any) -> Iterator[Any]:
    """Yield the elements under ``node`` (itself first) in document order."""
    stack = [node]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(child for child in reversed(node.childNodes)
                     if child.nodeType == Node.ELEMENT_NODE)
