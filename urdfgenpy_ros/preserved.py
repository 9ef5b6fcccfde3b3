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

from typing import Any

from lxml import etree


class Preserved:
    """
    The source element of a model element, and what of it the model does not hold.

    Everything is derived from ``node`` (an lxml element) when a writer asks: ``texts``
    are the original attribute texts (a value nobody changed is written back as it was
    read), ``attributes`` the attributes the model does not know, ``children`` the
    unknown child elements and comments with their anchor (how many known children came
    before). ``nested`` holds the same for plain children that have no model object of
    their own (``<mass>``, ``<parent>``, ``<geometry>``); ``order`` the document order of
    the robot's top-level items; ``outside`` the comments before and after the root.
    """

    __slots__ = ('node', 'known_attributes', 'known_children', 'nested', 'order', 'outside',
                 'state')

    def __init__(self, node: Any, known_attributes: frozenset[str] = frozenset(),
                 known_children: frozenset[str] = frozenset(),
                 nested: dict[str, Preserved] | None = None) -> None:
        self.node = node
        self.known_attributes = known_attributes
        self.known_children = known_children
        self.nested = nested or {}
        self.order: list[Any] | None = None
        self.outside: tuple[list[Any], list[Any]] = ([], [])
        self.state: tuple | None = None  # a top-level element's fingerprint when read

    @property
    def texts(self) -> Any:
        """Return the original attributes (a mapping of name to text)."""
        return self.node.attrib

    @property
    def attributes(self) -> dict[str, str]:
        """Return the attributes the model does not know, with prefixed names."""
        unknown = {}
        for name, value in self.node.attrib.items():
            if name not in self.known_attributes:
                unknown[_prefixed(self.node, name)] = value
        return unknown

    @property
    def children(self) -> list[tuple[int, Any]]:
        """Return ``(anchor, node)`` for every unknown child element or comment."""
        kept, known = [], 0
        for child in self.node:
            if isinstance(child.tag, str) and child.tag in self.known_children:
                known += 1
            else:
                kept.append((known, child))
        return kept

    def sub(self, tag: str) -> Preserved | None:
        """Return what was kept of the plain child ``tag``."""
        return self.nested.get(tag)

    def __repr__(self) -> str:
        """Return the source tag and line."""
        return f'Preserved(<{self.node.tag}> line {self.node.sourceline})'


def _prefixed(node: Any, name: str) -> str:
    if name[0] != '{':
        return name
    qname = etree.QName(name)
    for prefix, uri in node.nsmap.items():
        if uri == qname.namespace and prefix:
            return f'{prefix}:{qname.localname}'
    return qname.localname
