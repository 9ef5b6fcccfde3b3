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
Joint transforms as robot_state_publisher publishes them, and link poses from them.

Each joint gives the transform from its parent link to its child link: the joint origin,
then the motion (a turn about the axis for revolute and continuous joints, a shift along
it for prismatic ones). Floating and planar joints are published at their origin, as
robot_state_publisher does. Rotations are quaternions ``(x, y, z, w)``.
"""

from __future__ import annotations

from collections.abc import Mapping
import math
from typing import TYPE_CHECKING

from urdfgenpy_ros.model.joint import JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

Vector = tuple[float, float, float]
Quaternion = tuple[float, float, float, float]
Transform = tuple[str, str, Vector, Quaternion]  # parent, child, translation, rotation


def quaternion_from_rpy(roll: float, pitch: float, yaw: float) -> Quaternion:
    """Return the quaternion of URDF's fixed-axis rpy (Rz(yaw) Ry(pitch) Rx(roll))."""
    cr, sr = math.cos(roll / 2.0), math.sin(roll / 2.0)
    cp, sp = math.cos(pitch / 2.0), math.sin(pitch / 2.0)
    cy, sy = math.cos(yaw / 2.0), math.sin(yaw / 2.0)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def multiply(a: Quaternion, b: Quaternion) -> Quaternion:
    """Return the Hamilton product ``a b``."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz)


def rotate(q: Quaternion, v: Vector) -> Vector:
    """Return ``v`` turned by the unit quaternion ``q``."""
    x, y, z, w = q
    tx, ty, tz = 2.0 * (y * v[2] - z * v[1]), 2.0 * (z * v[0] - x * v[2]), \
        2.0 * (x * v[1] - y * v[0])
    return (v[0] + w * tx + y * tz - z * ty, v[1] + w * ty + z * tx - x * tz,
            v[2] + w * tz + x * ty - y * tx)


class JointTransforms:
    """The transform of every joint of a robot, fixed ones once, moving ones per state."""

    def __init__(self, robot: RobotModel) -> None:
        self.static: list[Transform] = []
        self._moving: list[tuple[str, str, str, Vector, Quaternion, Vector, bool]] = []
        for joint in robot.joints:
            origin = joint.origin
            rotation = quaternion_from_rpy(*origin.rpy)
            if joint.type in (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC):
                axis = joint.effective_axis
                norm = math.sqrt(sum(value * value for value in axis)) or 1.0
                self._moving.append((joint.name, joint.parent, joint.child, origin.xyz,
                                     rotation, (axis[0] / norm, axis[1] / norm,
                                                axis[2] / norm),
                                     joint.type is JointType.PRISMATIC))
            else:
                self.static.append((joint.parent, joint.child, origin.xyz, rotation))

    @property
    def moving_joints(self) -> list[str]:
        """Return the names of the joints whose transform depends on the state."""
        return [entry[0] for entry in self._moving]

    def moving(self, positions: Mapping[str, float]) -> list[Transform]:
        """Return the transforms of the moving joints at ``positions`` (missing: 0)."""
        result = []
        for name, parent, child, xyz, rotation, axis, prismatic in self._moving:
            value = positions.get(name, 0.0)
            if prismatic:
                shift = rotate(rotation, (axis[0] * value, axis[1] * value, axis[2] * value))
                result.append((parent, child, (xyz[0] + shift[0], xyz[1] + shift[1],
                                               xyz[2] + shift[2]), rotation))
            else:
                s = math.sin(value / 2.0)
                turn = (axis[0] * s, axis[1] * s, axis[2] * s, math.cos(value / 2.0))
                result.append((parent, child, xyz, multiply(rotation, turn)))
        return result


def link_poses(robot: RobotModel, positions: Mapping[str, float]
               ) -> dict[str, tuple[Vector, Quaternion]]:
    """Return every link's pose in its root's frame (forward kinematics)."""
    transforms = JointTransforms(robot)
    by_child = {child: (parent, xyz, rotation)
                for parent, child, xyz, rotation in (*transforms.static,
                                                     *transforms.moving(positions))}
    poses: dict[str, tuple[Vector, Quaternion]] = {}
    for _, link in robot.walk():
        entry = by_child.get(link.name)
        if entry is None:
            poses[link.name] = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
            continue
        parent, xyz, rotation = entry
        base, base_rotation = poses[parent]
        offset = rotate(base_rotation, xyz)
        poses[link.name] = ((base[0] + offset[0], base[1] + offset[1], base[2] + offset[2]),
                            multiply(base_rotation, rotation))
    return poses
