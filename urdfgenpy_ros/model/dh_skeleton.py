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
The URDF skeleton of a Denavit-Hartenberg table: a link per joint, placeholder shapes.

The model layer: ``dh.DHTable.to_robot`` builds with :func:`skeleton`, and so does the
reader of DH table files in ``formats``, which reads into :class:`TableRows` (neither
imports the other).
"""

from __future__ import annotations

from dataclasses import dataclass, field, KW_ONLY
import math
from typing import Protocol, TYPE_CHECKING

from urdfgenpy_ros.model import robot_class
from urdfgenpy_ros.model.dh_row import DHConvention, DHRow
from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.geometry import Box, Cylinder, Geometry, Origin, Sphere
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.joint import Joint, JointLimit
from urdfgenpy_ros.model.link import Collision, Link, Visual
from urdfgenpy_ros.model.transforms import (
    from_xyz_rpy, IDENTITY4, Matrix4, multiply, rotation_x, rotation_z, to_xyz_rpy,
    translation)

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


class Table(Protocol):
    """What a skeleton and a table file are made of (a ``dh.DHTable`` has it)."""

    convention: DHConvention
    rows: list[DHRow]
    base: Origin
    tool: Origin


@dataclass(slots=True)
class TableRows:
    """A table as a file holds it, for the robot it builds (``DHTable`` is the user's)."""

    convention: DHConvention
    rows: list[DHRow] = field(default_factory=list)
    _: KW_ONLY
    base: Origin = field(default_factory=Origin)
    tool: Origin = field(default_factory=Origin)


def joint_origins(table: Table) -> tuple[list[Matrix4], Matrix4]:
    """Return each joint's origin (in its parent link) and the flange joint's origin."""
    base = from_xyz_rpy(table.base.xyz, table.base.rpy)
    tool = from_xyz_rpy(table.tool.xyz, table.tool.rpy)
    origins = []
    carried = base  # the fixed part that lies between the last link and the next joint
    for row in table.rows:
        # theta and d at joint value 0: the joint then adds its motion along/about z
        fixed_screw = multiply(rotation_z(row.theta_offset), translation(z=row.d))
        if table.convention is DHConvention.MODIFIED:
            origins.append(multiply(carried, rotation_x(row.alpha), translation(x=row.a),
                                    fixed_screw))
            carried = IDENTITY4
        else:
            origins.append(multiply(carried, fixed_screw))
            carried = multiply(translation(x=row.a), rotation_x(row.alpha))
    return origins, multiply(carried, tool)


def skeleton(table: Table, name: str, link_mass: float = 1.0, link_geometry: str = 'cylinder',
             *, link_radius: float = 0.04) -> RobotModel:
    """
    Return the skeleton of ``table`` as a robot (``model.robot_class()``).

    Its links are ``base_link``, ``link_1``..``link_n`` joined by the rows' joints (named
    ``joint_<n>`` or by the row's name), and a ``flange`` on a fixed joint. Each link
    gets a placeholder ``link_geometry`` (cylinder, box or sphere) of radius
    ``link_radius`` reaching to the next joint, and the inertia of that solid with the
    uniform ``link_mass``.
    """
    if link_geometry not in ('cylinder', 'box', 'sphere'):
        raise ModelError(f"link_geometry must be 'cylinder', 'box' or 'sphere', got "
                         f'{link_geometry!r}')
    origins, flange = joint_origins(table)
    robot = robot_class()(name)
    robot.add_link(Link('base_link'))
    parent = 'base_link'
    for number, (row, origin) in enumerate(zip(table.rows, origins), start=1):
        link_name = f'link_{number}'
        reach = origins[number] if number < len(origins) else flange
        robot.add_link(_placeholder(link_name, reach, link_geometry, link_radius,
                                    link_mass))
        xyz, rpy = to_xyz_rpy(origin)
        robot.add_joint(Joint(row.name, row.joint_type, parent, link_name,
                              origin=Origin(xyz, rpy), axis=(0.0, 0.0, 1.0),
                              limit=_limit(row)))
        parent = link_name
    xyz, rpy = to_xyz_rpy(flange)
    robot.add_link(Link('flange'))
    robot.add_joint(Joint('flange_joint', 'fixed', parent, 'flange',
                          origin=Origin(xyz, rpy)))
    return robot


def _limit(row: DHRow) -> JointLimit | None:
    """
    Return the joint limit of ``row``: its own values, else the defaults.

    A continuous row has none unless it gives an effort or a velocity (and then only what
    it gives).
    """
    if row.joint_type == 'continuous':
        if row.effort is None and row.velocity is None:
            return None
        return JointLimit(row.lower or 0.0, row.upper or 0.0, effort=row.effort or 0.0,
                          velocity=row.velocity or 0.0)
    default = (-math.pi, math.pi) if row.joint_type == 'revolute' else (0.0, 1.0)
    return JointLimit(default[0] if row.lower is None else row.lower,
                      default[1] if row.upper is None else row.upper,
                      effort=100.0 if row.effort is None else row.effort,
                      velocity=2.0 if row.velocity is None else row.velocity)


def _placeholder(name: str, reach: Matrix4, kind: str, radius: float, mass: float) -> Link:
    """Return a link whose shape spans from its origin to the next joint's origin."""
    x, y, z = reach[0][3], reach[1][3], reach[2][3]
    length = math.sqrt(x * x + y * y + z * z)
    if kind == 'sphere' or length < 2.0 * radius:
        shape: Geometry = Sphere(radius)
        origin = Origin((x / 2.0, y / 2.0, z / 2.0))
    else:
        shape = (Cylinder(radius, length) if kind == 'cylinder'
                 else Box(2.0 * radius, 2.0 * radius, length))
        # turn z onto the segment: pitch towards it, then yaw about the parent z
        pitch = math.acos(max(-1.0, min(1.0, z / length)))
        yaw = math.atan2(y, x) if math.hypot(x, y) > 1e-12 else 0.0
        origin = Origin((x / 2.0, y / 2.0, z / 2.0), (0.0, pitch, yaw))
    link = Link(name)
    link.add_visual(Visual(shape, origin=origin))
    link.add_collision(Collision(shape, origin=origin))
    return link.set_inertial(Inertial.from_geometry(mass, shape, origin=origin))
