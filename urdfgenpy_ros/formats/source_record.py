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

from difflib import SequenceMatcher
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
        self.children: list[Span] = []

    @property
    def empty(self) -> bool:
        """Return whether the element is written ``<x/>`` (not ``<x></x>``)."""
        return self.end == self.head

    def __repr__(self) -> str:
        """Return the node's kind, name and place."""
        return f'Span({self.kind} {self.name!r} {self.start}:{self.end})'


def scan(text: str) -> list[Span]:
    """Return the top-level nodes of ``text`` (elements, comments, PIs) with their spans."""
    top: list[Span] = []
    stack: list[Span] = []
    for match in _TOKEN.finditer(text):
        siblings = stack[-1].children if stack else top
        if match.group(6) is not None:
            span = Span(ELEMENT, match.group(6), match.start(), match.end())
            siblings.append(span)
            if not match.group(7):
                stack.append(span)
        elif match.group(5) is not None:
            if stack:
                stack.pop().end = match.end()
        elif match.group(1) is not None:
            siblings.append(_leaf(COMMENT, match))
        elif match.group(3) is not None and not _XML_DECLARATION.match(match.group(3)):
            siblings.append(_leaf(PI, match))
    return top


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


def pair(text: str, top: Any) -> tuple[dict[Any, Span], set[Any]]:
    """
    Return the span of each node of the document whose top element is ``top``.

    Nodes added since the text was read have none. Where a parent's children changed in
    number, the others are paired by their order and names: those (and what is in them)
    are also returned in the set of nodes whose span may be another's of the same name.
    """
    spans: dict[Any, Span] = {}
    loose: set[Any] = set()
    nodes = [*reversed(list(top.itersiblings(preceding=True))), top, *top.itersiblings()]
    found = scan(text)
    if len(found) != len(nodes):  # a copy of the tree has no siblings: its element only
        found = [span for span in found if span.kind == ELEMENT][:1]
        nodes = [top]
    _pair(text, found, nodes, spans, loose, False)
    return spans, loose


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


def _pair(text: str, found: list[Span], nodes: list[Any], spans: dict[Any, Span],
          loose: set[Any], moved: bool) -> None:
    if len(found) == len(nodes) and all(_fits(span, node) for span, node in zip(found, nodes)):
        pairs = list(zip(found, nodes))
    else:
        moved = True
        matcher = SequenceMatcher(None, [_key(text, span) for span in found],
                                  [_node_key(node) for node in nodes], autojunk=False)
        pairs = [(found[block.a + k], nodes[block.b + k])
                 for block in matcher.get_matching_blocks() for k in range(block.size)]
    for span, node in pairs:
        spans[node] = span
        if moved:
            loose.add(node)
        if span.children or len(node):
            _pair(text, span.children, list(node), spans, loose, moved)


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
    for child in span.children:
        result.append(text[position:child.start])
        position = child.end
    close = text.rfind('</', position, span.end)
    result.append(text[position:close if close >= 0 else span.end])
    return result


def unchanged(text: str, span: Span, node: Any, spans: dict[Any, Span]) -> bool:
    """Return whether ``node`` and everything in it are still what the text says."""
    if not isinstance(node.tag, str):
        return text_value(text[span.start + 4:span.end - 3]) == node.text \
            if span.kind == COMMENT else True
    if not same_attributes(text, span, node) or len(node) != len(span.children):
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
