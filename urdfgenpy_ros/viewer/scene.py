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
A robot as triangle meshes in link frames, posed by the package's forward kinematics.

The renderer and the web viewer share it: every visual (or collision) becomes a
``Part`` whose mesh is in its link's frame, with the colour URDF gives it; ``link_matrices``
turns joint values into each link's 4x4 pose through ``urdfgenpy_ros.dynamics.kinematics``.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from os import PathLike
from pathlib import Path
from typing import Any

from urdfgenpy_ros.dynamics.kinematics import link_poses
from urdfgenpy_ros.model.errors import MissingDependencyError, UrdfgenpyError
from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, Mesh, Origin, Sphere
from urdfgenpy_ros.resources import PackageResolver, ResourceError
from urdfgenpy_ros.robot import Robot

DEFAULT_RGBA = (0.72, 0.74, 0.78, 1.0)
Rgba = tuple[float, float, float, float]


def require(module: str, extra: str, feature: str) -> Any:
    """Import an optional module, or raise MissingDependencyError naming the extra."""
    import importlib
    try:
        return importlib.import_module(module)
    except ImportError:
        raise MissingDependencyError(module, extra, feature) from None


@dataclass
class Part:
    """One visual or collision of a link: a trimesh in the link frame and its colour."""

    link: str
    kind: str  # 'visual' or 'collision'
    index: int
    mesh: Any  # trimesh.Trimesh, vertices in the link frame
    rgba: Rgba
    textured: bool = False  # the mesh file carries its own colours


def origin_matrix(origin: Origin) -> Any:
    """Return the 4x4 matrix of a URDF origin (fixed-axis rpy)."""
    from trimesh import transformations
    import numpy
    matrix = transformations.euler_matrix(*origin.rpy, axes='sxyz')
    matrix[:3, 3] = origin.xyz
    return numpy.asarray(matrix)


def pose_matrix(xyz: Iterable[float], quaternion: Iterable[float]) -> Any:
    """Return the 4x4 matrix of a translation and an ``(x, y, z, w)`` quaternion."""
    from trimesh import transformations
    x, y, z, w = quaternion
    matrix = transformations.quaternion_matrix((w, x, y, z))
    matrix[:3, 3] = tuple(xyz)
    return matrix


def link_matrices(robot: Robot, positions: Mapping[str, float]) -> dict[str, Any]:
    """Return each link's pose in the root frame as a 4x4 matrix (missing values: 0)."""
    return {name: pose_matrix(xyz, rotation)
            for name, (xyz, rotation) in link_poses(robot, positions).items()}


def joint_positions(robot: Robot, values: Mapping[str, float]) -> dict[str, float]:
    """
    Return every movable joint's position: ``values`` where given, mimic joints following.

    :raises UrdfgenpyError: for a name that is no movable joint of the robot.
    """
    movable = {joint.name: joint for joint in robot.joints if joint.is_movable}
    for name in values:
        if name not in movable:
            raise UrdfgenpyError(f'joint {name!r}: not a movable joint of {robot.name!r} '
                                 f'(movable: {", ".join(movable) or "none"})')
    positions = {name: float(values.get(name, 0.0)) for name in movable}
    for _ in range(len(movable)):  # mimic chains, leader first
        for name, joint in movable.items():
            if joint.mimic is not None and joint.mimic.joint in positions \
                    and name not in values:
                positions[name] = (positions[joint.mimic.joint] * joint.mimic.multiplier
                                   + joint.mimic.offset)
    return positions


class MeshCache:
    """Load each mesh file once: package://, file:// and relative paths resolved."""

    def __init__(self, robot: Robot, search_paths: Iterable[str | PathLike[str]] = ()
                 ) -> None:
        self.resolver = PackageResolver(search_paths)
        source = robot.source.file if robot.source is not None else None
        self.base = Path(source).parent if source and Path(source).is_file() else None
        self._meshes: dict[str, Any] = {}
        self.problems: list[str] = []

    def load(self, mesh: Mesh) -> Any | None:
        """Return the mesh as one trimesh (scaled), or None with a note in ``problems``."""
        trimesh = require('trimesh', 'view', 'Drawing meshes')
        try:
            path = self.resolver.resolve(mesh.filename, self.base)
        except ResourceError as error:
            self.problems.append(str(error))
            return None
        key = str(path)
        if key not in self._meshes:
            import logging
            logger = logging.getLogger('trimesh')
            level = logger.level
            logger.setLevel(logging.CRITICAL)  # it logs tracebacks for a missing texture
            try:
                loaded = _coloured_dae(path) if path.suffix.lower() == '.dae' else None
                if loaded is None:
                    loaded = trimesh.load(key, force='mesh')
                    if path.suffix.lower() == '.dae':  # as RViz: the unit applied
                        from urdfgenpy_ros.model.mesh_read import dae_unit
                        loaded.apply_scale(dae_unit(path))
            except Exception as error:  # noqa: B902 - trimesh raises many kinds
                self.problems.append(f'{path}: cannot read the mesh ({error})')
                loaded = None
            finally:
                logger.setLevel(level)
            self._meshes[key] = loaded
        loaded = self._meshes[key]
        if loaded is None:
            return None
        result = loaded.copy()
        if mesh.scale is not None:
            result.apply_scale(mesh.scale)
        return result


