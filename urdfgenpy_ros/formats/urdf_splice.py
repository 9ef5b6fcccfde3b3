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
Write the nodes of a read document from its source text, for one write.

A node still as the text says is its span, copied. An edited element keeps its start
tag, with only the values that changed replaced in place (in the tag's quotes); the text
between its children is copied while it says the same; children are copied or, edited,
written the same way. Nodes added since the file was read are written by lxml.
"""

from __future__ import annotations

import re
from typing import Any

from lxml import etree

from urdfgenpy_ros.formats._xml import esc, escape_text, without_declared
from urdfgenpy_ros.formats.source_record import (
    attribute_value, attributes, children, gaps, shallow, Span, Spans, text_value, unchanged)
from urdfgenpy_ros.model.preserved import SourceDocument

_DOUBLE_QUOTED = re.compile(r'(\s[^\s=<>]+=)"([^"\']*)"')


def prefixed(node: Any, name: str) -> str:
    """Return an attribute name with its namespace prefix (``xacro:foo``)."""
    if name[0] != '{':
        return name
    qname = etree.QName(name)
    for prefix, uri in node.nsmap.items():
        if uri == qname.namespace and prefix:
            return f'{prefix}:{qname.localname}'
    return qname.localname


def in_quotes(text: str, quote: str) -> str:
    """Return markup the writer made with its attributes in ``quote`` (the file's)."""
    if quote == '"' or '="' not in text:
        return text
    return _DOUBLE_QUOTED.sub(r"\1'\2'", text)


class Splice:
    """The text of a read document and the span of each of its nodes (one write's)."""

    def __init__(self, document: SourceDocument, newline: str, quote: str,
                 declared: dict[str, str]) -> None:
        text = document.text
        if newline != '\n':
            text = text.replace(newline, '\n')  # the writer puts the file's ends back
        self.text = text
        self.quote = quote
        self.declared = declared
        self.top = document.node.getroottree().getroot()
        key = 'spans' + newline  # the spans of the text's top level: found once per text
        known = document.memo.get(key)
        if known is None or known[0] is not document.text:
            known = document.memo[key] = (document.text, shallow(text, 0, len(text), last=True))
        self.spans = Spans(text, self.top, known[1])

    def span(self, node: Any) -> Span | None:
        """Return the span of a node of the document, if it has one."""
        return self.spans.get(node)

    def copy(self, span: Span) -> str:
        """Return the source text of a span."""
        return self.text[span.start:span.end]

    # ---- nodes ------------------------------------------------------------------------

    def node_text(self, node: Any, as_read: bool = False) -> str:
        """
        Return a node of the document: its span while it is as read, else written in place.

        ``as_read``: the caller knows the node is unedited (its snapshot says so).
        """
        span = self.spans.get(node)
        if span is None:
            return self.fresh(node)
        if (as_read and node not in self.spans.loose) or \
                unchanged(self.text, span, node, self.spans):
            return self.copy(span)
        if not isinstance(node.tag, str):
            return self.fresh(node)
        return self.rewritten(node, span)

    def fresh(self, node: Any) -> str:
        """Return a node written by lxml (namespaces the root declares aside)."""
        text = etree.tostring(node, encoding='unicode', with_tail=False)
        return in_quotes(without_declared(text, self.declared), self.quote)

    def rewritten(self, node: Any, span: Span) -> str:
        """Return an edited element: its source start tag and text, edits in place."""
        text = self.text
        name = text[span.start + 1:span.start + 1 + len(span.name)]
        attrs = self.attributes(node, [(prefixed(node, key), value)
                                       for key, value in node.attrib.items()])
        kids = list(node)
        if not kids and node.text is None:
            return self.empty(name, attrs, span)
        between = gaps(text, span)
        after = {id(place): gap for place, gap in zip(children(text, span), between[1:])}
        parts = [f'<{name}{attrs}>', _text(node.text, between[0])]
        for child in kids:
            parts.append(self.node_text(child))
            place = self.spans.get(child)
            parts.append(_text(child.tail, after.get(id(place))))
        parts.append(f'</{name}>')
        return ''.join(parts)

    # ---- start tags -------------------------------------------------------------------

    def attributes(self, node: Any, given: list[tuple[str, str]]) -> str:
        """
        Return the attributes of an element's start tag: ``given`` (name, value), in place.

        While the element's start tag in the text has the same attributes in the same
        order, it is kept as written (line breaks and all) with the values that changed
        replaced in its quotes; otherwise they are written in the file's quotes.
        """
        span = self.spans.get(node) if node is not None else None
        if span is not None and span.kind == 'element':
            kept = self._in_place(span, given)
            if kept is not None:
                return kept
        return self.written(given)

    def written(self, given: list[tuple[str, str]]) -> str:
        """Return attributes written anew, in the file's quotes."""
        if self.quote == "'":
            return ''.join(f" {name}='{_single(value)}'" for name, value in given)
        return ''.join(f' {name}="{esc(value)}"' for name, value in given)

    def _in_place(self, span: Span, given: list[tuple[str, str]]) -> str | None:
        text = self.text
        places = [match for match in attributes(text, span)
                  if not (match.group(2) == 'xmlns' or match.group(2).startswith('xmlns:'))]
        if [match.group(2) for match in places] != [name for name, _ in given]:
            return None  # attributes added, removed or moved: the element's own line
        body_start = span.start + 1 + len(span.name)
        body_end = span.head - (2 if span.empty else 1)
        parts, position = [], body_start
        for match, (_, value) in zip(places, given):
            if attribute_value(match.group(5)) == value:
                continue  # unchanged: the source's spelling stays
            quote = match.group(4)
            parts += [text[position:match.start(5)],
                      esc(value) if quote == '"' else _single(value)]
            position = match.end(5)
        parts.append(text[position:body_end])
        return ''.join(parts)

    def empty(self, name: str, attrs: str, span: Span | None) -> str:
        """Return an element without content: ``<x/>``, or ``<x></x>``, ``<x />`` as written."""
        if span is not None:
            if not span.empty:
                return f'<{name}{attrs}></{name}>'
            if self.text[span.head - 3].isspace() and attrs and not attrs[-1].isspace():
                return f'<{name}{attrs} />'  # the space the source put before its end
        return f'<{name}{attrs}/>'


def _text(value: str | None, source: str | None) -> str:
    """Return text between tags: the source's spelling while it says ``value``."""
    if source is not None and text_value(source) == value:
        return source
    return escape_text(value) if value else ''


def _single(value: str) -> str:
    """Escape a value for a single-quoted attribute."""
    return esc(value).replace('&quot;', '"').replace("'", '&apos;')
