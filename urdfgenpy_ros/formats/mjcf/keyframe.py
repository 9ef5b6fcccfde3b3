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
The ``home`` keyframe: ros2_control's ``initial_value`` or zero, within the limits.

Mimic followers follow their leader.
"""

from __future__ import annotations

from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.floats import fmt_vec
from urdfgenpy_ros.formats.mjcf.bodies import BodyTree

if TYPE_CHECKING:
    from urdfgenpy_ros.robot import Robot


def write_keyframe(document: Any, tree: BodyTree, robot: Robot,
                   initial: dict[str, float] | None = None) -> None:
    """
    Write the ``home`` keyframe: every joint at zero, clamped to its limits.

    ``initial`` gives a joint's own home instead (ros2_control's ``initial_value``).
    """
    if not tree.joints:
        return
    home = {joint.name: joint.home for joint in tree.joints}
    for name, value in (initial or {}).items():
        if name in home and len(home[name]) == 1:
            home[name] = (_within(robot.get_joint(name), value),)
    for joint in robot.joints:
        mimic = joint.mimic
        if mimic is not None and joint.name in home and mimic.joint in home \
                and len(home[joint.name]) == 1:
            value = mimic.offset + mimic.multiplier * home[mimic.joint][0]
            home[joint.name] = (_within(joint, value),)
    qpos = [value for joint in tree.joints for value in home[joint.name]]
    keyframe = etree.SubElement(document, 'keyframe')
    etree.SubElement(keyframe, 'key', name='home', qpos=fmt_vec(qpos))


def _within(joint: Any, value: float) -> float:
    """Return ``value`` clamped to the limits of ``joint`` (when it has a range)."""
    limit = joint.limit
    if limit is not None and joint.type.needs_limit and limit.lower < limit.upper:
        return min(max(value, limit.lower), limit.upper)
    return value
