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
Where each node of an XML document stands in its source text.

lxml gives no offsets, so a small scanner reads the text once: every start tag, end tag,
comment and processing instruction, nested as the text nests them. The spans are then
paired with lxml's nodes in document order, parent by parent: a parent whose children
are no longer those of the text (one added or removed since it was read) keeps its own
span, and its children get none. CDATA sections, character and entity references are
text to the scanner; the document type declaration is refused before this is used.
"""

from __future__ import annotations

import html
import re
from typing import Any

from lxml import etree

# One token of markup. Everything between tokens is text (or CDATA, matched so that a
# '<' inside it is no tag).
_TOKEN = re.compile(
    r'<(?:(!--.*?-->)|(!\[CDATA\[.*?\]\]>)|(\?.*?\?>)|(![^>]*>)|/([^\s>]+)\s*>|'
    r'([^\s<>/!?]+)(?:\s+[^\s=<>/]+\s*=\s*(?:"[^"]*"|\'[^\']*\'))*\s*(/?)>)', re.DOTALL)
_XML_DECLARATION = re.compile(r'\?xml\s', re.IGNORECASE)

# One attribute of a start tag: the white space and name before it, its quote, its value.
ATTRIBUTE = re.compile(r'(\s+)([^\s=<>/]+)(\s*=\s*)(["\'])(.*?)\4', re.DOTALL)

ELEMENT, COMMENT, PI = 'element', 'comment', 'pi'


class Span:
    """One node of the source: ``text[start:end]``; an element's start tag ends at ``head``."""

    __slots__ = ('kind', 'name', 'start', 'head', 'end', 'children')

    def __init__(self, kind: str, name: str, start: int, head: int) -> None:
        self.kind = kind
        self.name = name
        self.start = start
        self.head = head  # just after the start tag's '>'
        self.end = head  # just after the end tag's '>' (or the '/>')
        self.children: list[Span] | None = []  # None: not scanned yet

    @property
    def empty(self) -> bool:
        """Return whether the element is written ``<x/>`` (not ``<x></x>``)."""
        return self.end == self.head

    def __repr__(self) -> str:
        """Return the node's kind, name and place."""
        return f'Span({self.kind} {self.name!r} {self.start}:{self.end})'


def scan(text: str, start: int = 0, end: int | None = None) -> tuple[list[Span], int]:
    """
    Return the nodes of ``text[start:end]`` (elements, comments, PIs), nested, with spans.

    The scan stops after an end tag that closes no node of the region (its parent's):
    also returned is where it stopped.
    """
    top: list[Span] = []
    stack: list[Span] = []
    stop = len(text) if end is None else end
    for match in _TOKEN.finditer(text, start, stop):
        siblings = stack[-1].children if stack else top
        assert siblings is not None
        if match.group(6) is not None:
            span = Span(ELEMENT, match.group(6), match.start(), match.end())
            siblings.append(span)
            if not match.group(7):
                stack.append(span)
        elif match.group(5) is not None:
            if not stack:
                return top, match.end()
            stack.pop().end = match.end()
        elif match.group(1) is not None:
            siblings.append(_leaf(COMMENT, match))
        elif match.group(3) is not None and not _XML_DECLARATION.match(match.group(3)):
            siblings.append(_leaf(PI, match))
    return top, stop


def shallow(text: str, start: int, end: int, last: bool = False) -> list[Span]:
    """
    Return the nodes of ``text[start:end]``, their children left to be scanned when asked.

    An element's end is its first end tag of that name unless a comment, CDATA, PI or an
    element of the same name comes before it, when the element is scanned through.
    ``last``: the document's level, where an element's end is the last such end tag.
    """
    found: list[Span] = []
    position = start
    search = _TOKEN.search
    while True:
        match = search(text, position, end)
        if match is None:
            return found
        name = match.group(6)
        if name is not None:
            span = Span(ELEMENT, name, match.start(), match.end())
            if not match.group(7):
                close = _close(text, name, span.head, end, last)
                if close is None:
                    span.children, span.end = scan(text, span.head, end)
                else:
                    span.children, span.end = None, close
            found.append(span)
            position = span.end
            continue
        if match.group(5) is not None:
            return found  # the end of the region's parent
        if match.group(1) is not None:
            found.append(_leaf(COMMENT, match))
        elif match.group(3) is not None and not _XML_DECLARATION.match(match.group(3)):
            found.append(_leaf(PI, match))
        position = match.end()


