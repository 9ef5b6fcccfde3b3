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
Actuators from what the robot declares.

Each ``<ros2_control>`` ``<joint>`` command interface becomes an actuator on that joint:
``position`` a position servo, ``velocity`` a velocity servo, ``effort`` a motor. The
control range is the interface's ``min``/``max`` parameters, else the joint's limits
(position: lower/upper, velocity: +-velocity, effort: +-effort). A ``<transmission>`` on
the joint gives the ``gear`` (its ``mechanicalReduction``); MuJoCo's control is then in
actuator units, so a servo's range is multiplied by it. The gains MuJoCo needs and URDF
does not hold (``kp``, ``kv``) come from the options, per joint or for all. Mimic
followers are never actuated.
"""

from __future__ import annotations

from dataclasses import dataclass
import math
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.formats.mjcf.gains import Gains
from urdfgenpy_ros.model.floats import fmt, fmt_vec
from urdfgenpy_ros.model.joint import Joint, JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

KINDS = {'position': 'position', 'velocity': 'velocity', 'effort': 'motor'}
"""ros2_control command interface -> MJCF actuator."""
ACTUATOR_TYPES = ('position', 'velocity', 'motor')
_ONE_DOF = (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC)


@dataclass
class Actuator:
    """One actuator to write: kind, joint, control range, gear and where it came from."""

    kind: str  # position, velocity, motor
    joint: Joint
    ctrlrange: tuple[float, float] | None
    gear: float
    origin: tuple[int, int] | None  # (ros2_control block, element number), None: option
    line: int | None = None  # the command interface's line, when it was read


def _number(element: Any, name: str) -> float | None:
    for param in element.findall('param'):
        if param.get('name') == name:
            try:
                return float((param.text or '').strip())
            except ValueError:
                return None
    return None


def blocks(robot: RobotModel, tag: str) -> list[Any]:
    """Return the elements of the robot's ``tag`` blocks, in order."""
    return [block.element for block in robot.extensions if block.tag == tag]


def gears(robot: RobotModel) -> dict[str, tuple[float, Any]]:
    """
    Return each joint's mechanical reduction and which transmission gave it.

    A classic ``<transmission>`` (``mechanicalReduction``) is named by its number among
    them; one inside ``<ros2_control>`` (``mechanical_reduction`` of its ``<joint>``, else
    of its ``<actuator>``) by (the block's number, its element number), as interfaces are.
    """
    found: dict[str, tuple[float, Any]] = {}
    for number, element in enumerate(blocks(robot, 'transmission')):
        joints = [node.get('name') for node in element.findall('joint')]
        reductions = [node.findtext('mechanicalReduction') for node in element.iter()
                      if node.findtext('mechanicalReduction') is not None]
        value = _reduction(reductions)
        for name in joints:
            if name:
                found[name] = (value, number)
    for number, block in enumerate(blocks(robot, 'ros2_control')):
        elements = list(block.iter())
        for element in block.findall('transmission'):
            for joint in element.findall('joint'):
                reductions = [node.findtext('mechanical_reduction')
                              for node in (joint, *element.findall('actuator'))
                              if node.findtext('mechanical_reduction') is not None]
                if joint.get('name'):
                    found[joint.get('name')] = (_reduction(reductions),
                                                (number, elements.index(element)))
    return found


def _reduction(texts: list[str | None]) -> float:
    """Return the first reduction of ``texts`` that is a non-zero number, else 1."""
    for text in texts:
        try:
            value = float((text or '').strip())
        except ValueError:
            continue
        if value != 0.0:
            return value
    return 1.0


def initial_values(robot: RobotModel) -> dict[str, float]:
    """
    Return each joint's ros2_control ``initial_value`` (its position state interface's).

    A ``<param name="initial_value">`` straight under the ``<joint>`` counts too.
    """
    found: dict[str, float] = {}
    for block in blocks(robot, 'ros2_control'):
        for joint in block.findall('joint'):
            places = [joint] + [interface for interface in joint.findall('state_interface')
                                if interface.get('name') == 'position']
            for place in places:
                value = _number(place, 'initial_value')
                if value is not None and math.isfinite(value) and joint.get('name'):
                    found[joint.get('name')] = value
    return found


