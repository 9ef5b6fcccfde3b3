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
Armature: a motor's rotor reflected through its gearbox, and what keeps stiff servos stable.

A transmission that gives a rotor inertia (``rotor_inertia`` as a ``<param>`` or an element
of its ``<actuator>`` or ``<joint>``) gives its joint the armature ``inertia x reduction^2``.

MuJoCo integrates a servo's stiffness explicitly: a position servo of stiffness
``k = kp gear^2`` on a joint of effective inertia ``I`` (its subtree's inertia about the
axis at home, plus the armature) oscillates with ``w = sqrt(k / I)`` and, at timestep
``h``, grows without bound once ``h w`` nears 2 (so does an explicit damping ``kv``:
``h^2 w^2 + 2 h kv gear^2 / I`` past 4). A joint past :data:`STABLE` is given the armature
that brings it back, and a note says so; a joint whose armature the user set is left as
it is and a note names the gain that would be stable.
"""

from __future__ import annotations

from dataclasses import dataclass
import math
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.floats import fmt
from urdfgenpy_ros.model.joint import JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

STABLE = 1.0
"""The largest ``h^2 w^2 + 2 h gamma`` kept: a quarter of the bound, for the coupled joints,
limits and contacts a single joint's figure leaves out."""
TIMESTEP = 0.002  # MuJoCo's default
IMPLICIT = ('implicit', 'implicitfast')  # integrators that take a servo's damping implicitly
_NAMES = ('rotor_inertia', 'rotorInertia')


def rotor_armatures(robot: RobotModel) -> dict[str, float]:
    """Return each joint's reflected rotor inertia (kg m^2), from its transmission."""
    from urdfgenpy_ros.formats.mjcf.actuators import blocks, gears
    reductions = gears(robot)
    found: dict[str, float] = {}
    for tag in ('transmission', 'ros2_control'):
        for block in blocks(robot, tag):
            transmissions = [block] if tag == 'transmission' else block.findall('transmission')
            for transmission in transmissions:
                inertia = _rotor_inertia(transmission)
                for joint in transmission.findall('joint'):
                    name = joint.get('name')
                    value = _rotor_inertia(joint) if inertia is None else inertia
                    if name and value is not None:
                        reduction = reductions.get(name, (1.0, None))[0]
                        found[name] = value * reduction * reduction
    return found


def _rotor_inertia(element: Any) -> float | None:
    """Return the rotor inertia ``element`` (or its ``<actuator>``) gives, else None."""
    for node in element.iter():
        text = None
        if node.tag in _NAMES:
            text = node.text
        elif node.tag == 'param' and node.get('name') in _NAMES:
            text = node.text
        if text is None:
            continue
        try:
            value = float(text.strip())
        except ValueError:
            continue
        if math.isfinite(value) and value > 0.0:
            return value
    return None


def write_rotor_armatures(worldbody: Any, robot: RobotModel) -> list[str]:
    """Set the reflected rotor inertia as each joint's armature; return the note."""
    armatures = rotor_armatures(robot)
    joints = {node.get('name'): node for node in worldbody.iter('joint')}
    said = []
    for name, value in sorted(armatures.items()):
        if name in joints and joints[name].get('armature') is None:
            joints[name].set('armature', fmt(value))
            said.append(f'{name} {fmt(value)}')
    if not said:
        return []
    return ['armature from the transmissions (rotor inertia x reduction^2, kg m^2): '
            + ', '.join(said)]


@dataclass(frozen=True)
class Servo:
    """A position servo on a one-dof joint: its stiffness and damping on the joint."""

    joint: str
    kp: float
    gear: float
    stiffness: float  # kp gear^2
    damping: float  # kv gear^2


def servos(document: Any) -> list[Servo]:
    """Return the position servos of the final document (the overlay's included)."""
    section = document.find('actuator')
    found = []
    for node in (section.iter('position') if section is not None else ()):
        try:
            gear = float((node.get('gear') or '1').split()[0])
            kp = float(node.get('kp') or '1')
            kv = float(node.get('kv') or '0')
        except ValueError:
            continue
        if node.get('joint') and kp > 0.0:
            found.append(Servo(node.get('joint'), kp, gear, kp * gear * gear, kv * gear * gear))
    return found


