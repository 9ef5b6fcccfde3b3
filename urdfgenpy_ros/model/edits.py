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
A count of the edits that can change any robot's tree, for caches to check in one read.

Adding, removing or renaming a link or joint, and setting a joint's type, ends, origin,
axis or mimic, add one to :data:`count` (whatever robot the object is in, if any). A
cache keeps the count it was made at: while it is unchanged, no robot's tree changed
(masses are not counted: they are read where they are used).
"""

from __future__ import annotations

from typing import Any

count = 0
"""How many such edits there have been in this process."""


def edited() -> None:
    """Count one edit."""
    global count
    count += 1


def counted(cls: type, *names: str) -> None:
    """
    Make setting each named slot of ``cls`` count an edit (reading it stays a slot read).

    The slot itself stays settable as ``<name>_slot``, counting nothing (constructors).
    """
    for name in names:
        slot = cls.__dict__[name]
        setattr(cls, name, property(slot.__get__, _setter(slot.__set__),
                                    doc=getattr(slot, '__doc__', None)))
        setattr(cls, f'{name}_slot', slot)


def _setter(set_slot: Any) -> Any:
    def set_value(owner: Any, value: Any) -> None:
        global count
        set_slot(owner, value)
        count += 1
    return set_value