def _coloured_dae(path: Path) -> Any | None:
    """
    Return a DAE as one trimesh coloured by face, as RViz places it; None when textured.

    Read once by content (the mesh cache): its triangles and each material's colour.
    """
    import io

    import numpy
    import trimesh

    from urdfgenpy_ros import mesh_cache
    from urdfgenpy_ros.model.mesh_read import dae_parts

    def make() -> bytes:
        parts = dae_parts(path)
        if any(part.textured for part in parts):
            return b''
        colours = [numpy.tile(numpy.asarray(part.rgba or DEFAULT_RGBA) * 255.0,
                              (len(part.faces), 1)) for part in parts]
        offsets = numpy.cumsum([0] + [len(part.vertices) for part in parts])[:-1]
        stream = io.BytesIO()
        numpy.savez(stream, vertices=numpy.concatenate([part.vertices for part in parts]),
                    faces=numpy.concatenate([part.faces + offset for part, offset
                                             in zip(parts, offsets)]),
                    colours=numpy.round(numpy.concatenate(colours)).astype(numpy.uint8))
        return stream.getvalue()
    data = mesh_cache.cached(mesh_cache.key('view1.dae', path.read_bytes()), make)
    if not data:
        return None
    arrays = numpy.load(io.BytesIO(data))
    mesh = trimesh.Trimesh(arrays['vertices'], arrays['faces'], process=False,
                           face_colors=arrays['colours'])
    mesh.remove_unreferenced_vertices()
    return mesh


def geometry_mesh(geometry: Any, cache: MeshCache) -> Any | None:
    """Return a trimesh for a URDF geometry (primitives are centred as URDF says)."""
    trimesh = require('trimesh', 'view', 'Drawing robots')
    if isinstance(geometry, Box):
        return trimesh.creation.box(extents=geometry.size)
    if isinstance(geometry, Cylinder):
        return trimesh.creation.cylinder(radius=geometry.radius, height=geometry.length,
                                         sections=32)
    if isinstance(geometry, Sphere):
        return trimesh.creation.icosphere(subdivisions=3, radius=geometry.radius)
    if isinstance(geometry, Capsule):  # trimesh's height is the cylinder's, as URDF's length
        return trimesh.creation.capsule(height=geometry.length, radius=geometry.radius,
                                        count=[32, 32])
    if isinstance(geometry, Mesh):
        return cache.load(geometry)
    return None


def _colour(robot: Robot, material: Any) -> Rgba | None:
    if material is None:
        return None
    if material.rgba is not None:
        return material.rgba
    try:
        defined = robot.get_material(material.name)
    except (KeyError, ValueError):
        return None
    return defined.rgba


def _has_own_colours(mesh: Any) -> bool:
    visual = getattr(mesh, 'visual', None)
    return visual is not None and getattr(visual, 'kind', None) in ('vertex', 'face',
                                                                    'texture')


def robot_parts(robot: Robot, kind: str = 'visual', cache: MeshCache | None = None,
                search_paths: Iterable[str | PathLike[str]] = ()) -> list[Part]:
    """Return the ``visual`` or ``collision`` parts of every link, meshes in link frames."""
    cache = cache or MeshCache(robot, search_paths)
    parts = []
    for link in robot.links:
        shapes: list[Any] = link.visuals if kind == 'visual' else link.collisions
        for index, shape in enumerate(shapes):
            mesh = geometry_mesh(shape.geometry, cache)
            if mesh is None or len(mesh.faces) == 0:
                continue
            mesh.apply_transform(origin_matrix(shape.origin))
            rgba = _colour(robot, getattr(shape, 'material', None))
            textured = rgba is None and _has_own_colours(mesh)
            if kind == 'collision':
                rgba = (0.95, 0.55, 0.1, 0.6)
            parts.append(Part(link.name, kind, index, mesh, rgba or DEFAULT_RGBA, textured))
    return parts


def inertia_box(inertial: Any) -> tuple[Any, tuple[float, float, float], bool]:
    """
    Return the box of uniform density with the same mass and inertia, as Gazebo shows it.

    Returns its pose in the link frame (centre of mass, principal axes), its sides, and
    whether the tensor is physical (positive-definite, triangle inequality); for a bad
    tensor the sides are clamped to stay drawable, so the box can be shown in warning red.
    """
    import numpy
    tensor = numpy.array(inertial.tensor, dtype=float)
    mass = float(inertial.mass)
    moments, axes = numpy.linalg.eigh(tensor)
    if numpy.linalg.det(axes) < 0.0:
        axes[:, 2] = -axes[:, 2]
    a, b, c = moments
    squares = [6.0 / mass * (b + c - a), 6.0 / mass * (a + c - b), 6.0 / mass * (a + b - c)] \
        if mass > 0.0 else [0.0, 0.0, 0.0]
    valid = mass > 0.0 and bool((moments > 0.0).all()) and all(s > 0.0 for s in squares)
    sides = tuple(float(numpy.sqrt(max(s, 0.0))) for s in squares)
    floor = max(max(sides) * 0.05, 1e-3)
    drawn = (max(sides[0], floor), max(sides[1], floor), max(sides[2], floor))
    pose = origin_matrix(inertial.origin)
    pose[:3, :3] = pose[:3, :3] @ axes
    return pose, drawn, valid
