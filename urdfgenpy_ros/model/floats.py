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


"""Exact text of numbers: the shortest spelling that reads back as the same float."""

from __future__ import annotations

from collections.abc import Iterable


def fmt(value: float) -> str:
    """Return the shortest text that reads back as the same float (``1`` for 1.0)."""
    text = repr(float(value))
    if text.endswith('.0'):
        return text[:-2]
    return '0' if text == '-0' else text


def fmt_vec(values: Iterable[float]) -> str:
    """Return numbers separated by single spaces."""
    return ' '.join([fmt(value) for value in values])
