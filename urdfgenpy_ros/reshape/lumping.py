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
Merge links joined by fixed joints, as SDFormat's URDF conversion does.

The child's visuals, collisions, sensors (also those in its ``<gazebo>`` blocks) and joints
move onto the parent with their poses composed; the inertials combine (masses add, the
centre of mass is their weighted mean, and the tensors are turned into the parent's frame
and shifted there by the parallel axis theorem).
"""

from __future__ import annotations

import copy
import math
from typing import TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.extensions import Extension
from urdfgenpy_ros.model.floats import fmt_vec
from urdfgenpy_ros.model.geometry import Origin
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.joint import Joint, JointType
from urdfgenpy_ros.model.link import Link, Shape
from urdfgenpy_ros.model.transforms import (
    from_xyz_rpy, IDENTITY4, Matrix4, multiply, to_xyz_rpy)

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotT

WORLD = 'world'
"""The link name URDF uses for the world frame; SDF reserves it."""


def _compose(outer: Origin, inner: Origin) -> Origin:
    xyz, rpy = to_xyz_rpy(multiply(from_xyz_rpy(outer.xyz, outer.rpy),
                                   from_xyz_rpy(inner.xyz, inner.rpy)))
    return Origin(xyz, rpy)


def _move_sensor_blocks(blocks: list[Extension], at: Origin, link: str) -> None:
    """
    Compose the ``<pose>`` of each ``<sensor>`` in ``blocks`` with ``at``, as SDFormat does.

    A pose with ``relative_to`` names its frame already and stays as it is.
    """
    for block in blocks:
        for sensor in block.element.findall('sensor'):
            pose = sensor.find('pose')
            if pose is not None and pose.get('relative_to'):
                continue
            values = (pose.text or '').split() if pose is not None else ['0'] * 6
            try:
                numbers = [float(value) for value in values]
            except ValueError:
                numbers = []
            if len(numbers) != 6 or (pose is not None and pose.get('rotation_format')
                                     not in (None, 'euler_rpy')):
                raise ModelError(f"link {link!r}: sensor {sensor.get('name')!r} has pose "
                                 f"{(pose.text or '').strip()!r}, not 'x y z roll pitch yaw': "
                                 'write six numbers to merge it into the parent link')
            if pose is not None and pose.get('degrees', '').strip().lower() in ('true', '1'):
                numbers[3:] = [math.radians(angle) for angle in numbers[3:]]
                del pose.attrib['degrees']
            moved = _compose(at, Origin(tuple(numbers[:3]), tuple(numbers[3:])))
            if pose is None:
                pose = etree.SubElement(sensor, 'pose')
            pose.text = f'{fmt_vec(moved.xyz)} {fmt_vec(moved.rpy)}'


def _tensor_in(inertial: Inertial, frame: Matrix4) -> tuple[list[float], list[list[float]]]:
    """Return the centre of mass and the tensor of ``inertial`` in the frame ``frame`` is in."""
    pose = multiply(frame, from_xyz_rpy(inertial.origin.xyz, inertial.origin.rpy))
    rotation = [row[:3] for row in pose[:3]]
    tensor = [list(row) for row in inertial.tensor]
    turned = [[sum(rotation[i][k] * tensor[k][m] * rotation[j][m] for k in range(3)
                   for m in range(3)) for j in range(3)] for i in range(3)]
    return [pose[0][3], pose[1][3], pose[2][3]], turned


def combine(parts: list[tuple[Inertial, Matrix4]]) -> Inertial | None:
    """Return the inertial of rigidly joined parts, each given in the common frame."""
    parts = [(inertial, frame) for inertial, frame in parts if inertial.mass > 0.0]
    if not parts:
        return None
    mass = sum(inertial.mass for inertial, _ in parts)
    placed = [(inertial.mass, *_tensor_in(inertial, frame)) for inertial, frame in parts]
    centre = [sum(m * c[i] for m, c, _ in placed) / mass for i in range(3)]
    total = [[0.0] * 3 for _ in range(3)]
    for m, c, tensor in placed:
        d = [c[i] - centre[i] for i in range(3)]
        square = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
        for i in range(3):
            for j in range(3):
                total[i][j] += tensor[i][j] + m * ((square if i == j else 0.0) - d[i] * d[j])
    return Inertial(mass, total[0][0], total[0][1], total[0][2], total[1][1], total[1][2],
                    total[2][2], origin=Origin(tuple(centre)))


def lumps(joint: Joint) -> bool:
    """
    Return whether SDFormat's URDF conversion merges ``joint``'s child into its parent.

    It keeps a fixed joint to the ``world`` frame, and one its ``<gazebo reference>`` block
    asks to keep (``preserveFixedJoint`` or ``disableFixedJointLumping`` set to true).
    """
    if joint.type is not JointType.FIXED or joint.parent == WORLD:
        return False
    for block in joint.extensions:
        for tag in ('preserveFixedJoint', 'disableFixedJointLumping'):
            value = block.element.findtext(tag)
            if value is not None and value.strip().lower() in ('true', '1'):
                return False
    return True


def move_contents(body: Link, child: Link, pose: Matrix4, at: Origin, *,
                  everything: bool = True, name_shapes: bool = False) -> None:
    """
    Move ``child``'s mass, visuals and collisions onto ``body``, ``child`` being at ``pose``.

    ``at`` is ``pose`` as an origin. With ``everything``, its sensors and sensor blocks
    move too (the child goes); ``name_shapes`` gives an unnamed visual or collision the
    child's name, as Gazebo's lumping names it.
    """
    parts = [(body.inertial, IDENTITY4)] if body.inertial is not None else []
    if child.inertial is not None:
        parts.append((child.inertial, pose))
    body.inertial = combine(parts) if parts else None
    child.inertial = None
    items: tuple[Shape, ...] = (*child.visuals, *child.collisions)
    for item in items:
        item.origin = _compose(at, item.origin)
        if name_shapes and not item.name:
            item.name = child.name
    body.visuals.extend(child.visuals)
    body.collisions.extend(child.collisions)
    child.visuals.clear()
    child.collisions.clear()
    if not everything:
        return
    for sensor in child.sensors:
        sensor.origin = _compose(at, sensor.origin)
        sensor.frame = body.name
        body.sensors.append(sensor)
    _move_sensor_blocks(child.extensions, at, child.name)
    body.extensions.extend(child.extensions)


def lump_fixed_joints(robot: RobotT) -> RobotT:
    """Return a copy of ``robot`` with fixed joints' children merged into their parents."""
    merged = copy.deepcopy(robot)
    while True:
        joint = next((j for j in merged.joints if lumps(j)), None)
        if joint is None:
            return merged
        parent, child = merged.get_link(joint.parent), merged.get_link(joint.child)
        at = joint.origin
        move_contents(parent, child, from_xyz_rpy(at.xyz, at.rpy), at)
        for grandchild in merged.child_joints(child.name):
            grandchild.parent = parent.name
            grandchild.origin = _compose(at, grandchild.origin)
        merged.remove_joint(joint.name)
        merged.remove_link(child.name)
