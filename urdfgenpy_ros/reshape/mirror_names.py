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
The names a mirrored limb takes: every occurrence of the limb's token, one to one.

A key of the renaming (``left_``) is replaced where it stands as a word of the name: at
its start or after a separator (``_``, ``/``, ``-``, ...), a change between letters and
digits or from lower to upper case, before a capitalised word, and ending likewise (``l_``
is not found in ``roll_link``; ``L`` is found in Romeo's ``LHipYawLink``). Its first
occurrence in a name is the limb's; a later one is the limb's too (ANYmal's
``LF_HIP_LF_hip_fixed`` by ``LF_: RF_`` is ``RF_HIP_RF_hip_fixed``) unless the limb has a
name that differs from this one there, up to the next word (PR2's ``l_gripper_l_finger...``
beside ``l_gripper_r_finger...``, OpenArm's ``openarm_left_left_finger`` beside
``openarm_left_right_finger``): then it tells parts of the limb apart and stays. Two names
of one kind that would become one are refused, naming both.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
import re

from urdfgenpy_ros.errors import ModelError


def _apart(before: str, after: str, following: str = '') -> bool:
    """
    Return whether a word of a name ends between the characters ``before`` and ``after``.

    ``following`` is the character after ``after``: an upper-case letter that starts a
    capitalised word ends the word before it (``L|Hip``, ``LFsr|Center``).
    """
    if not (before.isalnum() and after.isalnum()):
        return True
    return before.isdigit() != after.isdigit() or (before.islower() and after.isupper()) \
        or (before.isupper() and after.isupper() and following.islower())


def _bounded(name: str, index: int) -> bool:
    """Return whether a word of ``name`` starts or ends at ``index``."""
    return index in (0, len(name)) or _apart(name[index - 1], name[index],
                                             name[index + 1:index + 2])


def _occurrences(name: str, keys: list[str]) -> list[tuple[int, str]]:
    """Return ``(index, key)`` of each key standing as a word, left to right, not overlapping."""
    found = []
    index = 0
    while index < len(name):
        for key in keys:  # longest first
            end = index + len(key)
            if name.startswith(key, index) and _bounded(name, index) and _bounded(name, end):
                found.append((index, key))
                index = end
                break
        else:
            index += 1
    return found


def _tells_apart(name: str, index: int, key: str, names: frozenset[str]) -> bool:
    """
    Return whether another name of the limb differs from ``name`` only at ``index``.

    Only up to the next word: PR2's ``l_gripper_l_finger_tip_frame`` has no
    ``l_gripper_r_finger_tip_frame``, but ``l_gripper_r_finger_tip_link`` tells its
    second ``l_`` apart.
    """
    head, tail = name[:index], name[index + len(key):]
    word = re.match(r'[A-Za-z0-9]*[^A-Za-z0-9]?', tail).group()  # type: ignore[union-attr]
    for other in names:
        if other == name or not other.startswith(head):
            continue
        rest = other[len(head):]
        end = rest.find(word, 1) if word else (len(rest) - len(tail) if rest.endswith(tail)
                                               else -1)
        middle = rest[:end] if end > 0 else ''
        if middle and middle != key and '/' not in middle \
                and middle.count('_') == key.count('_'):
            return True
    return False


def limb_renamer(rename: Mapping[str, str], names: Iterable[str]) -> Callable[..., str]:
    """
    Return the renaming of the copy of a limb whose names are ``names`` (see the module).

    An empty key's value goes before every name. The returned function also renames
    texts that hold the limb's names (topics, frames): ``renamed(text, False)`` leaves
    such a prefix out (``<mu1>0.8</mu1>`` is no name).
    """
    keys = sorted((key for key in rename if key), key=len, reverse=True)
    limb = frozenset(names)
    prefix = rename.get('', '')  # an empty key: a prefix before every name

    def renamed(name: str, named: bool = True) -> str:
        parts, start, seen = [prefix if named else ''], 0, set()
        for index, key in _occurrences(name, keys):
            if key in seen and _tells_apart(name, index, key, limb):
                continue
            seen.add(key)
            parts += [name[start:index], rename[key]]
            start = index + len(key)
        return ''.join(parts) + name[start:]
    return renamed


def require_one_to_one(kind: str, renaming: Mapping[str, str],
                       rename: Mapping[str, str]) -> None:
    """
    Refuse a renaming that gives two names of one kind the same new name.

    :raises ModelError: naming both, and the renaming that made them one.
    """
    seen: dict[str, str] = {}
    for old, new in renaming.items():
        other = seen.setdefault(new, old)
        if other != old:
            raise ModelError(f'mirror: {kind}s {other!r} and {old!r} would both be named '
                             f'{new!r} in the copy (pass rename= that tells them apart; '
                             f'it was {dict(rename)!r})')