def stabilise(document: Any, robot: RobotModel, home: dict[str, tuple[float, ...]],
              given: set[str]) -> tuple[list[str], list[str]]:
    """
    Give each servo's joint the armature its gain needs at the model's timestep.

    ``given``: joints whose armature the user set (the URDF's ``<mujoco>`` block, the
    overlay): they keep it, and the advice names the gain that would be stable. Return
    the note of what was added, and the advice (an unstable or undamped servo).
    """
    option = document.find('option')
    timestep = float(option.get('timestep', TIMESTEP)) if option is not None else TIMESTEP
    integrator = option.get('integrator', 'Euler') if option is not None else 'Euler'
    implicit = integrator in IMPLICIT
    joints = {node.get('name'): node for node in document.find('worldbody').iter('joint')}
    inertias = joint_inertias(robot, {servo.joint for servo in servos(document)}, home)
    added, unstable, undamped = [], [], []
    for servo in servos(document):
        node, inertia = joints.get(servo.joint), inertias.get(servo.joint)
        if node is None or inertia is None:
            continue
        armature = float(node.get('armature') or '0')
        damping = 0.0 if implicit else servo.damping
        needed = _needed(servo.stiffness, damping, timestep)
        if servo.damping == 0.0:
            moved = max(inertia + armature, needed) if servo.joint not in given \
                else inertia + armature
            critical = 2.0 * math.sqrt(servo.stiffness * moved) / (servo.gear * servo.gear)
            undamped.append(f'{servo.joint} {_short(critical)}')
        if inertia + armature >= needed:
            continue
        if servo.joint in given:
            stable_kp = servo.kp * (inertia + armature) / needed
            unstable.append(f'joint {servo.joint!r}: kp {fmt(servo.kp)} is unstable at '
                            f'timestep {fmt(timestep)} s on its inertia {_short(inertia)} '
                            f'kg m^2 and the armature given, {fmt(armature)}: kp '
                            f'{_short(stable_kp)} or less, or armature '
                            f'{_short(needed - inertia)}, is stable')
            continue
        node.set('armature', _short(needed - inertia))
        added.append(f'{servo.joint} {_short(needed - inertia)} (inertia {_short(inertia)}, '
                     f'kp {fmt(servo.kp)})')
    advice = unstable
    if undamped:
        advice.append('position servos without damping (kv) oscillate about their target '
                      'and strike their limits: kv= / --kv damps them (critical damping: '
                      + ', '.join(undamped) + ')')
    notes = [f'armature added so that stiff servos on light joints stay stable at timestep '
             f'{fmt(timestep)} s (kg m^2; set <joint armature=> in an overlay to choose '
             'another): ' + ', '.join(added)] if added else []
    return notes, advice


def _needed(stiffness: float, damping: float, timestep: float) -> float:
    """Return the least inertia for which ``h^2 k/I + 2 h c/I`` is at most STABLE."""
    return (timestep * timestep * stiffness + 2.0 * timestep * damping) / STABLE


def _short(value: float) -> str:
    """Return ``value`` to four significant figures (a figure for people, not a model)."""
    return fmt(float(f'{value:.4g}'))


def joint_inertias(robot: RobotModel, names: set[str], home: dict[str, tuple[float, ...]]
                   ) -> dict[str, float]:
    """
    Return each named joint's effective inertia at ``home``: its subtree's about the axis.

    That is the diagonal of the joint-space mass matrix (kg m^2 for a hinge, kg for a
    slide), before armature.
    """
    import numpy
    from urdfgenpy_ros.dynamics import fk, movable_joints
    moving = set(movable_joints(robot))
    poses = fk(robot, {name: value[0] for name, value in home.items()
                       if name in moving and len(value) == 1})
    masses = _world_masses(robot, poses)
    found = {}
    for name in names:
        if not robot.has_joint(name):
            continue
        joint = robot.get_joint(name)
        if joint.type not in (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC):
            continue
        frame = poses[joint.child]
        axis = frame[:3, :3] @ numpy.asarray(joint.effective_axis, dtype=float)
        axis = axis / numpy.linalg.norm(axis)
        total = 0.0
        for link in _subtree(robot, joint.child):
            if link not in masses:
                continue
            mass, centre, tensor = masses[link]
            if joint.type is JointType.PRISMATIC:
                total += mass
                continue
            arm = numpy.cross(axis, centre - frame[:3, 3])
            total += float(axis @ tensor @ axis) + mass * float(arm @ arm)
        found[name] = total
    return found


def _world_masses(robot: RobotModel, poses: Any) -> dict[str, tuple[float, Any, Any]]:
    """Return each link's mass, centre of mass and inertia tensor in the root frame."""
    import numpy
    found = {}
    for link in robot.links:
        inertial = link.inertial
        if inertial is None or inertial.mass <= 0.0:
            continue
        frame = poses[link.name] @ numpy.asarray(inertial.origin.matrix(), dtype=float)
        turn = frame[:3, :3]
        tensor = turn @ numpy.asarray(inertial.tensor, dtype=float) @ turn.T
        found[link.name] = (inertial.mass, frame[:3, 3], tensor)
    return found


def _subtree(robot: RobotModel, link: str) -> list[str]:
    """Return ``link`` and every link below it."""
    found, stack = [], [link]
    while stack:
        name = stack.pop()
        found.append(name)
        stack.extend(joint.child for joint in robot.child_joints(name))
    return found
