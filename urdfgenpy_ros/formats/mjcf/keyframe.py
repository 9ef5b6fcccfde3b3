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

Mimic followers follow their leader. Every keyframe holds the robot where it is: its
``ctrl`` gives each position servo its joint's value there (velocity servos and motors 0),
so that resetting to it does not drive the servos to zero.
"""

from __future__ import annotations

from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.formats.mjcf.bodies import BodyTree
from urdfgenpy_ros.model.floats import fmt_vec

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

HOLDING = ('position', 'intvelocity')
"""Actuators whose control is a position: a keyframe's ctrl is the joint's value there."""


def home_positions(tree: BodyTree, robot: RobotModel, initial: dict[str, float] | None = None
                   ) -> dict[str, tuple[float, ...]]:
    """
    Return each MJCF joint's home: zero clamped to its limits, or its ``initial`` value.

    ``initial`` gives a joint's own home (ros2_control's ``initial_value``); a mimic
    follower follows its leader.
    """
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
    return home


def write_keyframe(document: Any, tree: BodyTree, home: dict[str, tuple[float, ...]]
                   ) -> None:
    """Write the ``home`` keyframe: every joint at its ``home`` value."""
    if not tree.joints:
        return
    qpos = [value for joint in tree.joints for value in home[joint.name]]
    keyframe = etree.SubElement(document, 'keyframe')
    etree.SubElement(keyframe, 'key', name='home', qpos=fmt_vec(qpos))


def hold_keyframes(document: Any, tree: BodyTree) -> list[str]:
    """
    Give every keyframe without a ``ctrl`` the one that holds the robot at its ``qpos``.

    Run after the overlay, on the final actuators. Return notes for what it cannot hold
    (a keyframe whose ``qpos`` does not fit the joints, an actuator it cannot aim).
    """
    section = document.find('actuator')
    keyframes = document.findall('keyframe')
    actuators = [node for node in (section if section is not None else ())
                 if isinstance(node.tag, str)]
    if not actuators or not keyframes:
        return []
    widths = [(joint.name, len(joint.home)) for joint in tree.joints]
    notes = []
    for key in (key for keyframe in keyframes for key in keyframe.iter('key')):
        if key.get('ctrl') is not None:
            continue
        values = _joint_values(key.get('qpos'), widths)
        if values is None:
            notes.append(f"keyframe {key.get('name', '(unnamed)')!r}: its qpos does not fit "
                         'the joints, so it has no ctrl: its servos drive to zero on reset')
            continue
        ctrl = []
        for actuator in actuators:
            ctrl.append(_target(actuator, values))
            if actuator.tag not in HOLDING and actuator.tag not in ('velocity', 'motor'):
                notes.append(f"keyframe {key.get('name', '(unnamed)')!r}: ctrl 0 for "
                             f"<{actuator.tag} name={actuator.get('name')!r}>, whose control"
                             ' is not a joint position')
        key.set('ctrl', fmt_vec(ctrl))
    return notes


def _joint_values(qpos: str | None, widths: list[tuple[str, int]]
                  ) -> dict[str, list[float]] | None:
    """Return ``qpos`` split by joint (absent: zeros), or None when it does not fit."""
    total = sum(width for _, width in widths)
    try:
        numbers = [float(word) for word in qpos.split()] if qpos else [0.0] * total
    except ValueError:
        return None
    if len(numbers) != total:
        return None
    values, at = {}, 0
    for name, width in widths:
        values[name], at = numbers[at:at + width], at + width
    return values


def _target(actuator: Any, values: dict[str, list[float]]) -> float:
    """Return the control that holds ``actuator``'s joint at ``values`` (0 for others)."""
    joint = values.get(actuator.get('joint', ''))
    if actuator.tag not in HOLDING or joint is None or len(joint) != 1:
        return 0.0
    try:  # the overlay's text is MuJoCo's to judge: a word that is no number aims nothing
        gear = float((actuator.get('gear') or '1').split()[0])
        span = [float(word) for word in (actuator.get('ctrlrange') or '').split()]
    except ValueError:
        return 0.0
    target = gear * joint[0]
    if len(span) == 2 and span[0] < span[1]:
        target = min(max(target, span[0]), span[1])
    return target


def _within(joint: Any, value: float) -> float:
    """Return ``value`` clamped to the limits of ``joint`` (when it has a range)."""
    limit = joint.limit
    if limit is not None and joint.type.needs_limit and limit.lower < limit.upper:
        return min(max(value, limit.lower), limit.upper)
    return value
