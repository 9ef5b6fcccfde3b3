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
Links SDF output writes as ``<frame>`` elements: children of fixed joints merged away.

libsdformat's URDF conversion merges each link on a fixed joint into its parent (mass,
shapes, sensors and ``<gazebo>`` blocks move there) and, since libsdformat 12.7, leaves a
``<frame>`` for the joint and one for the link, so both names stay addressable. SDF
output does the same for every link without mass on a fixed joint (SDF would give it
1 kg and a unit tensor) and, with ``lump_fixed``, for every link on a fixed joint. A
``<mass>`` without ``<inertia>`` counts as mass with a zero tensor, as libsdformat reads it.
"""

from __future__ import annotations

import copy
from typing import NamedTuple, TYPE_CHECKING

from urdfgenpy_ros.formats.sdf_mass import mass_only
from urdfgenpy_ros.model.geometry import Origin
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.joint import Joint
from urdfgenpy_ros.model.transforms import from_xyz_rpy, multiply, to_xyz_rpy
from urdfgenpy_ros.reshape.lumping import lumps, move_contents

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.model.link import Link


class Merged(NamedTuple):
    """A link merged into its parent: its name, its fixed joint's name, parent and origin."""

    link: str
    joint: str
    parent: str
    origin: Origin


def is_massless(link: Link) -> bool:
    """Return whether SDF output has no mass for ``link`` (no inertial, no lone mass)."""
    return link.inertial is None and mass_only(link) is None


def becomes_frame(robot: RobotModel, joint: Joint, lump_fixed: bool = False) -> bool:
    """Return whether SDF output merges ``joint``'s child into its parent, leaving frames."""
    if not lumps(joint) or joint.sensors or any(
            block.element.find('sensor') is not None for block in joint.extensions):
        return False  # kept: a joint that measures, or one a <gazebo> block preserves
    return lump_fixed or is_massless(robot.get_link(joint.child))


def _compose(outer: Origin, inner: Origin) -> Origin:
    xyz, rpy = to_xyz_rpy(multiply(from_xyz_rpy(outer.xyz, outer.rpy),
                                   from_xyz_rpy(inner.xyz, inner.rpy)))
    return Origin(xyz, rpy)


def give_lone_masses(robot: RobotModel) -> None:
    """Give each link with a ``<mass>`` and no ``<inertia>`` that mass and a zero tensor."""
    for link in robot.links:
        found = mass_only(link)
        if found is not None:
            link.inertial = Inertial(found.mass, origin=found.origin, source=found.location)


def merge_for_sdf(robot: RobotModel, lump_fixed: bool = False) -> tuple[RobotModel, list[Merged]]:
    """
    Return a copy of ``robot`` with the links SDF writes as frames merged, and those links.

    Each merged link's contents move onto its parent with their poses composed (an
    unnamed shape takes its link's name, as libsdformat names it), and the
    joints below it hang from the parent, as :func:`lumping.lump_fixed_joints` does; the
    ``<gazebo>`` blocks of a merged joint go to the robot (they name nothing left).
    """
    merged = copy.deepcopy(robot)
    give_lone_masses(merged)
    frames: list[Merged] = []
    while True:
        joint = next((j for j in merged.joints if becomes_frame(merged, j, lump_fixed)), None)
        if joint is None:
            return merged, frames
        parent, child = merged.get_link(joint.parent), merged.get_link(joint.child)
        at = joint.origin
        move_contents(parent, child, from_xyz_rpy(at.xyz, at.rpy), at, name_shapes=True)
        for grandchild in merged.child_joints(child.name):
            grandchild.parent = parent.name
            grandchild.origin = _compose(at, grandchild.origin)
        frames.append(Merged(child.name, joint.name, joint.parent, joint.origin))
        merged.extensions.extend(joint.extensions)  # said to go nowhere, with the reason
        merged.remove_joint(joint.name)
        merged.remove_link(child.name)
