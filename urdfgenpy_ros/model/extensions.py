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

"""Editable XML blocks URDF carries for other tools: gazebo, transmission, ros2_control."""

from __future__ import annotations

import copy
from typing import Any

from lxml import etree

_PARSER = etree.XMLParser(resolve_entities=False, no_network=True, load_dtd=False)


class Extension:
    """
    One ``<gazebo>``, ``<transmission>`` or ``<ros2_control>`` element, kept as XML.

    ``element`` is an lxml element: edit it in place with the lxml API. Two extensions are
    equal when their XML is equal, whitespace between elements aside.
    """

    __slots__ = ('element', 'source')

    def __init__(self, element: Any, source: Any = None) -> None:
        if isinstance(element, str):
            element = etree.fromstring(element, _PARSER)
        self.element = element
        self.source = source

    @classmethod
    def gazebo(cls, body: str = '', reference: str | None = None) -> Extension:
        """Return a ``<gazebo>`` block holding the XML text ``body``."""
        block = cls(f'<gazebo>{body}</gazebo>')
        if reference is not None:
            block.reference = reference
        return block

    @classmethod
    def transmission(cls, name: str, body: str = '') -> Extension:
        """Return a ``<transmission name=...>`` block holding ``body``."""
        block = cls(f'<transmission>{body}</transmission>')
        block.element.set('name', name)
        return block

    @classmethod
    def ros2_control(cls, name: str, body: str = '', kind: str = 'system') -> Extension:
        """Return a ``<ros2_control name=... type=...>`` block holding ``body``."""
        block = cls(f'<ros2_control>{body}</ros2_control>')
        block.element.set('name', name)
        block.element.set('type', kind)
        return block

    @property
    def tag(self) -> str:
        """Return the element's tag, e.g. ``gazebo``."""
        return str(self.element.tag)

    @property
    def name(self) -> str | None:
        """Return the ``name`` attribute, if any."""
        return self.element.get('name')

    @property
    def reference(self) -> str | None:
        """Return the link or joint a ``<gazebo>`` block refers to, if any."""
        return self.element.get('reference')

    @reference.setter
    def reference(self, value: str | None) -> None:
        if value is None:
            self.element.attrib.pop('reference', None)
        else:
            self.element.set('reference', value)

    def with_reference(self, reference: str) -> Any:
        """Return a copy of the element whose ``reference`` is ``reference``."""
        element = copy.deepcopy(self.element)
        element.set('reference', reference)
        return element

    def to_string(self) -> str:
        """Return the block's XML text."""
        return etree.tostring(self.element, encoding='unicode')

    def _canonical(self) -> bytes:
        element = copy.deepcopy(self.element)
        for node in element.iter():
            if node.text is not None and not node.text.strip():
                node.text = None
            if node.tail is not None and not node.tail.strip():
                node.tail = None
        element.tail = None
        return etree.tostring(element, method='c14n')

    def __eq__(self, other: object) -> bool:
        """Compare XML, ignoring whitespace between elements."""
        if not isinstance(other, Extension):
            return NotImplemented
        return self._canonical() == other._canonical()

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        """Return a short description."""
        return f'Extension({self.to_string()[:60]!r})'
