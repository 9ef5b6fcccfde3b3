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

import codecs
import copy
from os import PathLike
from pathlib import Path
import re
from typing import Any

from lxml import etree

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.floats import fmt, fmt_vec

__all__ = ['esc', 'escape_text', 'fmt', 'fmt_vec', 'fragment', 'INDENT', 'tag_end',
           'without_declared', 'write_text', 'xml_bytes']

INDENT = '  '


def robot_name(name: object) -> str:
    """Return a robot's name to write; a model without one is the user's one-line error."""
    if not isinstance(name, str) or not name:
        raise ModelError(f'robot: cannot be written, its name is {name!r}: give it one, e.g. '
                         "robot.name = 'my_robot'")
    return name


def esc(text: str) -> str:
    """Escape text for a double-quoted XML attribute."""
    if '&' in text or '<' in text or '>' in text or '"' in text:
        text = (text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')
                .replace('"', '&quot;'))
    return text


def escape_text(text: str) -> str:
    """Escape text content."""
    return text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;')


_TAG_REST = re.compile(r'(?:"[^"]*"|\'[^\']*\'|[^>"\'])*+>')  # a start tag after its '<'


def tag_end(text: str, start: int) -> int:
    """Return the index just after the ``>`` closing the start tag at ``start``."""
    match = _TAG_REST.match(text, start + 1)
    return len(text) if match is None else match.end()


_DECLARATION = re.compile(r' xmlns(?::([\w.-]+))?="([^"]*)"')


def fragment(element: Any, pad: str, declared: dict[str, str] | None = None,
             unit: str = INDENT) -> str:
    """
    Serialise an lxml element (or comment) indented by ``pad``.

    Namespace declarations that the enclosing root already makes (``declared``, prefix to
    URI) are left out of the fragment's opening tag.
    """
    element = copy.deepcopy(element)
    element.tail = None
    if len(element):
        etree.indent(element, space=unit, level=len(pad) // len(unit))
    text = etree.tostring(element, encoding='unicode', with_tail=False)
    return pad + without_declared(text, declared or {})


def without_declared(text: str, declared: dict[str, str]) -> str:
    """Drop namespace declarations the enclosing root already makes from the first tag."""
    if not declared or ' xmlns' not in text:
        return text
    end = text.find('>')
    head = _DECLARATION.sub(
        lambda m: '' if declared.get(m.group(1) or '') == m.group(2) else m.group(0),
        text[:end])
    return head + text[end:]


_ENCODING = re.compile(r'\s*<\?xml\b[^>]*?\bencoding\s*=\s*(["\'])([^"\']*)\1')


def xml_bytes(text: str, errors: str = 'strict') -> bytes:
    """
    Return XML ``text`` encoded as its declaration says (UTF-8 when it names none).

    A file read from ``encoding="ISO-8859-1"`` and written back keeps its declaration, so
    its bytes must follow it. Text that the named encoding cannot hold is written as
    UTF-8 and declared so.
    """
    match = _ENCODING.match(text, 0, 4096)
    if match is not None:
        try:
            codec = codecs.lookup(match.group(2)).name
        except LookupError:
            codec = 'utf-8'
        if codec != 'utf-8':
            try:
                return text.encode(codec, errors)
            except UnicodeEncodeError:
                text = f'{text[:match.start(2)]}UTF-8{text[match.end(2):]}'
    return text.encode('utf-8', errors)


def write_text(path: str | PathLike[str], text: str, *, bom: bool = False) -> None:
    """
    Write XML ``text`` to ``path`` in its declared encoding, creating parent folders.

    With ``bom``, a file written in UTF-8 starts with the byte order mark its source had.
    """
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    data = xml_bytes(text)
    if bom and data == text.encode('utf-8', 'surrogateescape'):
        data = codecs.BOM_UTF8 + data
    target.write_bytes(data)
