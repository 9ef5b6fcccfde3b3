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
Find a value set on a model element that is not of the kind its field declares.

Writers use it to tell a user's own wrong value (``inertial.mass = 'abc'``), reported as one
line, from a bug of ours, which keeps its traceback.
"""

from __future__ import annotations

from dataclasses import fields, is_dataclass
from enum import Enum
from typing import Any

_NUMBERS = {'float', 'int'}
_TUPLES = {'Vec3', 'Vec4', 'Rgba'}
_PLAIN = (str, int, float, bool, list, dict, tuple, bytes)
_SKIPPED = {'source', 'extras', '_robot'}


def wrong_kind(element: object) -> str | None:
    """Return ``field = value (expected kind)`` for the first ill-kinded value, or None."""
    return _wrong_kind(element, '')


def _wrong_kind(element: object, path: str) -> str | None:
    if not is_dataclass(element) or isinstance(element, type):
        return None
    for spec in fields(element):
        if spec.name in _SKIPPED:
            continue
        value = getattr(element, spec.name, None)
        where = f'{path}{spec.name}'
        expected = _expected(str(spec.type), value)
        if expected is not None:
            return f'{where} = {value!r} (expected {expected})'
        items = value if isinstance(value, list) else [value]
        for index, item in enumerate(items):
            inner = f'{where}[{index}].' if isinstance(value, list) else f'{where}.'
            found = _wrong_kind(item, inner)
            if found is not None:
                return found
    return None


def _expected(annotation: str, value: Any) -> str | None:
    """Return the kind ``value`` should have been, or None when it is of its kind."""
    kinds = {kind.strip() for kind in annotation.split('|')}
    if value is None:
        return None if 'None' in kinds else annotation
    kinds.discard('None')
    if kinds & _NUMBERS:
        return None if _number(value) else 'a number'
    if kinds == {'str'}:
        return None if isinstance(value, str) else 'a string'
    if kinds & _TUPLES or any(kind.startswith('tuple[') for kind in kinds):
        ok = isinstance(value, tuple) and all(_number(item) for item in value)
        length = 3 if 'Vec3' in kinds else 4 if kinds & {'Vec4', 'Rgba'} else len(value)
        if ok and len(value) != length:
            return f'{length} numbers'
        return None if ok else 'a tuple of numbers'
    if any(kind.startswith('list[') for kind in kinds):
        return None if isinstance(value, list) else 'a list'
    if all(kind[:1].isupper() for kind in kinds):  # a model class (Origin, Inertial, ...)
        if isinstance(value, _PLAIN) and not isinstance(value, Enum):
            return ' or '.join(sorted(kinds))
    return None


def _number(value: object) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)
