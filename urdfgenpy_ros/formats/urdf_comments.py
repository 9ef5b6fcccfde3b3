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
The comments of a URDF file that speak to urdfgenpy, as data, found when it is read.

A comment whose text names urdfgenpy (``<!-- urdfgenpy: ignore I205 -->``) is recorded
with its line, whether it comes before the first element, and the element it stands
before: that element's path (the one findings give) and the lines it spans. What such a
comment means is for its reader (:mod:`urdfgenpy_ros.validation.suppressions`).
"""

from __future__ import annotations

from typing import Any

from lxml import etree

from urdfgenpy_ros.model.preserved import Directive

_NAMED = ('link', 'joint', 'material')
_NUMBERED = ('visual', 'collision')


def read_directives(root: Any, text: str) -> list[Directive]:
    """
    Return the comments of ``root``'s document that name urdfgenpy, in document order.

    ``text`` is the file's: most never name urdfgenpy, and are not searched further.
    """
    if '!' not in text or 'urdfgenpy' not in text:  # no comment at all; none names it
        return []
    before = list(root.itersiblings(preceding=True))[::-1]
    leading = {id(node) for node in before}
    for child in root:
        if isinstance(child.tag, str):
            break
        leading.add(id(child))
    found = []
    for node in [*before, *root.iter(etree.Comment)]:
        if not isinstance(node, etree._Comment) or 'urdfgenpy' not in (node.text or ''):
            continue
        target = _next_element(node)
        place = ('', 0, 0) if target is None else (
            _path(target, root), target.sourceline or 0, _last_line(target))
        found.append(Directive(node.sourceline or 0, node.text or '', id(node) in leading,
                               *place))
    return found


def _next_element(node: Any) -> Any:
    """Return the element a comment stands directly before (skipping other comments)."""
    sibling = node.getnext()
    while sibling is not None and not isinstance(sibling.tag, str):
        sibling = sibling.getnext()
    return sibling


def _last_line(node: Any) -> int:
    return max((item.sourceline or 0) for item in node.iter())


def _path(node: Any, root: Any) -> str:
    """Return the element path the validator uses (``/robot/link[@name='arm']/inertial``)."""
    steps = []
    while node is not None and node is not root:
        tag = etree.QName(node).localname
        parent = node.getparent()
        if tag in _NAMED and parent is root:
            steps.append(f"{tag}[@name='{node.get('name', '')}']")
        elif tag in _NUMBERED:
            same = [item for item in parent if isinstance(item.tag, str) and item.tag == tag]
            steps.append(f'{tag}[{same.index(node) + 1}]')
        else:
            steps.append(tag)
        node = parent
    return '/robot' + ''.join(f'/{step}' for step in reversed(steps))
