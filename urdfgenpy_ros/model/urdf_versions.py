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
URDF versions: what each one adds, what each ROS distribution reads, how urdfdom reads one.

URDF 1.1 adds ``<capsule>`` and ``quat_xyzw`` on any ``<origin>``; URDF 1.2 adds the
``acceleration``, ``deceleration`` and ``jerk`` of a joint ``<limit>``. ROS 2 Jazzy's
urdfdom (and Debian's 3.0.1) read only 1.0; urdfdom 5 and 6 (ROS Rolling) read 1.0 to 1.2.
"""

from __future__ import annotations

from collections.abc import Iterator
import re
from typing import Any, NamedTuple, TYPE_CHECKING

from urdfgenpy_ros.model.geometry import Capsule

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

Version = tuple[int, int]

TARGETS: dict[str, tuple[Version, Version]] = {
    'jazzy': ((1, 0), (1, 0)),
    'rolling': ((1, 0), (1, 2)),
}
"""The URDF versions each ROS distribution's urdfdom reads: lowest, highest."""

DEFAULT_TARGET = 'jazzy'
_NUMBER = re.compile(r'\s*[+-]?\d+')


def parse_version(text: str | None) -> Version | str:
    """
    Return the ``(major, minor)`` of a ``<robot version=...>``, or why urdfdom refuses it.

    No attribute is version 1.0. The rules are urdfdom's: two whole numbers around one dot,
    nothing after the second, neither negative.
    """
    if text is None:
        return (1, 0)
    parts = text.split('.')
    if len(parts) != 2:
        return "the version attribute should be in the form 'x.y'"
    numbers = []
    for part in parts:
        found = _NUMBER.match(part)
        if found is None:
            return "the version attribute should be in the form 'x.y'"
        if found.end() != len(part):
            return 'extra characters after the version number'
        numbers.append(int(found.group()))
    if numbers[0] < 0 or numbers[1] < 0:
        return 'version number must be positive'
    return numbers[0], numbers[1]


def version_text(version: Version) -> str:
    """Return ``(1, 1)`` as ``'1.1'``."""
    return f'{version[0]}.{version[1]}'


class Feature(NamedTuple):
    """One use of something a later URDF version added, where the model holds it."""

    needs: Version  # the first URDF version that has it
    what: str  # e.g. "quat_xyzw on the origin"
    owner: str  # e.g. "joint 'elbow'"
    item: Any  # the model object (its ``source`` locates it)
    path: str  # the element path
    tag: str  # the tag to point at on the source line


def features(robot: RobotModel) -> Iterator[Feature]:
    """Yield every 1.1 and 1.2 feature the robot uses, link by link, then joint by joint."""
    for link in robot.links:
        owner, path = f'link {link.name!r}', f"/robot/link[@name='{link.name}']"
        inertial = link.inertial
        if inertial is not None and inertial.origin.quat_xyzw is not None:
            yield Feature((1, 1), 'quat_xyzw on the inertial origin', owner,
                          inertial.origin, path + '/inertial/origin', 'origin')
        parts = [('visual', item) for item in link.visuals] + \
            [('collision', item) for item in link.collisions]
        for kind, item in parts:
            if item.origin.quat_xyzw is not None:
                yield Feature((1, 1), f'quat_xyzw on the {kind} origin', owner, item.origin,
                              f'{path}/{kind}/origin', 'origin')
            if isinstance(item.geometry, Capsule):
                yield Feature((1, 1), f'<capsule> {kind}', owner, item.geometry,
                              f'{path}/{kind}/geometry/capsule', 'capsule')
    for joint in robot.joints:
        owner, path = f'joint {joint.name!r}', f"/robot/joint[@name='{joint.name}']"
        if joint.origin.quat_xyzw is not None:
            yield Feature((1, 1), 'quat_xyzw on the joint origin', owner, joint.origin,
                          path + '/origin', 'origin')
        limit = joint.limit
        if limit is not None:
            for name in ('acceleration', 'deceleration', 'jerk'):
                if getattr(limit, name) is not None:
                    yield Feature((1, 2), f'limit {name}', owner, limit, path + '/limit',
                                  'limit')


def needed_version(robot: RobotModel) -> Version:
    """Return the lowest URDF version that holds everything the robot uses (one pass)."""
    needed = (1, 0)
    for joint in robot.joints:
        limit = joint.limit
        if limit is not None and (limit.acceleration is not None or
                                  limit.deceleration is not None or limit.jerk is not None):
            return (1, 2)
        if joint.origin_slot.quat_xyzw is not None:  # the slot: no property call
            needed = (1, 1)
    if needed == (1, 1):
        return needed
    for link in robot.links:
        inertial = link.inertial
        if inertial is not None and inertial.origin.quat_xyzw is not None:
            return (1, 1)
        for items in (link.visuals, link.collisions):
            for item in items:
                if item.origin.quat_xyzw is not None or type(item.geometry) is Capsule:
                    return (1, 1)
    return needed
