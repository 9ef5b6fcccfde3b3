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
The collision geometry of each link as coal shapes, with a bounding sphere each.

coal (the maintained FCL, pinocchio's collision library) is an optional dependency: the
``moveit`` extra. Meshes are read as coal's BVH models, as MoveIt's FCL plug-in reads
them; boxes, cylinders, spheres and capsules are coal's primitives. The sphere around
each shape lets the pair tests skip, with numpy, the states where two shapes are too far
apart to touch.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, TYPE_CHECKING

import numpy

from urdfgenpy_ros.model.errors import MissingDependencyError, UrdfgenpyError
from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, Mesh, Sphere
from urdfgenpy_ros.model.link import Collision
from urdfgenpy_ros.resources import PackageResolver

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def import_coal() -> Any:
    """Return the ``coal`` module, or a one-line error naming the extra."""
    try:
        import coal
    except ImportError:
        raise MissingDependencyError('coal', 'moveit', 'The collision matrix') from None
    return coal


@dataclass(frozen=True)
class Shape:
    """One ``<collision>`` of a link: the coal geometry, its pose, its bounding sphere."""

    link: str
    geometry: Any
    origin: numpy.ndarray
    """4x4 pose of the shape in its link's frame."""
    center: numpy.ndarray
    """Centre of the bounding sphere in the shape's own frame."""
    radius: float


def _primitive(coal: Any, geometry: Any) -> tuple[Any, float]:
    if isinstance(geometry, Box):
        sizes = (geometry.length, geometry.width, geometry.height)
        return coal.Box(*sizes), 0.5 * float(numpy.linalg.norm(sizes))
    if isinstance(geometry, Cylinder):
        return (coal.Cylinder(geometry.radius, geometry.length),
                float(numpy.hypot(geometry.radius, geometry.length / 2.0)))
    if isinstance(geometry, Sphere):
        return coal.Sphere(geometry.radius), geometry.radius
    if isinstance(geometry, Capsule):
        return (coal.Capsule(geometry.radius, geometry.length),
                geometry.radius + geometry.length / 2.0)
    raise UrdfgenpyError(f'no collision shape for {type(geometry).__name__}')


class ShapeReader:
    """Build the shapes of links, each mesh file read once."""

    def __init__(self, robot: RobotModel, search_paths: Any = ()) -> None:
        self.coal = import_coal()
        self.resolver = PackageResolver(search_paths)
        file = robot.source.file if robot.source is not None else None
        self.folder = Path(file).parent if file else None
        self.meshes: dict[tuple[Path, Any], tuple[Any, numpy.ndarray, float]] = {}

    def shape(self, link: str, collision: Collision) -> Shape:
        """Return the shape of one ``<collision>`` of ``link``."""
        origin = numpy.array(collision.origin.matrix())
        geometry = collision.geometry
        if isinstance(geometry, Mesh):
            model, center, radius = self._mesh(link, geometry)
        else:
            model, radius = _primitive(self.coal, geometry)
            center = numpy.zeros(3)
        return Shape(link, model, origin, center, radius)

    def _mesh(self, link: str, mesh: Mesh) -> tuple[Any, numpy.ndarray, float]:
        try:
            path = self.resolver.resolve(mesh.filename, self.folder)
        except UrdfgenpyError as error:  # its reason, and the fix in this feature's words
            reason = str(error).rsplit(' (', 1)[0] if str(error).endswith(')') else str(error)
            fix = ('give the folder holding its package: --package-path, or search_paths '
                   'in Python') if mesh.filename.startswith('package://') else \
                'restore the file, or correct the filename'
            raise UrdfgenpyError(f'link {link!r}: collision mesh {reason} ({fix})') from None
        key = (path, mesh.scale)
        if key not in self.meshes:
            scale = numpy.array(mesh.scale if mesh.scale is not None else (1.0, 1.0, 1.0))
            try:
                model = self.coal.MeshLoader().load(str(path), scale)
            except Exception as error:  # assimp's message: the file, not our bug
                raise UrdfgenpyError(f'link {link!r}: cannot read collision mesh {path}: '
                                     f'{error} (repair or re-export it)') from None
            points = numpy.array(model.vertices()).reshape(-1, 3)
            if not len(points):
                raise UrdfgenpyError(f'link {link!r}: collision mesh {path} has no vertices '
                                     '(repair or re-export it)')
            center = (points.min(axis=0) + points.max(axis=0)) / 2.0
            radius = float(numpy.linalg.norm(points - center, axis=1).max())
            self.meshes[key] = (model, center, radius)
        return self.meshes[key]


def link_shapes(robot: RobotModel, search_paths: Any = ()) -> dict[str, list[Shape]]:
    """Return the shapes of every link with collision geometry, in the robot's link order."""
    reader = ShapeReader(robot, search_paths)
    return {link.name: [reader.shape(link.name, collision) for collision in link.collisions]
            for link in robot.links if link.collisions}
