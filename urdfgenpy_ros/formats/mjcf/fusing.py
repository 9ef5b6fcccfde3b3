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
Fixed links fused into their parents, each kept as a ``<site>`` where it was.

The merge is :func:`urdfgenpy_ros.reshape.lumping.lump_fixed_joints` (the lumping the SDF writer
matches libsdformat with). Beside it, the same merges are followed by name, to say
where each merged link sits on the body that took it and which link each collision of
a body came from.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from urdfgenpy_ros.model.geometry import Origin
from urdfgenpy_ros.model.transforms import from_xyz_rpy, Matrix4, multiply, to_xyz_rpy
from urdfgenpy_ros.reshape.lumping import lump_fixed_joints, lumps

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


Sites = dict[str, list[tuple[str, Origin]]]


def fused(robot: RobotModel) -> tuple[RobotModel, Sites, dict[str, list[str]]]:
    """
    Return the fused robot, the sites per body and the owner link of each collision.

    ``sites`` maps a body to ``(merged link, pose on the body)``; ``owners`` maps a body
    to the link each of its collisions (in order) came from.
    """
    merged = lump_fixed_joints(robot)
    owners = {link.name: [link.name] * len(link.collisions) for link in robot.links}
    parent_of = {joint.name: joint.parent for joint in robot.joints}
    frame = {joint.name: from_xyz_rpy(joint.origin.xyz, joint.origin.rpy)
             for joint in robot.joints}  # each joint's pose on its current parent
    on: dict[str, list[tuple[str, Matrix4]]] = {}  # body -> merged links, pose on it
    remaining = list(robot.joints)
    while True:  # the order lump_fixed_joints merges in
        joint = next((j for j in remaining if lumps(j)), None)
        if joint is None:
            break
        parent, child, at = parent_of[joint.name], joint.child, frame[joint.name]
        owners[parent] = owners[parent] + owners.pop(child)
        moved = [(child, at)] + [(name, multiply(at, pose)) for name, pose in on.pop(child, [])]
        on[parent] = on.get(parent, []) + moved
        for other in remaining:
            if parent_of[other.name] == child:
                parent_of[other.name] = parent
                frame[other.name] = multiply(at, frame[other.name])
        remaining.remove(joint)
    order = {link.name: index for index, link in enumerate(robot.links)}
    sites: Sites = {}
    for body, placed in on.items():
        for name, pose in sorted(placed, key=lambda item: order[item[0]]):
            xyz, rpy = to_xyz_rpy(pose)
            sites.setdefault(body, []).append((name, Origin(xyz, rpy)))
    return merged, sites, owners
