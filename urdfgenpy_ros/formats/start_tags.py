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
Start tags as the source wrote them, where lxml would write them otherwise.

lxml writes every start tag on one line with single spaces; CAD exporters (SolidWorks's
among them) put each attribute on its own line. An unedited element keeps its source
tags: the reader records the unusual ones, the writer puts them back. So too for a text
that spells characters with references (``&quot;``), which lxml writes as characters.
"""

from __future__ import annotations

from collections.abc import Iterator
import html
from itertools import islice
import re
from typing import Any

from lxml import etree

_PLAIN = re.compile(r'<[^\s<>/]+(?: [^\s=<>]+="[^"<>]*")*/?>')  # as lxml writes it


def tag_end(text: str, start: int) -> int:
    """Return the index just after the ``>`` closing the start tag at ``start``."""
    match = _TAG_REST.match(text, start + 1)
    return len(text) if match is None else match.end()


_TAG_REST = re.compile(r'(?:"[^"]*"|\'[^\']*\'|[^>"\'])*+>')  # a start tag after its '<'

SourceTags = dict[Any, tuple[str, tuple[tuple[str, str], ...]]]
"""Per element, its source start tag and the attributes it had when read."""


def source_tag(tags: SourceTags, node: Any) -> str | None:
    """Return ``node``'s recorded start tag while its attributes are still as read."""
    recorded = tags.get(node)
    if recorded is None or tuple(node.attrib.items()) != recorded[1]:
        return None
    return recorded[0]


# One token of XML text, after the text before it: what is skipped (comments, CDATA,
# processing instructions, declarations, end tags), or a start tag as lxml writes it
# (group 1), or another start tag (group 2); group 3 says whether an end tag follows at
# once (an empty element written ``<x></x>``).
_TOKEN = re.compile(r'[^<]*+(?:<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>|<![^>]*>|</[^>]*>|'
                    r'(<[^\s<>/!?]+(?: [^\s=<>]+="[^"<>]*")*/?>)|'
                    r'(<[^\s<>/!?](?:[^>"\']++|"[^"]*"|\'[^\']*\')*+>)|<)(</)?', re.DOTALL)


# A token found in source text: something that is no start tag (comment, CDATA, processing
# instruction, declaration) or a start tag lxml would write otherwise (anything after the
# part lxml writes alike, or ``<x></x>``). Start tags lxml writes alike are not matched.
_UNUSUAL = re.compile(r'<(?:!--.*?-->|!\[CDATA\[.*?\]\]>|\?.*?\?>|![^>]*>|'
                      r'(?![/!?])[^\s<>/]++(?: [^\s=<>]+="[^"<>]*")*+(?!/>|>(?!</))'
                      r'(?:[^>"\']++|"[^"]*"|\'[^\']*\')*+>)', re.DOTALL)


def unusual_start_tags(document: Any, text: str, newline: str = '\n') -> SourceTags:
    """
    Return the source start tags of the document's elements that lxml would write otherwise.

    That is: line breaks, tabs, runs of spaces or single quotes inside the tag, and the
    start tag of an empty element written with an end tag (``<link></link>``, which lxml
    writes ``<link/>``). ``text`` is the whole source; its start tags come in the
    elements' order, and a tag is recorded only for the element at its place that still
    has the tag's name and attribute values (the tree may have changed since it was
    read). ``newline`` is the file's line end, which the writer puts back at each line
    break.
    """
    found = _Recorded()
    for match, element in _opened(document, text, _UNUSUAL):
        tag = match.group()
        attributes = tuple(element.attrib.items())
        if _as_read(tag, element.tag, attributes):
            found[element] = (tag.replace(newline, '\n'),  # the writer puts the file's ends
                              attributes)
    if _TEXT_REFERENCE.search(text) is not None:
        found.texts = _spelled_texts(document, text, newline)
    return found


# Text right after a start tag that spells a character with a reference lxml would not
# write (``&quot;``, ``&apos;``, ``&#...;``); lxml writes the character itself.
_TEXT_REFERENCE = re.compile(r'>[^<]*&(?:quot;|apos;|#)')

# What to pass over (comments, CDATA, processing instructions, declarations), or a start
# tag followed by such text.
_SPELLED = re.compile(r'<(?:!--.*?-->|!\[CDATA\[.*?\]\]>|\?.*?\?>|![^>]*>)|'
                      r'<(?![/!?])(?:[^>"\']++|"[^"]*"|\'[^\']*\')*+>'
                      r'(?=[^<]*&(?:quot;|apos;|#))', re.DOTALL)


