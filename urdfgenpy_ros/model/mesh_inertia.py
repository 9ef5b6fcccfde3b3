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
Inertia of closed meshes, and of MeshLab's "Compute Geometric Measures" figures.

The volume integrals are Eberly's (Polyhedral Mass Properties, 2002): exact for a closed,
consistently wound triangle mesh. trimesh (optional extra ``mesh``) only reads the file,
as RViz reads it (:mod:`urdfgenpy_ros.model.mesh_read`: a DAE's unit applied, its up axis not).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from os import PathLike
from pathlib import Path
from typing import Any, TypeVar
import warnings

from urdfgenpy_ros.model import checks
from urdfgenpy_ros.model.errors import MissingDependencyError, UrdfgenpyError
from urdfgenpy_ros.model.geometry import Origin

Built = TypeVar('Built')
"""What ``cls`` builds: an ``Inertial`` (this module does not import it)."""


class ScaleWarning(UserWarning):
    """A mesh larger than 10 m: likely in millimetres (``name`` and ``extent`` in m)."""

    def __init__(self, name: str, extent: float) -> None:
        super().__init__(f'{name} spans {extent:g} m: if it is in millimetres, pass '
                         'scale=(0.001, 0.001, 0.001)')
        self.name = name
        self.extent = extent


def _numpy() -> Any:
    try:
        import numpy
    except ImportError:
        raise MissingDependencyError('numpy', 'mesh', 'Mesh inertia') from None
    return numpy


def load_triangles(path: str | PathLike[str]) -> Any:
    """Return the mesh's triangles as an (n, 3, 3) array, placed as RViz places them."""
    from urdfgenpy_ros.model.errors import ModelError
    from urdfgenpy_ros.model.mesh_read import load_mesh
    try:
        import trimesh  # noqa: F401 (the extra it needs, named in its own words)
    except ImportError:
        raise MissingDependencyError('trimesh', 'mesh', 'Inertial.from_mesh') from None
    try:
        mesh: Any = load_mesh(path)  # a DAE's unit applied, its up axis not (as RViz)
    except ModelError as error:
        reason = str(error).removeprefix(f'{path}: ')
        if reason.startswith('no triangles'):
            return _numpy().zeros((0, 3, 3))
        raise UrdfgenpyError(f'{path}: cannot read the mesh ({reason})') from None
    return mesh.vertices[mesh.faces]


def _check_closed(numpy: Any, triangles: Any, name: str) -> None:
    """Raise unless every edge is shared by exactly two triangles."""
    rounded = numpy.round(triangles.reshape(-1, 3), 12)
    _, index = numpy.unique(rounded, axis=0, return_inverse=True)
    corners = index.reshape(-1, 3)
    edges = numpy.sort(numpy.concatenate([corners[:, [0, 1]], corners[:, [1, 2]],
                                          corners[:, [2, 0]]]), axis=1)
    _, counts = numpy.unique(edges, axis=0, return_counts=True)
    if (counts != 2).any():
        open_edges = int((counts == 1).sum())
        raise UrdfgenpyError(
            f'{name}: the mesh is not closed ({open_edges} open edge(s)); volume '
            'integration needs a closed surface: close the holes (MeshLab: Filters > '
            'Remeshing > Close Holes) or give the inertia explicitly')


def mass_properties(triangles: Any) -> tuple[float, Any, Any]:
    """Return volume, centre of mass and the unit-density tensor about the centre."""
    numpy = _numpy()
    p0, p1, p2 = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    normal = numpy.cross(p1 - p0, p2 - p0)
    w0, w1, w2 = p0, p1, p2
    t0 = w0 + w1
    f1 = t0 + w2
    t1 = w0 * w0
    t2 = t1 + w1 * t0
    f2 = t2 + w2 * f1
    f3 = w0 * t1 + w1 * t2 + w2 * f2
    g0, g1, g2 = f2 + w0 * (f1 + w0), f2 + w1 * (f1 + w1), f2 + w2 * (f1 + w2)
    x, y, z = 0, 1, 2
    volume = (normal[:, x] * f1[:, x]).sum() / 6.0
    first = numpy.array([(normal[:, a] * f2[:, a]).sum() for a in (x, y, z)]) / 24.0
    second = numpy.array([(normal[:, a] * f3[:, a]).sum() for a in (x, y, z)]) / 60.0
    xy = (normal[:, x] * (p0[:, y] * g0[:, x] + p1[:, y] * g1[:, x]
                          + p2[:, y] * g2[:, x])).sum() / 120.0
    yz = (normal[:, y] * (p0[:, z] * g0[:, y] + p1[:, z] * g1[:, y]
                          + p2[:, z] * g2[:, y])).sum() / 120.0
    zx = (normal[:, z] * (p0[:, x] * g0[:, z] + p1[:, x] * g1[:, z]
                          + p2[:, x] * g2[:, z])).sum() / 120.0
    if volume < 0.0:  # wound inside out: every integral changes sign
        volume, first, second, xy, yz, zx = -volume, -first, -second, -xy, -yz, -zx
    centre = first / volume
    cx, cy, cz = centre
    tensor = numpy.array([
        [second[1] + second[2] - volume * (cy * cy + cz * cz), -(xy - volume * cx * cy),
         -(zx - volume * cz * cx)],
        [-(xy - volume * cx * cy), second[0] + second[2] - volume * (cz * cz + cx * cx),
         -(yz - volume * cy * cz)],
        [-(zx - volume * cz * cx), -(yz - volume * cy * cz),
         second[0] + second[1] - volume * (cx * cx + cy * cy)]])
    return float(volume), centre, tensor


def inertial_from_mesh(filename: str | PathLike[str], density: float | None = None,
                       mass: float | None = None,
                       scale: Sequence[float] | None = None, *, cls: Callable[..., Built]
                       ) -> Built:
    """
    Return the ``cls`` (an Inertial) of a solid mesh of uniform ``density`` or ``mass``.

    The origin is the centre of mass (axes as the mesh's); ``scale`` multiplies the
    vertices first (0.001 for millimetres).

    :raises UrdfgenpyError: for an open mesh, or when neither or both of density and
        mass are given.
    """
    if (density is None) == (mass is None):
        raise UrdfgenpyError('Inertial.from_mesh(): give exactly one of density= (kg/m^3) '
                             'and mass= (kg)')
    numpy = _numpy()
    triangles = numpy.asarray(load_triangles(filename), dtype=float)
    if scale is not None:
        triangles = triangles * numpy.asarray(scale, dtype=float)
    name = Path(filename).name
    if len(triangles) == 0:
        raise UrdfgenpyError(f'{name}: the file holds no triangles (is it a mesh?)')
    _check_closed(numpy, triangles, name)
    volume, centre, tensor = mass_properties(triangles)
    extent = float((triangles.reshape(-1, 3).max(axis=0) -
                    triangles.reshape(-1, 3).min(axis=0)).max())
    if extent > 10.0:
        warnings.warn(ScaleWarning(name, extent), stacklevel=2)
    if mass is None:
        mass = float(density) * volume  # type: ignore[arg-type]
    tensor = tensor * (mass / volume)
    return cls(mass, tensor[0, 0], tensor[0, 1], tensor[0, 2], tensor[1, 1],
               tensor[1, 2], tensor[2, 2], origin=Origin(tuple(float(c) for c in centre)))


def inertial_from_meshlab(mass: float, volume: float, tensor: Sequence[Sequence[float]],
                          centre: Sequence[float] | None = None, *, cls: Callable[..., Built]
                          ) -> Built:
    """
    Return an SI inertial (a ``cls``) from MeshLab's "Compute Geometric Measures" output.

    MeshLab works in the mesh's units (usually millimetres) with density 1: ``volume`` in
    mm^3, ``tensor`` (3x3) in mm^5 and the optional ``centre`` of mass in mm. Scaling by
    ``mass / volume`` and 1e-6 (mm^2 to m^2) gives kg m^2.
    """
    mass = checks.non_negative('Inertial.from_meshlab', 'mass', mass, 'kg')
    volume = checks.positive('Inertial.from_meshlab', 'volume', volume, 'mm^3')
    factor = mass / volume * 0.000001
    values = [[checks.finite('Inertial.from_meshlab', 'tensor', value) * factor
               for value in row] for row in tensor]
    origin = Origin(tuple(float(c) / 1000.0 for c in centre)) if centre else Origin()
    return cls(mass, values[0][0], values[0][1], values[0][2], values[1][1],
               values[1][2], values[2][2], origin=origin)
