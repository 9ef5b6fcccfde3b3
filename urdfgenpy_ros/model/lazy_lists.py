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
List fields made on first use: ``link.extensions`` and ``link.sensors``, say.

Most links and joints never hold a ``<gazebo>`` block or a sensor. A new one stores None
and the list is made when the field is first read, so building a robot of thousands of
links does not make (and the garbage collector does not walk) thousands of empty lists.
Reading the field always gives the object's own list, so ``link.extensions.append(block)``
works as with a plain list field. ``link.extensions_if_any`` reads the same slot without
making a list: the list, or None (writers use it).
"""

from __future__ import annotations

from typing import Any, TYPE_CHECKING

if TYPE_CHECKING:
    from urdfgenpy_ros.model.extensions import Extension
    from urdfgenpy_ros.model.sensors import Sensor

    class LazySlots:
        """What lazy_lists and own_names give a link or joint, as type checkers see it."""

        @property
        def extensions_if_any(self) -> list[Extension] | None:
            """Return the ``extensions`` list, or None if none was made yet."""

        @extensions_if_any.setter
        def extensions_if_any(self, value: list[Extension] | None) -> None:
            """Set the ``extensions`` slot itself (None: made on first use)."""

        @property
        def sensors_if_any(self) -> list[Sensor] | None:
            """Return the ``sensors`` list, or None if none was made yet."""

        @sensors_if_any.setter
        def sensors_if_any(self, value: list[Sensor] | None) -> None:
            """Set the ``sensors`` slot itself (None: made on first use)."""

        @property
        def name_slot(self) -> str:
            """Return the name's slot, set without renaming (constructors)."""

        @name_slot.setter
        def name_slot(self, value: str) -> None:
            """Set the name's slot itself."""
else:
    class LazySlots:
        """Nothing at run time: lazy_lists and own_names set these on the class itself."""

        __slots__ = ()


class LazyList:
    """The descriptor of one list field, over the dataclass slot that stores it."""

    __slots__ = ('_get', '_set')

    def __init__(self, slot: Any) -> None:
        self._get = slot.__get__
        self._set = slot.__set__

    def __get__(self, owner: Any, kind: type | None = None) -> Any:
        if owner is None:
            return self
        items = self._get(owner, kind)
        if items is None:
            items = []
            self._set(owner, items)
        return items

    def __set__(self, owner: Any, value: Any) -> None:
        self._set(owner, value)


def lazy_lists(cls: type, *names: str) -> None:
    """
    Make each named list field of the slotted dataclass ``cls`` a :class:`LazyList`.

    The slot itself stays readable as ``<name>_if_any``: the list, or None if none was
    made yet (a read that makes nothing, at the speed of a plain attribute).
    """
    for name in names:
        slot = cls.__dict__[name]
        setattr(cls, name, LazyList(slot))
        setattr(cls, f'{name}_if_any', slot)
