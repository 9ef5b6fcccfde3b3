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

"""Text helpers shared by the writers: exact numbers, escaping, preserved XML."""

from __future__ import annotations

import copy
from os import PathLike
from pathlib import Path
import re
from typing import Any

from lxml import etree

from urdfgenpy_ros.preserved import Preserved

INDENT = '  '
_FORMATTED: dict[float, str] = {}


def fmt(value: float) -> str:
    """Return the shortest text that reads back as the same float (``1`` for 1.0)."""
    text = _FORMATTED.get(value)
    if text is None:
        text = repr(float(value))
        if text.endswith('.0'):
            text = text[:-2]
        if text == '-0':
            text = '0'
        if len(_FORMATTED) > 4096:
            _FORMATTED.clear()
        _FORMATTED[value] = text
    return text


_VECTORS: dict[tuple, str] = {}


def fmt_vec(values: Any) -> str:
    """Return numbers separated by single spaces (cached: vectors repeat a lot)."""
    text = _VECTORS.get(values)
    if text is None:
        text = ' '.join([fmt(v) for v in values])
        if len(_VECTORS) > 4096:
            _VECTORS.clear()
        _VECTORS[tuple(values)] = text
    return text


def esc(text: str) -> str:
    """Escape text for a double-quoted XML attribute."""
    if '&' in text or '<' in text or '>' in text or '"' in text:
        text = (text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')
                .replace('"', '&quot;'))
    return text


def escape_text(text: str) -> str:
    """Escape text content."""
    return text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')


def _reads_as(text: str, value: Any) -> bool:
    """Return whether the original attribute ``text`` still denotes ``value``."""
    try:
        if isinstance(value, tuple):
            return tuple(float(part) for part in text.split()) == value
        if isinstance(value, float):
            return float(text) == value
    except ValueError:
        return False
    return text == value


_DECLARATION = re.compile(r' xmlns(?::([\w.-]+))?="([^"]*)"')


def fragment(element: Any, pad: str, declared: dict[str, str] | None = None) -> str:
    """
    Serialise an lxml element (or comment) indented by ``pad``.

    Namespace declarations that the enclosing root already makes (``declared``, prefix to
    URI) are left out of the fragment's opening tag.
    """
    element = copy.deepcopy(element)
    element.tail = None
    if len(element):
        etree.indent(element, space=INDENT, level=len(pad) // len(INDENT))
    text = etree.tostring(element, encoding='unicode', with_tail=False)
    return pad + _without_declared(text, declared or {})


def _without_declared(text: str, declared: dict[str, str]) -> str:
    """Drop namespace declarations the enclosing root already makes from the first tag."""
    if not declared or ' xmlns' not in text:
        return text
    end = text.find('>')
    head = _DECLARATION.sub(
        lambda m: '' if declared.get(m.group(1) or '') == m.group(2) else m.group(0),
        text[:end])
    return head + text[end:]


Attr = tuple[str, Any, str, Any]
"""``(name, value, formatted text, default)``; default None means always written."""


def verbatim(node: Any, pad: str, declared: dict[str, str]) -> str:
    """Return a source element exactly as it was read (namespaces the root declares aside)."""
    text = etree.tostring(node, encoding='unicode', with_tail=False)
    return pad + _without_declared(text, declared)


def element(pad: str, tag: str, attrs: list[Attr], extras: Preserved | None,
            children: list[str], tags: list[str] | None = None,
            restore_children: bool = True) -> str:
    """
    Return one element with its children, restoring what a reader preserved.

    For an element read from a file (``extras`` set): attributes and known children
    (``tags`` names each child's tag) come in the file's order; an attribute the file did
    not have stays out while it still holds its default; original number text is kept
    while it still reads as the value; unknown attributes and children go back where
    they were.
    """
    parts = [pad, '<', tag]
    if extras is None:
        for name, _, text, _ in attrs:
            parts.append(f' {name}="{esc(text)}"')
    else:
        texts = extras.texts
        rank = {name: number for number, name in enumerate(texts)}
        placed = []
        for name, value, text, default in attrs:
            original = texts.get(name)
            if original is not None:
                if _reads_as(original, value):
                    text = original
            elif default is not None and value == default:
                continue
            placed.append((rank.get(name, len(rank)), f' {name}="{esc(text)}"'))
        unknown = extras.attributes
        if unknown:
            ranks = [number for number, name in enumerate(texts)
                     if name not in extras.known_attributes]
            placed.extend((number, f' {name}="{esc(text)}"')
                          for number, (name, text) in zip(ranks, unknown.items()))
        parts.extend(text for _, text in sorted(placed, key=lambda item: item[0]))
        if tags is not None:
            children = _in_source_order(extras.node, children, tags)
        if restore_children and len(extras.node):
            children = list(children)
            inner = pad + INDENT
            for offset, (anchor, node) in enumerate(extras.children):
                children.insert(min(anchor + offset, len(children)), fragment(node, inner))
        text = extras.node.text
        if text is not None and not text.isspace():
            children = [f'{pad}{INDENT}{escape_text(text.strip())}', *children]
    if not children:
        parts.append('/>')
        return ''.join(parts)
    parts.append('>\n')
    parts.append('\n'.join(children))
    parts.append(f'\n{pad}</{tag}>')
    return ''.join(parts)


def _in_source_order(node: Any, children: list[str], tags: list[str]) -> list[str]:
    """Order ``children`` as their tags appear in ``node``; new ones go last."""
    waiting = list(zip(tags, children))
    ordered = []
    for child in node:
        for index, (tag, text) in enumerate(waiting):
            if tag == child.tag:
                ordered.append(text)
                del waiting[index]
                break
    return ordered + [text for _, text in waiting]


def write_text(path: str | PathLike[str], text: str) -> None:
    """Write ``text`` to ``path`` as UTF-8, creating parent directories."""
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(text, encoding='utf-8')
