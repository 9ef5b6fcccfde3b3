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

"""The tables kept in the pages' Markdown (codes, node parameters) are current."""

from __future__ import annotations

import importlib.util
import re
from types import ModuleType

from helpers import REPO

from urdfgenpy_ros.model.codes import CODES, PREFLIGHT_HINTS

HOW = 'run python docs/hooks.py to write the tables again, and commit them'


def _hooks() -> ModuleType:
    spec = importlib.util.spec_from_file_location('docs_hooks', REPO / 'docs' / 'hooks.py')
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _rows(page: str) -> list[list[str]]:
    """Return the cells of every table row of a page as committed (separators left out)."""
    text = (REPO / 'docs' / page).read_text(encoding='utf-8')
    return [[cell.strip() for cell in re.split(r'(?<!\\)\|', line)[1:-1]]
            for line in text.splitlines()
            if line.startswith('|') and not line.startswith('|---')]


def test_every_committed_part_is_what_the_code_makes_now() -> None:
    hooks = _hooks()
    for page in sorted((REPO / 'docs').glob('*.md')):
        text = page.read_text(encoding='utf-8')
        assert hooks.with_committed_parts(text) == text, f'{page.name} is not current: {HOW}'


def test_the_committed_code_table_holds_every_code_as_codes_py_says() -> None:
    """Read back as GitHub shows it, each row against CODES itself (not the hook)."""
    rows = {row[0]: row[1:] for row in _rows('validation.md')
            if re.fullmatch(r'[A-Z]\d{3}', row[0])}
    assert set(rows) == set(CODES), f'{sorted(set(rows) ^ set(CODES))}: {HOW}'
    for code, (severity, title) in CODES.items():
        shown = [cell.replace('`', '').replace('\\|', '|') for cell in rows[code]]
        assert shown[0] == severity.value and shown[1] == title, (code, HOW)
        if code in PREFLIGHT_HINTS:
            assert shown[2] == PREFLIGHT_HINTS[code], (code, HOW)


def test_the_committed_parameter_table_names_each_declared_parameter() -> None:
    """The node's declarations, read from its source by the parameter calls it makes."""
    source = (REPO / 'urdfgenpy_ros' / 'publisher' / 'node.py').read_text(encoding='utf-8')
    table = source[source.index('_PARAMETERS'):]
    declared = re.findall(r"^    '(\w+)': \(", table, re.M)
    shown = [row[0].strip('`') for row in _rows('node.md')[1:]]
    assert declared and shown == declared, HOW
