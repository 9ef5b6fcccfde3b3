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
Where ``--fix`` takes a link's tensor from: its first collision, else visual, shape.

A box, cylinder, sphere or capsule gives the tensor of the solid; a closed mesh the
tensor of the solid it bounds (as ``urdfgenpy inertia`` computes it), read from the file
its URI names. Each is of uniform density, with the link's mass.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from os import PathLike
from pathlib import Path
from typing import TYPE_CHECKING
import warnings

from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, Mesh, Sphere
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.link import Collision, Link, Visual
from urdfgenpy_ros.model.mesh_inertia import ScaleWarning
from urdfgenpy_ros.resources import PackageResolver

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

_SOLIDS = (Box, Cylinder, Sphere, Capsule)


@dataclass
class TensorSources:
    """The robot's mesh files, found once: a resolver and the folder of its file."""

    resolver: PackageResolver
    base: Path | None
    _read: dict[tuple[str, tuple[float, ...] | None], Inertial | str] = field(
        default_factory=dict)

    @classmethod
    def of(cls, robot: RobotModel, search_paths: Sequence[str | PathLike[str]] = ()
           ) -> TensorSources:
        """Return the sources of ``robot``, meshes found through ``search_paths``."""
        files = [*robot.included_files,
                 *([robot.source.file] if robot.source is not None and robot.source.file
                   else [])]
        base = next((Path(file).parent for file in files if Path(file).is_file()), None)
        return cls(PackageResolver(search_paths), base)

    def unit_mesh(self, mesh: Mesh) -> Inertial | str:
        """Return the 1 kg inertial of the solid ``mesh`` bounds, or why there is none."""
        key = (mesh.filename, mesh.scale)
        if key not in self._read:
            try:
                path = self.resolver.resolve(mesh.filename, self.base)
                with warnings.catch_warnings(record=True) as said:
                    warnings.simplefilter('always', ScaleWarning)
                    self._read[key] = Inertial.from_mesh(str(path), mass=1.0,
                                                         scale=mesh.scale)
                if said:  # metres read as millimetres: that tensor would be wrong
                    self._read[key] = str(said[0].message)
            except UrdfgenpyError as error:  # open, unreadable, missing, no trimesh
                self._read[key] = str(getattr(error, 'message', error))
        return self._read[key]

    def solid(self, link: Link) -> tuple[str, Visual | Collision, Inertial] | str:
        """
        Return the kind and item a tensor is taken from, and that body of the link's mass.

        Without one, return why: no shape, or what was wrong with each mesh.
        """
        assert link.inertial is not None
        mass = link.inertial.mass
        reasons = []
        for kind, items in (('collision', link.collisions), ('visual', link.visuals)):
            for item in items:
                shape = item.geometry
                if isinstance(shape, _SOLIDS):
                    return kind, item, Inertial.from_geometry(mass, shape)
                if not isinstance(shape, Mesh):
                    continue
                unit = self.unit_mesh(shape)
                if isinstance(unit, str):
                    reasons.append(f'{kind} mesh {shape.filename!r}: {unit}')
                    continue
                return kind, item, Inertial(
                    mass, *(value * mass for value in (unit.ixx, unit.ixy, unit.ixz, unit.iyy,
                                                       unit.iyz, unit.izz)),
                    origin=unit.origin)
        return '; '.join(reasons)
