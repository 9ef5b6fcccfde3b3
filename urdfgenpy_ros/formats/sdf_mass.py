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
A link's ``<inertial>`` with a ``<mass>`` and no ``<inertia>``, as SDF output writes it.

urdfdom drops such an inertial (the reader does too, with P106, and keeps it as written);
libsdformat's own URDF conversion keeps the mass and its origin with a zero tensor, so a
0.072 kg camera stays 0.072 kg in Gazebo instead of SDF's default of 1 kg. SDF output does
what that conversion does.
"""

from __future__ import annotations

from typing import NamedTuple, TYPE_CHECKING

from urdfgenpy_ros.model.errors import SourceLocation
from urdfgenpy_ros.model.geometry import Origin

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.model.link import Link


class MassOnly(NamedTuple):
    """The mass and origin of an ``<inertial>`` without ``<inertia>``, and where it is."""

    mass: float
    origin: Origin
    location: SourceLocation


def mass_only(link: Link) -> MassOnly | None:
    """Return the mass-only inertial the link was read with (and has no inertial), or None."""
    extras = link.extras
    if link.inertial is not None or extras is None:
        return None
    for child in extras.element().children:
        if child.tag != 'inertial':
            continue
        if child.find('inertia') is not None:
            return None
        mass = child.find('mass')
        try:
            value = float(mass.attrib['value']) if mass is not None else None
            origin = child.find('origin')
            pose = Origin() if origin is None else Origin(
                xyz=_numbers(origin.attrib.get('xyz')), rpy=_numbers(origin.attrib.get('rpy')))
        except (KeyError, TypeError, ValueError):
            return None
        if value is None or not value > 0.0:
            return None
        file = link.source.file if link.source is not None else None
        return MassOnly(value, pose, SourceLocation(file, child.line, 1))
    return None


def mass_only_notes(robot: RobotModel) -> list[str]:
    """Return one line per link whose mass-only inertial SDF output keeps."""
    notes = []
    for link in robot.links:
        found = mass_only(link)
        if found is not None:
            notes.append(f'{found.location}: note: link {link.name!r}: <inertial> without '
                         f'<inertia>: the SDF keeps its mass {found.mass:g} kg with a zero '
                         "tensor, as libsdformat's URDF conversion does (add <inertia> to "
                         'give it one)')
    return notes


def _numbers(text: str | None) -> tuple[float, float, float]:
    if text is None:
        return (0.0, 0.0, 0.0)
    values = tuple(float(part) for part in text.split())
    if len(values) != 3:
        raise ValueError(text)
    return values


def default_mass_notes(robot: RobotModel) -> list[str]:
    """
    Return one line per link SDF output writes with no ``<inertial>`` at all.

    SDF gives such a link its default, 1 kg with a unit tensor, so a massless tool frame
    weighs 1 kg in Gazebo; libsdformat's own URDF conversion lumps or drops it instead.
    """
    notes = []
    for link in robot.links:
        if link.inertial is not None or link.name == 'world' or mass_only(link) is not None:
            continue
        joints = [robot.parent_joint(link), *robot.child_joints(link)]
        lumpable = any(joint is not None and joint.type.value == 'fixed' for joint in joints)
        fix = ('pass --lump-fixed to merge it as libsdformat does, or give it an <inertial>'
               if lumpable else 'give it an <inertial>')
        where = f'{link.source}: ' if link.source is not None else ''
        notes.append(f'{where}warning: link {link.name!r} has no <inertial>: SDF gives it '
                     f'its default mass of 1 kg and a unit tensor ({fix})')
    return notes