def _range(kind: str, joint: Joint, element: Any) -> tuple[float, float] | None:
    low = _number(element, 'min') if element is not None else None
    high = _number(element, 'max') if element is not None else None
    if low is not None and high is not None and low < high:
        return low, high
    limit = joint.limit
    if limit is None:
        return None
    if kind == 'position':
        if joint.type is JointType.CONTINUOUS or not limit.lower < limit.upper:
            return None
        return limit.lower, limit.upper
    value = limit.velocity if kind == 'velocity' else limit.effort
    return (-value, value) if value > 0.0 else None


def declared_actuators(robot: RobotModel, kind: str | None) -> list[Actuator]:
    """
    Return the actuators: from ``<ros2_control>``, or ``kind`` on every joint when given.

    ``kind`` (position, velocity, motor) replaces what ``<ros2_control>`` declares.
    """
    reductions = gears(robot)
    followers = {joint.name for joint in robot.joints if joint.mimic is not None}
    found: list[Actuator] = []

    def add(name: str, what: str, element: Any, origin: tuple[int, int] | None) -> None:
        if not robot.has_joint(name) or name in followers:
            return
        joint = robot.get_joint(name)
        if joint.type not in _ONE_DOF:
            return
        gear = reductions.get(name, (1.0, None))[0]
        span = _range(what if what != 'motor' else 'effort', joint, element)
        if span is not None and what != 'motor':
            low, high = span[0] * gear, span[1] * gear
            span = (min(low, high), max(low, high))
        found.append(Actuator(what, joint, span, gear, origin,
                              getattr(element, 'sourceline', None)))

    if kind is not None:
        for joint in robot.joints:
            add(joint.name, kind, None, None)
        return found
    for number, block in enumerate(blocks(robot, 'ros2_control')):
        elements = list(block.iter())
        for index, interface in enumerate(elements):
            parent = interface.getparent()
            if interface.tag != 'command_interface' or parent is None \
                    or parent.tag != 'joint':
                continue
            what = KINDS.get(interface.get('name', ''))
            if what is not None:
                add(parent.get('name', ''), what, interface, (number, index))
    return found


def write_actuators(parent: Any, actuators: list[Actuator], kp: Gains, kv: Gains,
                    defaults: tuple[float, float] = (1.0, 1.0)) -> None:
    """
    Add an ``<actuator>`` section holding ``actuators`` to ``parent``.

    A position servo takes its joint's ``kp`` and, when given, its ``kv`` as damping; a
    velocity servo its ``kv``; ``defaults`` are the (kp, kv) of joints given none.
    """
    if not actuators:
        return
    section = etree.SubElement(parent, 'actuator')
    taken: set[str] = set()
    for actuator in actuators:
        name = f'{actuator.joint.name}_{actuator.kind}'
        number = 2
        while name in taken:
            name, number = f'{actuator.joint.name}_{actuator.kind}_{number}', number + 1
        taken.add(name)
        attributes = {'name': name, 'joint': actuator.joint.name}
        if actuator.gear != 1.0:
            attributes['gear'] = fmt(actuator.gear)
        if actuator.ctrlrange is not None:
            attributes['ctrlrange'] = fmt_vec(actuator.ctrlrange)
        stiffness, damping = kp.of_joint(actuator.joint.name), kv.of_joint(actuator.joint.name)
        if actuator.kind == 'position':
            attributes['kp'] = fmt(stiffness if stiffness is not None else defaults[0])
            if damping is not None:
                attributes['kv'] = fmt(damping)
        elif actuator.kind == 'velocity':
            attributes['kv'] = fmt(damping if damping is not None else defaults[1])
        etree.SubElement(section, actuator.kind, attributes)
