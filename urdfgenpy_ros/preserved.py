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


"""What a reader found in the file for one element, so that writers can keep it."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple


class Layout(NamedTuple):
    """How a file was written: indentation unit, line ends, quotes, its first lines."""

    unit: str = '  '
    newline: str = '\n'
    quote: str = '"'
    declaration: str = '<?xml version="1.0"?>'
    head: str | None = None  # the ``<robot ...>`` opening tag as written
    end: str = '\n'  # the white space after the document's last tag
    gap: str = '\n'  # the white space after the XML declaration (or before all, if none)
    between: tuple[str, ...] = ()  # the white space before each later node up to the root
    bom: bool = False  # the file began with a UTF-8 byte order mark


Details = tuple[Layout, Callable[[], dict[Any, Any]] | None, str | None,
                tuple[str, str] | None]
"""What a reader works out about a file when it is first written (see DocumentPreserved)."""


class Preserved:
    """
    The source element of a model element and a by-value snapshot of what it read.

    A writer compares the element's current fields with ``snapshot``: equal, it writes
    ``node`` as it was; different, it writes the element anew in the layout of ``node``,
    keeping what the model does not hold (unknown attributes and children, comments) and
    the original text of every value nobody changed. The robot's (a
    :class:`DocumentPreserved`) also has ``order``, the document order of its items,
    ``outside``, the comments before and after the root, and ``layout``.
    """

    __slots__ = ('node', 'snapshot')

    order: list[Any] | None = None
    outside: tuple[list[Any], list[Any]] = ([], [])
    layout: Layout = Layout()
    start_tags: dict[Any, tuple[str, tuple[tuple[str, str], ...]]] = {}
    verbatim: tuple[str, str] | None = None

    def __init__(self, node: Any, snapshot: tuple | None = None) -> None:
        self.node = node
        self.snapshot = snapshot

    def writing(self) -> tuple[Layout, str | None]:
        """Return the layout for a writer, and no text of the tree (see the document's)."""
        return self.layout, None

    def __repr__(self) -> str:
        """Return the source tag and line."""
        return f'Preserved(<{self.node.tag}> line {self.node.sourceline})'


class DocumentPreserved(Preserved):
    """
    What a reader kept of the ``<robot>`` element: its items' order, layout, comments.

    ``layout``, ``start_tags`` and ``verbatim`` are only needed to write: ``details``,
    given by the reader, works them out from the source text on first use and is then
    dropped. It returns the layout, a function that finds the start tags (called when
    they are first needed: a file written back unedited may never need them), lxml's
    text of the tree (or None), and ``verbatim``.
    """

    __slots__ = ('order', 'outside', '_layout', '_start_tags', '_find_tags', '_verbatim',
                 '_details')

    def __init__(self, node: Any, order: list[Any], outside: tuple[list[Any], list[Any]],
                 details: Callable[[Any], Details]) -> None:
        super().__init__(node)
        self.order = order
        self.outside = outside
        self._layout = Layout()
        # the source start tags lxml would write otherwise (formats/start_tags.py)
        self._start_tags: dict[Any, tuple[str, tuple[tuple[str, str], ...]]] = {}
        self._find_tags: Callable[[], dict[Any, Any]] | None = None
        self._verbatim: tuple[str, str] | None = None
        self._details: Callable[[Any], Details] | None = details

    def _work_out(self) -> str | None:
        details = self._details
        if details is None:
            return None
        # two threads may both work it out: the same result
        self._layout, self._find_tags, written, self._verbatim = details(self.node)
        self._details = None
        return written

    def writing(self) -> tuple[Layout, str | None]:
        """
        Return the layout, and lxml's text of the tree if this call had to work it out.

        A writer calls it first: the text is the tree as it is now, which the writer may
        use instead of serialising it again.
        """
        written = self._work_out()
        return self._layout, written

    @property
    def layout(self) -> Layout:  # type: ignore[override]
        """Return how the file was written (indentation, line ends, quotes, first lines)."""
        if self._details is not None:
            self._work_out()
        return self._layout

    @property
    def start_tags(  # type: ignore[override]
            self) -> dict[Any, tuple[str, tuple[tuple[str, str], ...]]]:
        """Return the source start tags lxml would write otherwise, by element."""
        if self._details is not None:
            self._work_out()
        find = self._find_tags
        if find is not None:
            self._start_tags = find()
            self._find_tags = None
        return self._start_tags

    @property
    def verbatim(self) -> tuple[str, str] | None:  # type: ignore[override]
        """
        Return lxml's text of the tree as read and the file's own text of the root, or None.

        While lxml writes the tree as it wrote it at first, nothing in it changed: the
        file's text of the root (its line ends as line feeds) is the tree as its author wrote it.
        """
        if self._details is not None:
            self._work_out()
        return self._verbatim
