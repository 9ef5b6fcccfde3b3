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
Merge fixed-joint children into their parents, for URDF output (``Robot.merge_fixed``).

The lumping is the SDF writer's (:mod:`urdfgenpy_ros.reshape.lumping`, which matches SDFormat's):
masses add, the centre of mass is their mean, tensors turn into the parent's frame and
shift by the parallel axis theorem. Visuals and collisions move with their poses; moving
joints below a merged link hang from the link it merged into. A moved visual or
collision without a name takes its link's: SDFormat then names it
``<into>_fixed_joint_lump__<link>_collision_<n>`` from either file, so contact sensors
naming it keep working. Each merged link stays, a
massless frame on its fixed joint, so TF frames survive (its ``<gazebo>`` blocks and
sensors stay on it, where the frame still is); ``drop_frames`` removes it and moves those
onto the link it merged into, as SDFormat does.
"""

from __future__ import annotations

import copy

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.transforms import IDENTITY4, Matrix4, multiply
from urdfgenpy_ros.reshape._frames import origin_of
from urdfgenpy_ros.reshape.lumping import lumps, move_contents


def merge_fixed(robot, keep=(), *, drop_frames: bool = False):
    """
    Return a copy of ``robot`` with its fixed-joint children merged into their parents.

    Links named in ``keep`` (a name or several) are never merged (links can still merge
    into them); a fixed joint SDFormat keeps (to ``world``, or a ``<gazebo>`` block's
    ``preserveFixedJoint``) is kept too.
    """
    keep = {keep} if isinstance(keep, str) else set(keep)  # one name, or several
    unknown = sorted(name for name in keep if not robot.has_link(name))
    if unknown:
        raise ModelError(f'merge_fixed: keep names no link of {robot.name!r}: '
                         f'{", ".join(map(repr, unknown))} (name links)')
    merged = copy.deepcopy(robot)
    into: dict[str, tuple[str, Matrix4]] = {}  # merged link -> (body, pose in the body)
    for joint, child in list(merged.walk())[1:]:
        if joint is None or not lumps(joint) or child.name in keep:
            continue
        body_name, pose = into.get(joint.parent, (joint.parent, IDENTITY4))
        pose = multiply(pose, joint.origin.matrix())
        body = merged.get_link(body_name)
        _lump(body, child, pose, drop_frames)
        into[child.name] = (body_name, pose)
        for below in merged.child_joints(child.name):
            if drop_frames or not lumps(below) or below.child in keep:
                below.origin = origin_of(multiply(pose, below.origin.matrix()), below.origin)
                below.parent = body_name
        if drop_frames:
            merged.remove_joint(joint.name)
            merged.remove_link(child.name)
    return merged


def _lump(body, child, pose: Matrix4, drop_frames: bool) -> None:
    """Move ``child``'s mass, visuals and collisions onto ``body`` (``child`` at ``pose``)."""
    # the frame stays unless dropped: what refers to it (sensors, blocks) stays with it;
    # moved shapes take the names Gazebo's lumping of the original gives them
    move_contents(body, child, pose, origin_of(pose), everything=drop_frames, name_shapes=True)