_AFTER_NAME = ' \t\r\n/>'
_CLOSERS: dict[str, re.Pattern[str]] = {}  # per element name (a bounded table of regexes)


def _closer(name: str) -> re.Pattern[str]:
    """Return the regex finding the first end tag of ``name``, opening of it, or ``<!``/``<?``."""
    pattern = _CLOSERS.get(name)
    if pattern is None:
        if len(_CLOSERS) > 256:
            _CLOSERS.clear()
        quoted = re.escape(name)
        pattern = _CLOSERS[name] = re.compile(rf'</{quoted}\s*>|<{quoted}[\s/>]|<[!?]')
    return pattern


def _close(text: str, name: str, head: int, end: int, last: bool) -> int | None:
    """Return the end of the element whose start tag ends at ``head``, if simply found."""
    if not last:
        match = _closer(name).search(text, head, end)
        return match.end() if match is not None and match.group()[1] == '/' else None
    closing = '</' + name
    found = text.rfind(closing, head, end)
    if found < 0:
        return None
    opening = '<' + name
    nested = text.find(opening, head, found)
    while nested >= 0:
        if text[nested + len(opening):nested + len(opening) + 1] in _AFTER_NAME:
            return None
        nested = text.find(opening, nested + 1, found)
    closed = text.find('>', found, end)
    return None if closed < 0 else closed + 1


def children(text: str, span: Span) -> list[Span]:
    """Return the children of an element's span, scanning them on first use."""
    if span.children is None:
        span.children = shallow(text, span.head, span.end)
    return span.children


def _leaf(kind: str, match: Any) -> Span:
    return Span(kind, '', match.start(), match.end())


def _local(name: str) -> str:
    return name.rsplit('}', 1)[-1].rsplit(':', 1)[-1]


def _fits(span: Span, node: Any) -> bool:
    tag = node.tag
    if isinstance(tag, str):
        return span.kind == ELEMENT and (span.name == tag or _local(span.name) == _local(tag))
    if tag is etree.Comment:
        return span.kind == COMMENT
    return span.kind == PI and tag is etree.PI


class Spans:
    """
    The span of each node of a document, found level by level as the writer asks.

    Nodes added since the text was read have none. Where a parent's children changed in
    number, the others are paired by their order, names and attribute values: those (and
    what is in them) are ``loose``, their span possibly another's of the same name.
    """

    def __init__(self, text: str, top: Any, found: list[Span] | None = None) -> None:
        """Pair ``top`` and its siblings with the text's top level (``found``, if scanned)."""
        self.text = text
        self.known: dict[Any, Span] = {}
        self.loose: set[Any] = set()
        self.expanded: set[Any] = set()  # the nodes whose children were paired
        nodes = [*reversed(list(top.itersiblings(preceding=True))), top, *top.itersiblings()]
        if found is None:
            found = shallow(text, 0, len(text), last=True)
        if len(found) != len(nodes):  # a copy of the tree has no siblings: its element only
            found = [span for span in found if span.kind == ELEMENT][:1]
            nodes = [top]
        self._pair(found, nodes, False)

    def get(self, node: Any) -> Span | None:
        """Return the span of ``node``, or None."""
        span = self.known.get(node)
        if span is not None:
            return span
        parent = node.getparent()
        if parent is None or parent in self.expanded:
            return None
        outer = self.get(parent)
        self.expanded.add(parent)
        if outer is None or outer.kind != ELEMENT:
            return None
        self._pair(children(self.text, outer), list(parent), parent in self.loose)
        return self.known.get(node)

    def _pair(self, found: list[Span], nodes: list[Any], moved: bool) -> None:
        if len(found) == len(nodes) and all(_fits(span, node)
                                            for span, node in zip(found, nodes)):
            pairs = list(zip(found, nodes))
        else:
            from difflib import SequenceMatcher  # only for an edited file (start-up)
            moved = True
            matcher = SequenceMatcher(None, [_key(self.text, span) for span in found],
                                      [_node_key(node) for node in nodes], autojunk=False)
            pairs = [(found[block.a + k], nodes[block.b + k])
                     for block in matcher.get_matching_blocks() for k in range(block.size)]
        known = self.known
        for span, node in pairs:
            known[node] = span
        if moved:
            self.loose.update(node for _, node in pairs)


