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
Put a (calibrated) DH table into a robot: only the chain's joint origins change.

Each link of the chain stays where it sits on the frame its joint moves (standard: DH
frame i-1 turned and shifted by joint i; modified: DH frame i), as the robot's own table
(``DHTable.from_robot``) places it; the new table moves those frames, and each movable
joint's origin is set to put its child link there. A tip reached by fixed joints is put at
the table's flange by the last of them; the other fixed joints, the axes and everything
else stay as they are, so a lossless write changes one line per joint.
"""

from __future__ import annotations

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.joint import JointType
from urdfgenpy_ros.model.transforms import IDENTITY4, Matrix4, multiply
from urdfgenpy_ros.reshape._frames import inverse, max_difference, origin_of
from urdfgenpy_ros.reshape.dh_extract import chain_axes, dh_from_robot

_UNCHANGED = 1e-13  # an origin that moves less than this keeps its text


def apply_dh(robot, table, base: str, tip: str) -> list[str]:
    """
    Set the origins of the chain from ``base`` to ``tip`` so its kinematics is ``table``'s.

    Return the names of the joints whose origin changed.

    :raises ModelError: when the table's rows do not match the chain's movable joints, or
        the table moves a tip that is a movable joint's own link.
    """
    joints, axes, _ = chain_axes(robot, base, tip)
    if len(table.rows) != len(axes):
        names = ', '.join(axis.joint.name for axis in axes)
        raise ModelError(f'the table has {len(table.rows)} rows, the chain from {base!r} to '
                         f'{tip!r} {len(axes)} movable joints ({names}): give one row per '
                         'joint, base to tip')
    for row, axis in zip(table.rows, axes):
        if row.turns == (axis.joint.type is JointType.PRISMATIC):
            raise ModelError(f'DH row {row.joint!r} is {row.joint_type}, joint '
                             f'{axis.joint.name!r} is {axis.joint.type.value}: the rows '
                             'follow the chain')
    nominal = dh_from_robot(robot, base, tip, table.convention, cls=type(table))
    zero = [0.0] * len(axes)
    old_frames, new_frames = nominal.link_frames(zero), table.link_frames(zero)
    # each link on the frame its joint moves, as the robot's own table places it
    placed = {axis.joint.child: multiply(new, inverse(old), axis.pose)
              for axis, old, new in zip(axes, old_frames, new_frames)}
    last = joints[-1]
    if last.type is not JointType.FIXED:
        tail_old = multiply(inverse(old_frames[-1]), nominal.flange(zero))
        tail_new = multiply(inverse(new_frames[-1]), table.flange(zero))
        if max_difference(tail_old, tail_new) > 1e-12:
            other = (', or use the modified convention (its last a, alpha sit before the '
                     'joint)' if table.convention.value == 'standard' else '')
            raise ModelError(f"tip {tip!r} is the link of joint {last.name!r}: the table's "
                             'tool (and last a, alpha in the standard convention) cannot move '
                             f'it; name as tip a frame on a fixed joint below it{other}')
    else:
        placed[last.child] = table.flange(zero)
    changed = []
    pose, new_pose = IDENTITY4, IDENTITY4  # the parent link's pose: as read, as it will be
    for joint in joints:
        old_child = multiply(pose, joint.origin.matrix())
        target = placed.get(joint.child)
        if target is None:  # a fixed joint that stays: its child follows its parent
            new_pose, pose = multiply(new_pose, joint.origin.matrix()), old_child
            continue
        origin: Matrix4 = multiply(inverse(new_pose), target)
        if max_difference(origin, joint.origin.matrix()) > _UNCHANGED:
            joint.origin = origin_of(origin, joint.origin)
            changed.append(joint.name)
        new_pose, pose = multiply(new_pose, joint.origin.matrix()), old_child
    return changed
