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

"""What a reader did not understand, kept so that writers can put it back in place."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass(slots=True)
class Preserved:
    """
    Unconsumed parts of one element, in document order.

    ``attributes`` holds unknown attributes; ``children`` holds unknown child elements
    and comments as ``(anchor, element)``, where ``anchor`` is the number of known
    children written before it; ``texts`` holds the original text of known attributes,
    so that a value nobody changed is written back exactly as it was read; ``nested``
    holds the same for plain children such as ``<mass>`` or ``<parent>``.
    """

    attributes: dict[str, str] = field(default_factory=dict)
    children: list[tuple[int, Any]] = field(default_factory=list)
    texts: dict[str, str] = field(default_factory=dict)
    nested: dict[str, Preserved] = field(default_factory=dict)

    def sub(self, tag: str) -> Preserved | None:
        """Return what was kept of the child ``tag`` that has no model object of its own."""
        return self.nested.get(tag)

    def __bool__(self) -> bool:
        """Return whether anything is preserved."""
        return bool(self.attributes or self.children or self.texts or self.nested)
