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

from collections.abc import Iterator, Mapping
from contextlib import contextmanager
import os
from pathlib import Path
from typing import Any, NamedTuple
from xml.dom import expatbuilder, minidom, Node

from lxml import etree

from urdfgenpy_ros.model.errors import SourceLocation


class Origin(NamedTuple):
    """Where an element was written, and the call and include sites that brought it."""

    where: SourceLocation
    via: tuple[SourceLocation, ...] = ()  # innermost first: macro calls and includes


_Raw = tuple[str, int, int, tuple[SourceLocation, ...]]  # file, line, column, via


class XacroMap:
    """A map from the lines of an expansion to the source of the element on each."""

    def __init__(self, lines: dict[int, _Raw], properties: dict[str, list[SourceLocation]],
                 text: str) -> None:
        self.raw = lines
        self.properties = properties  # name as written -> its definitions
        self.text = text  # the expansion
        self._tree: tuple[dict[int, str], dict[int, list[tuple[str, int]]]] | None = None

    @property
    def lines(self) -> dict[int, Origin]:
        """Return every line's origin (a new dict: for tests and tools, not the hot path)."""
        return {line: self.at(line) for line in self.raw}  # type: ignore[misc]

    def at(self, line: int) -> Origin | None:
        """Return the origin of the element whose start tag is on ``line``, or None."""
        raw = self.raw.get(line)
        if raw is None:
            return None
        return Origin(SourceLocation(raw[0], raw[1], raw[2]), raw[3])

    @property
    def tags(self) -> dict[int, str]:
        """Return the tag of the element on each line of the expansion."""
        return self._index()[0]

    @property
    def children(self) -> dict[int, list[tuple[str, int]]]:
        """Return (tag, line) of each child element of the element on each line."""
        return self._index()[1]

    def _index(self) -> tuple[dict[int, str], dict[int, list[tuple[str, int]]]]:
        """Read the expansion's tree once, when a finding first needs it."""
        if self._tree is None:
            tags: dict[int, str] = {}
            children: dict[int, list[tuple[str, int]]] = {}
            root = etree.fromstring(self.text.encode('utf-8'), etree.XMLParser(
                resolve_entities=False, huge_tree=True))
            for element in root.iter(etree.Element):
                line = element.sourceline
                if line is None:
                    continue
                tag = tags[line] = etree.QName(element).localname
                parent = element.getparent()
                if parent is not None and parent.sourceline is not None:
                    children.setdefault(parent.sourceline, []).append((tag, line))
            self._tree = tags, children
        return self._tree

    def line_of(self, line: int, steps: list[tuple[str, int]]) -> int:
        """
        Return the line of the element ``steps`` (tag, 1-based index or 0) name below an owner.

        ``line`` is the owner's, or of an element on the way (the steps after its tag).
        """
        here = [number for number, (tag, _) in enumerate(steps) if tag == self.tags.get(line)]
        for tag, index in steps[here[-1] + 1:] if here else steps:
            below = [row for name, row in self.children.get(line, ()) if name == tag]
            if not 0 < index <= len(below):  # not there, or chosen by a name: stop here
                break
            line = below[index - 1]
        return line


class _Recorder:
    """The places of one expansion's elements, by ``id()`` (each node is kept alive)."""

    def __init__(self) -> None:
        self.origins: dict[int, tuple[Any, str, int, int, tuple[SourceLocation, ...]]] = {}
        self.calls: list[list[Any]] = []  # [call site's via, body copied yet]
        self.included: list[tuple[SourceLocation, ...]] = []
        self.properties: dict[str, list[SourceLocation]] = {}
        self.written: list[tuple[int, Any]] = []  # offset of each start tag printed
        self.orders: dict[int, tuple[Any, list[Any]]] = {}
        self.made: list[Any] | None = None  # the elements a copy is making, in order

    def place(self, node: Any, label: str) -> SourceLocation | None:
        found = self.origins.get(id(node))
        if found is None or found[0] is not node:
            return None
        return SourceLocation(found[1], found[2], found[3], label)

    def site(self, node: Any, label: str) -> tuple[SourceLocation, ...]:
        """Return the chain of an element that calls or includes: itself, then its own."""
        found = self.origins.get(id(node))
        if found is None or found[0] is not node:
            return ()
        return (SourceLocation(found[1], found[2], found[3], label), *found[4])

    def cloned(self, original: Any, made: list[Any]) -> None:
        """Give the elements ``made`` (in document order) the places of ``original``'s."""
        via = None
        if original.tagName == 'xacro:macro' and self.calls and not self.calls[-1][1]:
            self.calls[-1][1] = True  # the body xacro copies for this call
            via = self.calls[-1][0]
        origins = self.origins
        for one, copy in zip(self._in_order(original), made):
            found = origins.get(id(one))
            if found is not None and found[0] is one:
                copy.__class__ = _Placed
                origins[id(copy)] = (copy, *found[1:4], found[4] if via is None else via)

    def _in_order(self, node: Any) -> list[Any]:
        """Return the elements under ``node`` (itself first) in document order, cached."""
        cached = self.orders.get(id(node))
        if cached is not None and cached[0] is node:
            return cached[1]
        found, stack = [], [node]
        while stack:
            one = stack.pop()
            found.append(one)
            stack.extend(child for child in reversed(one.childNodes)
                         if child.nodeType == Node.ELEMENT_NODE)
        self.orders[id(node)] = (node, found)  # a body or block: xacro copies, never edits
        return found