def _key(text: str, span: Span) -> str:
    """Return a span's kind, name and attribute values, to align it with a node."""
    if span.kind != ELEMENT:
        return span.kind
    values = [attribute_value(match.group(5)) for match in attributes(text, span)
              if not match.group(2).startswith('xmlns')]
    return ' '.join([ELEMENT, _local(span.name), *values])


def _node_key(node: Any) -> str:
    tag = node.tag
    if isinstance(tag, str):
        return ' '.join([ELEMENT, _local(tag), *node.attrib.values()])
    return COMMENT if tag is etree.Comment else PI


# ---- what the text says ----------------------------------------------------------------

def attributes(text: str, span: Span) -> list[Any]:
    """Return the attribute matches (see :data:`ATTRIBUTE`) of an element's start tag."""
    return list(ATTRIBUTE.finditer(text, span.start + 1 + len(span.name), span.head))


def attribute_value(source: str) -> str:
    """Return an attribute's value as XML reads the source text of it."""
    if '\r' in source:
        source = source.replace('\r\n', ' ').replace('\r', ' ')
    if '\n' in source or '\t' in source:
        source = source.replace('\n', ' ').replace('\t', ' ')
    return html.unescape(source) if '&' in source else source


def text_value(source: str) -> str | None:
    """Return the text XML reads from the source text between two tags (None if empty)."""
    if not source:
        return None
    if '<![CDATA[' in source:
        parts = re.split(r'<!\[CDATA\[(.*?)\]\]>', source, flags=re.DOTALL)
        return ''.join(part if index % 2 else _plain(part) for index, part in enumerate(parts))
    return _plain(source)


def _plain(source: str) -> str:
    if '\r' in source:
        source = source.replace('\r\n', '\n').replace('\r', '\n')
    return html.unescape(source) if '&' in source else source


def same_attributes(text: str, span: Span, node: Any) -> bool:
    """Return whether ``node`` has the attributes its start tag gives, in that order."""
    found = [match for match in attributes(text, span)
             if not (match.group(2) == 'xmlns' or match.group(2).startswith('xmlns:'))]
    items = node.attrib.items()
    if len(found) != len(items):
        return False
    for match, (name, value) in zip(found, items):
        if _local(match.group(2)) != _local(name) or \
                attribute_value(match.group(5)) != value:
            return False
    return True


def gaps(text: str, span: Span) -> list[str]:
    """Return the text after the start tag and after each child (the last up to the end tag)."""
    if span.empty:
        return ['']
    position = span.head
    result = []
    for child in children(text, span):
        result.append(text[position:child.start])
        position = child.end
    close = text.rfind('</', position, span.end)
    result.append(text[position:close if close >= 0 else span.end])
    return result


def unchanged(text: str, span: Span, node: Any, spans: Spans) -> bool:
    """Return whether ``node`` and everything in it are still what the text says."""
    if not isinstance(node.tag, str):  # a comment's text is as written, entities and all
        source = text[span.start:span.end].replace('\r\n', '\n')
        if span.kind == COMMENT:
            return source[4:-3] == node.text
        return source == etree.tostring(node, encoding='unicode', with_tail=False)
    if not same_attributes(text, span, node) or len(node) != len(children(text, span)):
        return False
    between = gaps(text, span)
    if text_value(between[0]) != node.text:
        return False
    for child, after in zip(node, between[1:]):
        inner = spans.get(child)
        if inner is None or text_value(after) != child.tail or \
                not unchanged(text, inner, child, spans):
            return False
    return True
