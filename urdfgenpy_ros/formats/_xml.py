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


def fragment(element: Any, pad: str) -> str:
    """Serialise an lxml element (or comment) indented by ``pad``."""
    element = copy.deepcopy(element)
    element.tail = None
    if len(element):
        etree.indent(element, space=INDENT, level=len(pad) // len(INDENT))
    return pad + etree.tostring(element, encoding='unicode', with_tail=False)


Attr = tuple[str, Any, str, Any]
"""``(name, value, formatted text, default)``; default None means always written."""


def element(pad: str, tag: str, attrs: list[Attr], extras: Preserved | None,
            children: list[str]) -> str:
    """
    Return one element with its children, restoring what a reader preserved.

    For an element read from a file (``extras`` set), an attribute the file did not
    have stays out while it still holds its default; original number text is kept while
    it still reads as the value; unknown attributes and children go back where they were.
    """
    parts = [pad, '<', tag]
    texts = extras.texts if extras is not None else None
    for name, value, text, default in attrs:
        if texts is not None:
            original = texts.get(name)
            if original is not None:
                if _reads_as(original, value):
                    text = original
            elif default is not None and value == default:
                continue
        parts.append(f' {name}="{esc(text)}"')
    if extras is not None:
        for name, text in extras.attributes.items():
            parts.append(f' {name}="{esc(text)}"')
        if extras.children:
            children = list(children)
            inner = pad + INDENT
            for offset, (anchor, node) in enumerate(extras.children):
                children.insert(min(anchor + offset, len(children)), fragment(node, inner))
    if not children:
        parts.append('/>')
        return ''.join(parts)
    parts.append('>\n')
    parts.append('\n'.join(children))
    parts.append(f'\n{pad}</{tag}>')
    return ''.join(parts)


def write_text(path: str | PathLike[str], text: str) -> None:
    """Write ``text`` to ``path`` as UTF-8, creating parent directories."""
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(text, encoding='utf-8')