_ACTIVE: list[_Recorder] = []


class _Placed(minidom.Element):
    """A minidom element whose copies keep the place it was written at."""

    __slots__ = ()

    def cloneNode(self, deep: bool) -> Any:  # noqa: N802 - minidom's name
        """Return xacro's copy, with the places of this element and its children."""
        if not _ACTIVE or not deep:
            return super().cloneNode(deep)
        recorder = _ACTIVE[-1]
        outer, recorder.made = recorder.made, []
        try:
            clone = super().cloneNode(deep)
            recorder.cloned(self, recorder.made)
        finally:
            recorder.made = outer
        return clone

    def writexml(self, writer: Any, indent: str = '', addindent: str = '',
                 newl: str = '') -> None:
        """Print as xacro prints (its ``fixed_writexml``), noting where the tag starts."""
        if _ACTIVE:
            _ACTIVE[-1].written.append((writer.tell() + len(indent), self))
        super().writexml(writer, indent, addindent, newl)


class _Document(minidom.Document):
    """A minidom document that tells a copy in progress the elements it makes."""

    __slots__ = ()

    def createElementNS(self, namespaceURI: str | None,  # noqa: N802, N803 - minidom's
                        qualifiedName: str) -> Any:  # noqa: N803
        """Return minidom's new element, noted when a copy is being made."""
        element = super().createElementNS(namespaceURI, qualifiedName)
        if _ACTIVE and _ACTIVE[-1].made is not None:
            _ACTIVE[-1].made.append(element)
        return element


_START = expatbuilder.Namespaces.start_element_handler


class _Builder(expatbuilder.ExpatBuilderNS):
    """minidom's builder, noting expat's position at each start tag."""

    _parser: Any
    curNode: Any
    document: Any

    def __init__(self, file: str, via: tuple[SourceLocation, ...], recorder: _Recorder):
        super().__init__()
        self._file, self._via, self._origins = file, via, recorder.origins

    def reset(self) -> None:
        """Start a document, one whose copies are noted."""
        super().reset()
        self.document.__class__ = _Document

    def start_element_handler(self, name: str, attributes: Any) -> None:
        parser = self._parser
        line, column = parser.CurrentLineNumber, parser.CurrentColumnNumber + 1
        _START(self, name, attributes)
        node = self.curNode
        node.__class__ = _Placed
        self._origins[id(node)] = (node, self._file, line, column, self._via)


@contextmanager
def recording(xacro: Any, texts: Mapping[str, str] | None = None) -> Iterator[_Recorder]:
    """
    Record the places of the elements of the expansions run inside (hold the lock).

    ``texts`` (absolute path: text) are read instead of those files: an edit tried first.
    """
    recorder = _Recorder()
    texts = texts or {}
    saved = {name: getattr(xacro, name)
             for name in ('parse', 'handle_macro_call', 'process_include', 'grab_property')}

    def parse(inp: Any, filename: str | None = None) -> Any:
        if inp is not None:
            return saved['parse'](inp, filename)
        try:
            opened = open(os.path.join(xacro.root_dir, str(filename)))  # as xacro.parse does
        except OSError:
            return saved['parse'](inp, filename)  # xacro raises its own error
        via = recorder.included[-1] if recorder.included else ()
        with opened:
            builder = _Builder(str(filename), via, recorder)
            instead = texts.get(str(Path(opened.name).resolve())) if texts else None
            return builder.parseString(instead) if instead is not None else \
                builder.parseFile(opened)

    def handle_macro_call(node: Any, macros: Any, symbols: Any) -> Any:
        if not node.tagName.startswith('xacro:'):
            return False  # not a call: as xacro's own first test answers
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
        name = elt.getAttribute('name')
        place = recorder.place(elt, f"<xacro:property name='{name}'>")
        if place is not None:
            recorder.properties.setdefault(name, []).append(place)
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


def pretty_print(recorder: _Recorder, document: Any) -> tuple[str, XacroMap]:
    """Return xacro's pretty print of ``document`` and its map (inside ``recording``)."""
    recorder.written = []
    text = document.toprettyxml(indent='  ')
    lines: dict[int, _Raw] = {}
    origins = recorder.origins
    line, last = 1, 0
    for offset, node in recorder.written:
        line += text.count('\n', last, offset)
        last = offset
        found = origins.get(id(node))
        if found is not None and found[0] is node:
            lines[line] = found[1:]
    return text, XacroMap(lines, recorder.properties, text)
