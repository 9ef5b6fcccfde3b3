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
Regenerate an SRDF's collision matrix in place, keeping everything written by hand.

Only the ``<disable_collisions>`` lines whose reason is one of the computed ones
(Adjacent, Default, Always, Never) are the matrix's; everything else (groups, states, end
effectors, comments, layout, pairs disabled for another reason such as ``User``) is
copied byte for byte. A computed line that still holds is kept as it is; one whose
reason changed gets the new reason in place; one that no longer holds is removed with its
line; new pairs are added after the last ``<disable_collisions>``, in its indentation and
quotes. An unchanged matrix gives the file back byte for byte.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from os import PathLike
from pathlib import Path
import re
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.model.errors import ModelError, ParseError
from urdfgenpy_ros.moveit.collision_matrix import CollisionMatrix, compute_matrix, pair
from urdfgenpy_ros.moveit.collision_matrix import Reason
from urdfgenpy_ros.moveit.contacts import Pair

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

_ELEMENT = re.compile(r'<disable_collisions\b[^>]*?/>|<disable_collisions\b.*?'
                      r'</disable_collisions\s*>', re.S)
_COMMENT = re.compile(r'<!--.*?-->', re.S)
_ATTRIBUTE = re.compile(r"""\b(link1|link2|reason)\s*=\s*(["'])(.*?)\2""", re.S)
_COMPUTED = {reason.value for reason in Reason}


@dataclass
class Update:
    """The updated text, and what changed in the matrix."""

    text: str
    added: list[tuple[Pair, str]] = field(default_factory=list)
    removed: list[tuple[Pair, str]] = field(default_factory=list)
    changed: list[tuple[Pair, str, str]] = field(default_factory=list)

    def lines(self) -> list[str]:
        """Return one line per change, for the user."""
        return ([f'added {a} {b} ({reason})' for (a, b), reason in self.added]
                + [f'removed {a} {b} ({reason})' for (a, b), reason in self.removed]
                + [f'changed {a} {b} ({old} -> {new})' for (a, b), old, new in self.changed])


def _entries(text: str) -> list[tuple[int, int, dict[str, str]]]:
    """Return each ``<disable_collisions>`` outside comments: start, end, attributes."""
    comments = [(m.start(), m.end()) for m in _COMMENT.finditer(text)]
    found = []
    for match in _ELEMENT.finditer(text):
        if any(start <= match.start() < end for start, end in comments):
            continue
        attributes = {m.group(1): m.group(3) for m in _ATTRIBUTE.finditer(match.group())}
        found.append((match.start(), match.end(), attributes))
    return found


def update_text(text: str, matrix: CollisionMatrix, file: str = '<srdf>') -> Update:
    """Return ``text`` with its computed pairs replaced by ``matrix``'s (see the module)."""
    end_tag = text.rfind('</robot>')
    if end_tag < 0:
        raise ParseError(f'{file}: no </robot> closes the SRDF (give an SRDF file)')
    wanted = {key: reason.value for key, reason in matrix.disabled.items()}
    update, edits, seen = Update(text), [], set()
    entries = _entries(text)
    for start, end, attributes in entries:
        reason = attributes.get('reason', '')
        if reason not in _COMPUTED or 'link1' not in attributes or 'link2' not in attributes:
            continue  # written by hand: kept
        key = pair(attributes['link1'], attributes['link2'])
        if key in wanted and key not in seen:
            seen.add(key)
            if wanted[key] != reason:
                element = text[start:end]
                new = re.sub(r"""(\breason\s*=\s*["'])[^"']*""", r'\g<1>' + wanted[key],
                             element, count=1)
                edits.append((start, end, new))
                update.changed.append((key, reason, wanted[key]))
            continue
        edits.append(_line_span(text, start, end) + ('',))
        update.removed.append((key, reason))
    missing = [(key, reason) for key, reason in wanted.items() if key not in seen]
    if missing:
        at, indent, quote = _insertion(text, entries, end_tag)
        lines = ''.join(f'{indent}<disable_collisions link1={quote}{a}{quote} link2={quote}'
                        f'{b}{quote} reason={quote}{reason}{quote}/>\n'
                        for (a, b), reason in missing)
        edits.append((at, at, lines))
        update.added = missing
    for start, end, new in sorted(edits, reverse=True):
        text = text[:start] + new + text[end:]
    update.text = text
    return update


def _line_span(text: str, start: int, end: int) -> tuple[int, int]:
    """Return the whole line(s) of an element alone on its line, else just the element."""
    line_start = text.rfind('\n', 0, start) + 1
    line_end = text.find('\n', end)
    line_end = len(text) if line_end < 0 else line_end + 1
    if text[line_start:start].strip() or text[end:line_end].strip():
        return start, end
    return line_start, line_end


def _insertion(text: str, entries: list[tuple[int, int, dict[str, str]]], end_tag: int
               ) -> tuple[int, str, str]:
    """Return where new lines go, their indentation and quote character."""
    if entries:
        start, end, _ = entries[-1]
        line_start = text.rfind('\n', 0, start) + 1
        line_end = text.find('\n', end)
        indent = text[line_start:start] if not text[line_start:start].strip() else '    '
        quote = "'" if re.search(r"""link1\s*=\s*'""", text[start:end]) else '"'
        return (len(text) if line_end < 0 else line_end + 1), indent, quote
    line_start = text.rfind('\n', 0, end_tag) + 1
    match = re.search(r'\n([ \t]+)<', text)
    return line_start, match.group(1) if match else '    ', '"'


def file_state(text: str, name: str, file: str) -> dict[str, float]:
    """Return the joint values of the file's group states called ``name``."""
    try:
        root = etree.fromstring(text.encode('utf-8'))
    except etree.XMLSyntaxError as error:
        raise ParseError(f'{file}: cannot read the SRDF: {error} (give an SRDF file)'
                         ) from None
    values = {str(joint.get('name')): float(joint.get('value', 'nan'))
              for state in root.iter('group_state') if state.get('name') == name
              for joint in state.iter('joint')}
    if not values:
        known = sorted({str(state.get('name')) for state in root.iter('group_state')})
        raise ModelError(f'{file}: no group state {name!r} (its states: {", ".join(known)})')
    return values


def update_srdf(robot: RobotModel, existing: str | PathLike[str], samples: int = 10000,
                seed: int = 0, default_state: str | Mapping[str, float] | None = None,
                search_paths: Any = ()) -> Update:
    """Return the SRDF at ``existing`` with the collision matrix of ``robot`` recomputed."""
    path = Path(existing)
    text = path.read_bytes().decode('utf-8', 'surrogateescape')
    values = file_state(text, default_state, str(path)) if isinstance(default_state, str) \
        else default_state
    matrix = compute_matrix(robot, samples, seed, values, search_paths)
    return update_text(text, matrix, str(path))
