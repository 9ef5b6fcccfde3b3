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
What SDFormat's URDF conversion does to the links: which it lumps, which it leaves out.

libsdformat's parser_urdf, which Gazebo runs on every URDF it spawns, lumps a link on a
fixed joint into its parent (unless a ``<gazebo reference="JOINT">`` block keeps the
joint), and leaves out a link whose mass, after lumping, is below 1e-6 kg, with everything
below it. The inertia check, ``--engines gazebo`` and the SDF row's ``prepare`` read it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from urdfgenpy_ros.formats.sdf_mass import mass_only
from urdfgenpy_ros.model.joint import Joint
from urdfgenpy_ros.reshape.lumping import lumps, WORLD

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

SDFORMAT_ZERO_MASS = 1e-6  # ignition::math::equal(mass, 0.0): its default tolerance


@dataclass
class SdfConversion:
    """What SDFormat's URDF conversion does to each link it does not keep as a link."""

    lumped: dict[str, tuple[str, Joint]] = field(default_factory=dict)
    """Link -> (the link it is lumped into, its fixed joint)."""
    cut: dict[str, list[str]] = field(default_factory=dict)
    """Massless link -> the links below it that are left out with it."""
    lumped_into: set[str] = field(default_factory=set)
    """Links that receive the mass of lumped children."""
    mass: dict[str, float] = field(default_factory=dict)
    """Link -> its mass with the mass of the children lumped into it (kg)."""

    @property
    def dropped(self) -> set[str]:
        """Return every link that is neither a link nor lumped in the SDF."""
        gone = set()
        for top, below in self.cut.items():
            gone.update(below)
            if top not in self.lumped:
                gone.add(top)
        return gone


def sdformat_conversion(robot: RobotModel) -> SdfConversion:
    """Return which links SDFormat's URDF conversion lumps and which it leaves out."""
    conversion = SdfConversion()
    mass = conversion.mass
    for root in robot.roots:
        order = list(robot.walk(root))
        for joint, link in reversed(order):  # children first: their mass is lumped upwards
            alone = mass_only(link)  # <mass> without <inertia>: libsdformat keeps the mass
            own = link.inertial.mass if link.inertial is not None else (
                alone.mass if alone is not None else 0.0)
            mass[link.name] = mass.get(link.name, 0.0) + own
            if joint is not None and lumps(joint):
                mass[joint.parent] = mass.get(joint.parent, 0.0) + mass[link.name]
                conversion.lumped_into.add(joint.parent)
        kept: dict[str, str] = {}
        cut_by: dict[str, str] = {}
        for joint, link in order:
            parent = joint.parent if joint is not None else None
            if parent is not None and parent in cut_by:
                cut_by[link.name] = cut_by[parent]
                conversion.cut[cut_by[parent]].append(link.name)
                continue
            if joint is not None and lumps(joint) and parent is not None:
                kept[link.name] = kept[parent]
                conversion.lumped[link.name] = (kept[parent], joint)
            else:
                kept[link.name] = link.name
            if link.name != WORLD and not mass[link.name] >= SDFORMAT_ZERO_MASS:
                cut_by[link.name] = link.name
                conversion.cut[link.name] = []
    return conversion
