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
Names belong to the robot: setting ``link.name`` on a link a robot holds renames it there.

Links and joints remember the robot that holds them (``Robot.add_link``/``add_joint``); their
``name`` is a property whose setter goes through ``Robot.rename_link``/``rename_joint``, so
joint ends, mimics, ``<gazebo reference>`` and the robot's index follow. Outside a robot the
name is set as given.
"""

from __future__ import annotations

from typing import Any

from urdfgenpy_ros.model.edits import edited

_SLOTS: dict[type, Any] = {}


def own_names(cls: type, kind: str) -> None:
    """Make ``cls.name`` (a dataclass slot) rename through the robot holding the object."""
    slot = cls.__dict__['name']
    _SLOTS[cls] = slot
    rename = f'rename_{kind}'

    def set_name(self: Any, value: str) -> None:
        robot = getattr(self, '_robot', None)
        if robot is not None:
            try:
                old = slot.__get__(self)
            except AttributeError:  # not set yet (being constructed or unpickled)
                old = None
            if old is not None and old != value and robot._holds(kind, old, self):
                getattr(robot, rename)(old, value)
                return
        slot.__set__(self, value)
        edited()

    setattr(cls, 'name', property(slot.__get__, set_name,
                                  doc=f'The {kind} name; setting it renames the {kind} '
                                  f'everywhere in the robot that holds it.'))


def set_name_only(element: Any, value: str) -> None:
    """Set a link's or joint's name without renaming anything else (for the renamer)."""
    slot = next(_SLOTS[klass] for klass in type(element).__mro__ if klass in _SLOTS)
    slot.__set__(element, value)
    edited()
