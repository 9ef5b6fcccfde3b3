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
A cheap fingerprint of a link, joint or material, to tell whether it changed since it was read.

Frozen parts (origins, shapes, materials) count by identity: replacing one is a change.
Mutable parts (inertials, limits, lists of visuals) count by value.
"""

from __future__ import annotations

from typing import Any

from urdfgenpy_ros.joint import Joint
from urdfgenpy_ros.link import Link
from urdfgenpy_ros.material import Material


def _fields(item: Any, names: tuple[str, ...]) -> tuple:
    return tuple(getattr(item, name) for name in names) if item is not None else ()


_INERTIAL = ('mass', 'ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz', 'origin', 'extras')
_LIMIT = ('lower', 'upper', 'effort', 'velocity', 'extras')


def state(item: Link | Joint | Material) -> tuple:
    """Return the fingerprint of ``item`` (equal fingerprints: nothing was edited)."""
    if isinstance(item, Link):
        return (item.name, item.extras, _fields(item.inertial, _INERTIAL),
                tuple((id(v.geometry), id(v.origin), id(v.material), v.name, id(v.extras))
                      for v in item.visuals),
                tuple((id(c.geometry), id(c.origin), c.name, id(c.extras))
                      for c in item.collisions),
                len(item.sensors))
    if isinstance(item, Joint):
        return (item.name, item.type, item.parent, item.child, id(item.origin), item.axis,
                item.extras, _fields(item.limit, _LIMIT),
                _fields(item.dynamics, ('damping', 'friction', 'extras')),
                _fields(item.mimic, ('joint', 'multiplier', 'offset', 'extras')),
                _fields(item.safety_controller, ('soft_lower_limit', 'soft_upper_limit',
                                                 'k_position', 'k_velocity', 'extras')),
                _fields(item.calibration, ('rising', 'falling', 'extras')),
                len(item.sensors))
    return (id(item),)