def _spelled_texts(document: Any, text: str, newline: str) -> dict[Any, tuple[str, str]]:
    """
    Return, per element whose text the source spells with references, that spelling.

    With the text it stands for, which the element must still have for the spelling to
    be put back. Only a spelling that reads as that text is recorded.
    """
    spelled: dict[Any, tuple[str, str]] = {}
    for match, element in _opened(document, text, _SPELLED):
        end = text.find('<', match.end())
        spelling = text[match.end():end if end >= 0 else len(text)].replace(newline, '\n')
        name = _NAME.match(match.group())
        if name is not None and _names_tag(name.group(1), element.tag) and \
                element.text is not None and _text_value(spelling) == element.text:
            spelled[element] = (spelling, element.text)
    return spelled


def _opened(document: Any, text: str, tokens: re.Pattern[str]) -> Iterator[tuple[Any, Any]]:
    """
    Yield each start tag ``tokens`` matches in the source ``text``, with its element.

    ``tokens`` also matches what is no start tag (comments, CDATA, processing
    instructions, declarations), which is passed over; between two matches every ``<``
    opens a start tag or an end tag, so counting them finds the element in document order.
    """
    elements = document.iter(etree.Element)
    index = taken = position = 0  # start tags before ``position``; elements taken
    for match in tokens.finditer(text):
        index += text.count('<', position, match.start()) - \
            text.count('</', position, match.start())
        position = match.end()
        if match.group()[1] in '!?':
            continue
        next(islice(elements, index - taken, index - taken), None)  # skip to the index-th
        element = next(elements, None)
        if element is None:
            return
        index += 1
        taken = index
        yield match, element


def _text_value(source: str) -> str:
    """Return the text XML reads from the source text of it (no markup in it)."""
    return html.unescape(source.replace('\r\n', '\n').replace('\r', '\n'))


# One attribute of a source start tag: its name, its quote and its value as written.
ATTRIBUTE = re.compile(r'([^\s=/>]+)\s*=\s*(["\'])(.*?)\2', re.DOTALL)
_NAME_OF_TAG = re.compile(r'<([^\s/>]+)')


def _as_read(tag: str, name: Any, attributes: tuple[tuple[str, str], ...]) -> bool:
    """
    Return whether the source start tag ``tag`` is the element's, with its attributes.

    The tree may have changed since it was read (a block edited in place, an element
    added): a tag is only recorded for an element that still has its name and values.
    """
    written = _NAME_OF_TAG.match(tag).group(1)  # type: ignore[union-attr]
    if written != name and (not isinstance(name, str) or
                            written.rsplit(':', 1)[-1] != name.rsplit('}', 1)[-1]):
        return False
    found = ATTRIBUTE.findall(tag, len(written) + 1)
    if len(found) != len(attributes):  # namespace declarations are no attributes
        found = [item for item in found if not item[0].startswith('xmlns')
                 or item[0][5:6] not in ('', ':')]
        if len(found) != len(attributes):
            return False
    for (key, _, value), (have, text) in zip(found, attributes):
        if value != text and _value(value) != text:
            return False
        if key != have and key.rsplit(':', 1)[-1] != have.rsplit('}', 1)[-1]:
            return False
    return True


def _value(source: str) -> str:
    """Return an attribute's value as XML reads the source text of it."""
    if '\r' in source:
        source = source.replace('\r\n', ' ').replace('\r', ' ')
    if '\n' in source or '\t' in source:
        source = source.replace('\n', ' ').replace('\t', ' ')
    return html.unescape(source) if '&' in source else source


def same_as_source(written: str, text: str, start: int) -> bool:
    """Return whether lxml's ``written`` document has all inside the root's tag as ``text``."""
    return text.startswith(written[tag_end(written, 0):], tag_end(text, start))


class _Recorded(dict[Any, tuple[str, tuple[tuple[str, str], ...]]]):
    """The recorded start tags, and the last text they were put back into (``memo``)."""

    __slots__ = ('memo', 'texts')

    def __init__(self) -> None:
        super().__init__()
        self.memo: tuple[Any, str, str] | None = None  # node, lxml's text, restored text
        self.texts: dict[Any, tuple[str, str]] = {}  # texts spelled with references


def as_source(serialized: str, node: Any, extras: Any) -> str:
    """
    Return lxml's text of ``node`` as the source wrote it, as far as the tree is as read.

    ``extras`` is the robot's :class:`~urdfgenpy_ros.preserved.DocumentPreserved`: while
    the whole tree is as read, its text is the file's; otherwise the recorded start tags
    are put back.
    """
    verbatim = extras.verbatim
    if verbatim is not None and node is extras.node and serialized == verbatim[0]:
        return verbatim[1]
    if not isinstance(node.tag, str):  # a comment or processing instruction
        return serialized
    return restore_start_tags(serialized, node, extras.start_tags)


