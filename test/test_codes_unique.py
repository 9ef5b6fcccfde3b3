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

"""A code is declared once: a dict literal keeps the last of two equal keys, silently."""

from __future__ import annotations

import ast
from collections import Counter
from pathlib import Path

import urdfgenpy_ros.model.codes as codes


def _keys(name: str) -> list[str]:
    """Return the literal keys of the module-level dict ``name`` of codes.py, in order."""
    tree = ast.parse(Path(codes.__file__).read_text(encoding='utf-8'))
    for node in tree.body:
        if isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) \
                and node.target.id == name and isinstance(node.value, ast.Dict):
            return [key.value for key in node.value.keys if isinstance(key, ast.Constant)]
    return []


def test_every_code_is_declared_once() -> None:
    keys = _keys('CODES')
    assert len(set(keys)) == len(codes.CODES)
    assert keys, 'no declared codes found'
    twice = sorted(code for code, count in Counter(keys).items() if count > 1)
    assert not twice, f'codes declared more than once: {twice}'
