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
Denavit-Hartenberg tables to URDF skeletons.

Two conventions, each row's transform:

* ``STANDARD`` (Denavit-Hartenberg's, "distal"): ``Rz(theta) Tz(d) Tx(a) Rx(alpha)``;
  joint i turns about z of frame i-1.
* ``MODIFIED`` (Craig's, "proximal"): ``Rx(alpha) Tx(a) Rz(theta) Tz(d)``, where the row
  of joint i holds a_{i-1} and alpha_{i-1}; joint i turns about z of frame i.

A revolute row's variable is theta (``theta_offset`` is added); a prismatic row's is d
(``d`` is the offset and ``theta_offset`` is fixed). See docs/dh_guide.md.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from os import PathLike
from typing import cast, TYPE_CHECKING

from urdfgenpy_ros.model.dh_row import DHConvention, DHRow
from urdfgenpy_ros.model.dh_skeleton import skeleton, TableRows
from urdfgenpy_ros.model.transforms import (
    from_xyz_rpy, Matrix4, multiply, rotation_x, rotation_z, translation)

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.robot import Robot

__all__ = ['DHConvention', 'DHRow', 'DHTable']


@dataclass(slots=True)
class DHTable(TableRows):
    """A DH table: convention, rows, and optional base and tool transforms."""

    def __post_init__(self) -> None:
        """Coerce the convention."""
        self.convention = DHConvention(self.convention)

    # ---- kinematics -------------------------------------------------------------------

    def _split(self, row: DHRow, q: float) -> tuple[float, float]:
        """Return (theta, d) of ``row`` at joint value ``q``."""
        if row.turns:
            return row.theta_offset + q, row.d
        return row.theta_offset, row.d + q

    def row_transform(self, row: DHRow, q: float) -> Matrix4:
        """Return the homogeneous transform of one row at joint value ``q``."""
        theta, d = self._split(row, q)
        if self.convention is DHConvention.STANDARD:
            return multiply(rotation_z(theta), translation(z=d), translation(x=row.a),
                            rotation_x(row.alpha))
        return multiply(rotation_x(row.alpha), translation(x=row.a), rotation_z(theta),
                        translation(z=d))

    def frames(self, q: Sequence[float]) -> list[Matrix4]:
        """Return DH frames 0..n in the base frame (frame 0 is the base transform)."""
        frames = [from_xyz_rpy(self.base.xyz, self.base.rpy)]
        for row, value in zip(self.rows, q, strict=True):
            frames.append(multiply(frames[-1], self.row_transform(row, value)))
        return frames

    def flange(self, q: Sequence[float]) -> Matrix4:
        """Return the tool frame: DH frame n times the tool transform."""
        return multiply(self.frames(q)[-1], from_xyz_rpy(self.tool.xyz, self.tool.rpy))

    def link_frames(self, q: Sequence[float]) -> list[Matrix4]:
        """
        Return the pose of ``link_1``..``link_n`` of the skeleton ``to_robot`` builds.

        Modified: link i is DH frame i. Standard: link i is the frame of joint i's motion,
        DH frame i-1 turned and moved by joint i (``Rz(theta_i) Tz(d_i)``); DH frame n is
        the flange before the tool transform.
        """
        frames = self.frames(q)
        if self.convention is DHConvention.MODIFIED:
            return frames[1:]
        links = []
        for index, (row, value) in enumerate(zip(self.rows, q, strict=True)):
            theta, d = self._split(row, value)
            links.append(multiply(frames[index], rotation_z(theta), translation(z=d)))
        return links

    # ---- URDF -------------------------------------------------------------------------

    def to_robot(self, name: str, link_mass: float = 1.0, link_geometry: str = 'cylinder',
                 *, link_radius: float = 0.04) -> Robot:
        """
        Return the skeleton of the table as a Robot.

        Its links are ``base_link``, ``link_1``..``link_n`` joined by the rows' joints (named
        ``joint_<n>`` or by the row's name), and a ``flange`` on a fixed joint. Each link
        gets a placeholder ``link_geometry`` (cylinder, box or sphere) of radius
        ``link_radius`` reaching to the next joint, and the inertia of that solid with the
        uniform ``link_mass``.
        """
        return cast('Robot', skeleton(self, name, link_mass, link_geometry,
                                      link_radius=link_radius))

    @classmethod
    def from_robot(cls, robot: RobotModel, base: str, tip: str,
                   convention: DHConvention | str = 'standard') -> DHTable:
        """
        Return the DH table of ``robot``'s serial chain from link ``base`` to link ``tip``.

        Rows are named after the joints and keep their limits; ``base``, ``tool`` and each
        row's ``theta_offset`` make ``to_robot()``'s forward kinematics the chain's.
        The choices DH leaves open are listed in docs/reshaping.md.

        :raises ModelError: naming the joint when the chain is not serial revolute or
            prismatic (floating, planar and mimic joints are refused).
        """
        from urdfgenpy_ros.reshape.dh_extract import dh_from_robot
        table: DHTable = dh_from_robot(robot, base, tip, convention, cls=cls)
        return table

    # ---- files ------------------------------------------------------------------------

    @classmethod
    def from_file(cls, path: str | PathLike[str]) -> DHTable:
        """Read a table from a .yaml/.yml or .csv file (see docs/dh_guide.md)."""
        from urdfgenpy_ros.formats.dh_table import read_table
        return read_table(path, cls)

    def save(self, path: str | PathLike[str], degrees: bool = False) -> None:
        """
        Write the table to a .yaml/.yml or .csv file, angles in degrees if asked.

        :raises ModelError: for a .csv when the table has a base or tool transform (CSV
            cannot hold them; nothing is written).
        """
        from urdfgenpy_ros.formats.dh_table import write_table
        write_table(self, path, degrees)
