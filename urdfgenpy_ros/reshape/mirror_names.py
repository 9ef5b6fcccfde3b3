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
is not found in ``roll_link``; ``L`` is found in Romeo's ``LHipYawLink``); a key that
starts a name inside a word (``L`` in ``LF_HIP``) is replaced there, and that word
wherever it stands. Its first occurrence in a name is the limb's; a later one is the
limb's too (ANYmal's ``LF_HIP_LF_hip_fixed`` by ``LF_: RF_`` is ``RF_HIP_RF_hip_fixed``)
unless the robot has a name that differs from this one there, up to the next word (PR2's
``l_gripper_l_finger...`` beside ``l_gripper_r_finger...``, OpenArm's
``openarm_left_left_finger`` beside ``openarm_left_right_finger``): then it tells parts of
the limb apart and stays. Two names of one kind that would become one are refused, naming
both.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
import re

from urdfgenpy_ros.model.errors import ModelError


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


# what follows a token up to the end of the next word (``_shank_`` in ``_shank_fixed``)
_NEXT_WORD = re.compile(r'[^A-Za-z0-9]*[A-Za-z0-9]*[^A-Za-z0-9]?')


def _tells_apart(name: str, index: int, key: str, names: frozenset[str]) -> bool:
    """
    Return whether another name of the limb differs from ``name`` only at ``index``.

    Only up to the next word: PR2's ``l_gripper_l_finger_tip_frame`` has no
    ``l_gripper_r_finger_tip_frame``, but ``l_gripper_r_finger_tip_link`` tells its
    second ``l_`` apart.
    """
    head, tail = name[:index], name[index + len(key):]
    word = _NEXT_WORD.match(tail).group()  # type: ignore[union-attr]
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


def limb_renamer(rename: Mapping[str, str], names: Iterable[str],
                 others: Iterable[str] = ()) -> Callable[..., str]:
    """
    Return the renaming of the copy of a limb whose names are ``names`` (see the module).

    ``others`` are the robot's other names: they too tell the parts of a limb apart (PR2's
    ``l_gripper_r_finger`` when the limb is ``l_gripper_l_finger`` alone).

    An empty key's value goes before every name. The returned function also renames
    texts that hold the limb's names (topics, frames): ``renamed(text, False)`` leaves
    such a prefix out (``<mu1>0.8</mu1>`` is no name).
    """
    limb = frozenset(names)
    every = limb | frozenset(others)
    keys = sorted((key for key in rename if key), key=len, reverse=True)
    words = _leading_words(limb, keys, rename)
    new = {**rename, **words}
    keys = sorted([*keys, *words], key=len, reverse=True)
    prefix = rename.get('', '')  # an empty key: a prefix before every name

    def renamed(name: str, named: bool = True) -> str:
        parts, start, seen = [prefix if named else ''], 0, set()
        for index, key in _occurrences(name, keys):
            if key in seen and _tells_apart(name, index, key, every):
                continue
            seen.add(key)
            parts += [name[start:index], new[key]]
            start = index + len(key)
        return ''.join(parts) + name[start:]
    return renamed


def _leading_words(names: Iterable[str], keys: list[str], rename: Mapping[str, str]
                   ) -> dict[str, str]:
    """
    Return each word a key starts a limb's name inside of, with its new spelling.

    A name starting with a key has it replaced even inside a word, and so has that word
    wherever it stands in the limb's names (``L: R`` makes ANYmal's ``LF_HIP_LF_hip_fixed``
    ``RF_HIP_RF_hip_fixed`` and ``base_LF_HAA`` ``base_RF_HAA``; the simple humanoid's
    ``LARM_LINK1`` ``RARM_LINK1``).
    """
    words: dict[str, str] = {}
    for name in names:
        key = next((key for key in keys if name.startswith(key)), None)
        if key is not None and not _bounded(name, len(key)):
            end = next(index for index in range(len(key) + 1, len(name) + 1)
                       if _bounded(name, index))
            words.setdefault(name[:end], rename[key] + name[len(key):end])
    return words


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