def restore_start_tags(serialized: str, node: Any, tags: SourceTags) -> str:
    """
    Return lxml's serialisation of ``node`` with its elements' source start tags.

    And with the source's spelling of texts written with references, while unchanged.
    """
    texts = getattr(tags, 'texts', None)
    if not tags and not texts:
        return serialized
    memo = getattr(tags, 'memo', None)
    if memo is not None and memo[0] is node and memo[1] == serialized:
        return memo[2]  # written again unchanged (a node republishing, say): same text
    elements = list(node.iter(etree.Element))
    if not tags:
        restored = serialized
    elif len(tags) > _FEW:
        restored = _restore(serialized, elements, tags)
    else:
        restored = _restore_few(serialized, elements, tags)
    if texts:
        restored = _restore_texts(restored, elements, texts)
    if restored is not serialized and isinstance(tags, _Recorded):
        tags.memo = (node, serialized, restored)
    return restored


_FEW = 32  # up to this many recorded tags, find each one's place instead of reading all

# Everything up to the '<' of the next start tag: text, comments, CDATA, processing
# instructions and end tags are passed over, so each match is one start tag.
_TO_NEXT_START = re.compile(r'(?:[^<]++|<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>|'
                            r'<![^>]*>|</[^>]*>)*+<', re.DOTALL)


def _restore_few(serialized: str, elements: list[Any], tags: SourceTags) -> str:
    """Put back a few recorded tags, skipping from one element's start tag to the next."""
    located = _start_tags_of(serialized, elements, [
        element for element, (_, attributes) in tags.items()
        if tuple(element.attrib.items()) == attributes])
    if not located:
        return serialized
    parts, position = [], 0
    for element, start, end in located:
        parts += [serialized[position:start], _as_source(tags[element][0], serialized[start:end])]
        position = end
    parts.append(serialized[position:])
    return ''.join(parts)


def _restore_texts(serialized: str, elements: list[Any],
                   texts: dict[Any, tuple[str, str]]) -> str:
    """Put back the source's spelling of the texts still as read, after their start tags."""
    located = _start_tags_of(serialized, elements, [
        element for element, (_, value) in texts.items() if element.text == value])
    if not located:
        return serialized
    parts, position = [], 0
    for element, _, end in located:
        stop = serialized.find('<', end)
        stop = len(serialized) if stop < 0 else stop
        if _text_value(serialized[end:stop]) != element.text:
            return serialized  # not the shape expected: keep lxml's text
        parts += [serialized[position:end], texts[element][0]]
        position = stop
    parts.append(serialized[position:])
    return ''.join(parts)


def _start_tags_of(serialized: str, elements: list[Any],
                   chosen: list[Any]) -> list[tuple[Any, int, int]] | None:
    """
    Return where lxml's text of ``elements`` has the start tag of each chosen element.

    In document order, as (element, start, end); None if the text is not of that shape.
    Elements not among ``elements`` (another subtree) are left out.
    """
    places = []
    for element in chosen:
        try:
            places.append((elements.index(element), element))
        except ValueError:  # not in this subtree
            continue
    places.sort(key=lambda place: place[0])
    starts = _TO_NEXT_START.finditer(serialized)
    located, seen = [], 0
    for index, element in places:
        match = next(islice(starts, index - seen, None), None)
        seen = index + 1
        if match is None:
            return None
        start = match.end() - 1
        name = _NAME.match(serialized, start)
        if name is None or not _names_tag(name.group(1), element.tag):
            return None
        located.append((element, start, tag_end(serialized, start)))
    return located


def _names_tag(written: str, tag: str) -> bool:
    """Return whether a start tag's written name is the element tag (prefix and all)."""
    return written == tag or written.rsplit(':', 1)[-1] == tag.rsplit('}', 1)[-1]


def _restore(serialized: str, elements: list[Any], tags: SourceTags) -> str:
    """Put back recorded tags, reading every start tag lxml wrote."""
    if not any(item in tags for item in elements):
        return serialized
    parts, position, index = [], 0, 0
    for match in _TOKEN.finditer(serialized):
        start, end = match.span(1)
        if start < 0:
            start, end = match.span(2)
            if start < 0:
                continue
        if index == len(elements):
            return serialized  # not the shape expected: keep lxml's text
        recorded = source_tag(tags, elements[index])
        index += 1
        if recorded is not None:
            parts.append(serialized[position:start])
            parts.append(_as_source(recorded, serialized[start:end]))
            position = end
    if index != len(elements):
        return serialized
    parts.append(serialized[position:])
    return ''.join(parts)


def _as_source(recorded: str | None, written: str) -> str:
    """Return the recorded start tag in place of lxml's ``written`` one, end tag and all."""
    if recorded is None:
        return written
    empty = written.endswith('/>')
    if recorded.endswith('/>') == empty:
        return recorded
    if empty:  # <x></x>: lxml writes <x/>
        return f'{recorded}</{_NAME.match(recorded).group(1)}>'  # type: ignore[union-attr]
    return written  # children added since it was read: lxml's tag, open


_NAME = re.compile(r'<([^\s/>]+)')
