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


"""What a reader found in the file, so that writers can keep it: data, never code."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any, NamedTuple


class Directive(NamedTuple):
    """
    A comment of the file that speaks to urdfgenpy (``<!-- urdfgenpy: ignore I205 -->``).

    ``line`` and ``text`` are the comment's; ``leading`` says it stands before the first
    element (above ``<robot>``, or first inside it). ``path`` is the element path (as
    findings give it) of the element the comment stands directly before, other comments
    between, and ``first`` .. ``last`` the lines that element spans; ``path`` is '' when
    no element follows.
    """

    line: int
    text: str
    leading: bool
    path: str = ''
    first: int = 0
    last: int = 0


class SourceElement(NamedTuple):
    """
    An element of the file as read, as data: its tag, attributes, line and child elements.

    What the model does not hold (an ``<inertial>`` urdfdom drops, a ``<compiler>`` inside
    a ``<mujoco>`` block) is read through these, never through the parser's tree.
    """

    tag: str
    attrib: dict[str, str]
    line: int
    children: tuple[SourceElement, ...]

    def find(self, tag: str) -> SourceElement | None:
        """Return the first child element named ``tag``, or None."""
        return next((child for child in self.children if child.tag == tag), None)

    def each(self, tag: str) -> Iterator[SourceElement]:
        """Yield this element and every element inside it named ``tag``, in document order."""
        if self.tag == tag:
            yield self
        for child in self.children:
            yield from child.each(tag)


def source_element(node: Any) -> SourceElement:
    """Return the element ``node`` of the file as read, as :class:`SourceElement` data."""
    return SourceElement(node.tag, dict(node.attrib), node.sourceline or 0, tuple(
        [source_element(child) for child in node if isinstance(child.tag, str)]))


class Preserved:
    """
    The source element of a model element and a by-value snapshot of what it read.

    A writer compares the element's current fields with ``snapshot``: equal, it copies
    the element's text from the file; different, it writes the element anew in the
    layout of ``node``, keeping what the model does not hold (unknown attributes and
    children, comments) and the original text of every value nobody changed.
    """

    __slots__ = ('node', 'snapshot')

    def __init__(self, node: Any, snapshot: tuple | None = None) -> None:
        self.node = node
        self.snapshot = snapshot

    def element(self) -> SourceElement:
        """Return the source element, as read, as data (what the model may not hold)."""
        return source_element(self.node)

    def __repr__(self) -> str:
        """Return the source tag and line."""
        return f'Preserved(<{self.node.tag}> line {self.node.sourceline})'


class SourceDocument(Preserved):
    """
    The record of a file a robot was read from: its text, and its ``<robot>`` element.

    ``text`` is the file as read (decoded, without a byte order mark: ``bom`` says there
    was one); ``order`` the robot's items in document order (links, joints, materials,
    :class:`~urdfgenpy_ros.extensions.Extension` blocks, and other nodes as they are);
    ``blocks`` lxml's text of each block's element when read, by element, to tell an
    edited block; ``mended`` whether the reader mended the XML declaration (P102);
    ``directives`` the comments that speak to urdfgenpy, in document order (:class:`Directive`).
    Writers find each node's span in ``text`` (:mod:`urdfgenpy_ros.formats.source_record`)
    and keep in ``memo`` what they work out from it (its line ends, the spans of its
    nodes), each entry with the text it was made from: it holds while ``text`` is that text.
    """

    __slots__ = ('order', 'text', 'bom', 'mended', 'blocks', 'directives', 'memo')

    def __init__(self, node: Any, order: list[Any], text: str, *, bom: bool = False,
                 mended: bool = False, blocks: dict[Any, bytes] | None = None,
                 directives: list[Directive] | None = None) -> None:
        super().__init__(node)
        self.order = order
        self.text = text
        self.bom = bom
        self.mended = mended
        self.blocks = blocks if blocks is not None else {}
        self.directives = directives if directives is not None else []
        self.memo: dict[str, tuple[Any, ...]] = {}

    def __getstate__(self) -> tuple[None, dict[str, Any]]:
        """Return what a copy takes: every slot but ``memo`` (a copy works it out again)."""
        slots = {name: getattr(self, name) for name in (*Preserved.__slots__,
                                                        *SourceDocument.__slots__)}
        del slots['memo']
        return None, slots

    def __setstate__(self, state: tuple[None, dict[str, Any]]) -> None:
        """Take a copy's slots; its ``memo`` starts empty."""
        for name, value in state[1].items():
            setattr(self, name, value)
        self.memo = {}

    def elements(self, tag: str) -> list[Any]:
        """
        Return the robot's top-level ``<tag>`` elements the model does not hold, as read.

        Such an element (``<mujoco>``, a vendor's block) is kept as written and copied by
        the writers; exporters that understand it read it here, in document order.
        """
        return [node for node in self.unknown_elements() if node.tag == tag]

    def unknown_elements(self) -> list[Any]:
        """Return every top-level element the model does not hold, as read, in document order."""
        return [node for item, node in zip(self.order, self.node)  # the nodes writers copy
                if isinstance(node.tag, str) and not hasattr(item, 'extras')  # no link, joint,
                and not hasattr(item, 'element')]  # material, nor a block (Extension)

    def file_element(self) -> SourceElement:
        """Return the file's top element as read (``<robot>``, or what wraps it), as data."""
        return source_element(self.node.getroottree().getroot())

    @property
    def outside(self) -> tuple[list[Any], list[Any]]:
        """Return the comments and processing instructions before and after the root."""
        node = self.node
        return list(node.itersiblings(preceding=True))[::-1], list(node.itersiblings())
