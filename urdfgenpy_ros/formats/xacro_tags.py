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
The attributes of one start tag of a Xacro file, as written, with their lines and columns.

The source map gives the place of a start tag (expat's); what an attribute says there (an
expression such as ``${m*(h*h)/12}``) and the names its expressions read are read from
the file's text, only for the tags a finding names.
"""

from __future__ import annotations

import ast
from functools import lru_cache
import os
from pathlib import Path
import re
from typing import NamedTuple

_ATTRIBUTE = re.compile(r"""([^\s=/>]+)\s*=\s*("[^"]*"|'[^']*')""")
_EXPRESSION = re.compile(r'\$\{([^}]*)\}')


class Attribute(NamedTuple):
    """One attribute of a start tag: name, value as written, and where the value starts."""

    name: str
    value: str
    line: int
    column: int  # of the attribute's name, from 1


@lru_cache(maxsize=64)
def _text(file: str, stamp: float) -> str:
    return Path(file).read_text(encoding='utf-8', errors='replace')


def source_text(file: str) -> str | None:
    """Return a file's text (cached while unchanged), or None when it cannot be read."""
    try:
        return _text(file, os.stat(file).st_mtime)
    except OSError:
        return None


def attributes(file: str, line: int, column: int) -> list[Attribute]:
    """Return the attributes of the start tag at ``line``, ``column`` of ``file``."""
    text = source_text(file)
    if text is None:
        return []
    lines = text.split('\n')
    if line > len(lines):
        return []
    start = sum(len(row) + 1 for row in lines[:line - 1]) + column - 1
    end = _tag_end(text, start)
    found = []
    for match in _ATTRIBUTE.finditer(text, start, end):
        offset = match.start()
        row = text.count('\n', 0, offset) + 1
        found.append(Attribute(match.group(1), match.group(2)[1:-1], row,
                               offset - text.rfind('\n', 0, offset)))
    return found


def _tag_end(text: str, start: int) -> int:
    """Return the offset of the ``>`` that closes the start tag at ``start``."""
    quote = ''
    for index in range(start, len(text)):
        char = text[index]
        if quote:
            quote = '' if char == quote else quote
        elif char in '"\'':
            quote = char
        elif char == '>':
            return index
    return len(text)


def names_read(value: str) -> list[str]:
    """Return the names the ``${...}`` expressions of ``value`` read, in order, once each."""
    names: list[str] = []
    for expression in _EXPRESSION.findall(value):
        try:
            tree = ast.parse(expression.strip(), mode='eval')
        except SyntaxError:
            continue
        for node in ast.walk(tree):
            if isinstance(node, ast.Name) and node.id not in names:
                names.append(node.id)
    return names


def is_expression(value: str) -> bool:
    """Return whether an attribute value holds a ``${...}`` expression."""
    return _EXPRESSION.search(value) is not None
