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
Solids that can be measured: valid manifolds, or points inside when there is none.

A convex part is the manifold hull of its points, which is always valid. A solid that is
not convex (a CAD mesh, a decimated one) is the union of its bodies, each closed by trimesh
and checked by manifold3d, so that bodies overlapping in one file count once; when a body
is not a valid manifold the volumes are estimated with points drawn in the bounding box
and tested for being inside (trimesh ``contains``, per body).
"""

from __future__ import annotations

from typing import Any

from urdfgenpy_ros.collision.parts import Part

SAMPLES = 200_000  # points for a sampled measure: about 0.003 of IoU
_CONVEX = 1e-3  # a mesh whose volume is this close to its hull's is convex


def valid(solid: Any) -> Any:
    """Return ``solid`` when manifold3d calls it valid and it has volume, else None."""
    import manifold3d
    if solid.status() != manifold3d.Error.NoError or solid.volume() <= 0:
        return None
    return solid


def manifold_of(mesh: Any) -> Any:
    """Return a trimesh mesh as a ``manifold3d.Manifold`` (check it with :func:`valid`)."""
    import manifold3d
    import numpy
    data = manifold3d.Mesh(vert_properties=numpy.asarray(mesh.vertices, numpy.float32),
                           tri_verts=numpy.asarray(mesh.faces, numpy.uint32))
    return manifold3d.Manifold(data)


def hull_of(vertices: Any) -> Any:
    """Return the manifold convex hull of points, or None when they span no volume."""
    import manifold3d
    import numpy
    return valid(manifold3d.Manifold.hull_points(numpy.asarray(vertices, float)))


def is_convex(mesh: Any) -> bool:
    """Return whether a trimesh mesh encloses (nearly) its convex hull's volume."""
    hull = hull_of(mesh.vertices)
    return hull is not None and abs(abs(mesh.volume) - hull.volume()) <= _CONVEX * hull.volume()


def bodies(mesh: Any) -> list[Any]:
    """Return the mesh's connected bodies, each merged, hole-filled and faced outward."""
    import trimesh
    found = []
    for body in mesh.split(only_watertight=False):
        body.merge_vertices()
        body.update_faces(body.nondegenerate_faces())
        if not body.is_watertight:
            trimesh.repair.fill_holes(body)
        trimesh.repair.fix_normals(body)
        if body.volume < 0:
            body.invert()
        if len(body.faces) >= 4:
            found.append(body)
    return found


def solid_manifold(mesh: Any) -> Any:
    """Return the union of the mesh's bodies as one valid Manifold, or None."""
    import manifold3d
    if is_convex(mesh):
        return hull_of(mesh.vertices)
    solids = [valid(manifold_of(body)) for body in bodies(mesh)]
    if not solids or any(solid is None for solid in solids):
        return None
    if len(solids) == 1:
        return solids[0]
    return valid(manifold3d.Manifold.batch_boolean(solids, manifold3d.OpType.Add))


def parts_manifold(parts: list[Part], hulls: bool = False) -> Any:
    """
    Return the union of the parts as one valid Manifold, or None.

    Primitives and convex meshes are their hulls; with ``hulls``, every mesh is (how
    MuJoCo collides with it).
    """
    import manifold3d
    solids = []
    for part in parts:
        mesh = part.solid()
        if part.kind != 'mesh' or hulls:
            solids.append(hull_of(mesh.vertices))
        else:
            solids.append(solid_manifold(mesh))
    if not solids or any(solid is None for solid in solids):
        return None
    if len(solids) == 1:
        return solids[0]
    return valid(manifold3d.Manifold.batch_boolean(solids, manifold3d.OpType.Add))


def inside(mesh: Any, points: Any, convex: bool) -> Any:
    """Return which points are inside a trimesh mesh (by half-spaces when convex)."""
    import numpy
    if convex:
        hull = mesh.convex_hull
        normals = hull.face_normals
        offsets = numpy.einsum('ij,ij->i', normals, hull.triangles[:, 0, :])
        return numpy.all(points @ normals.T - offsets <= 1e-12, axis=1)
    found = numpy.zeros(len(points), bool)
    for body in bodies(mesh):
        found |= body.contains(points)
    return found


def sampled(original: Any, parts: list[Part], hulls: bool = False
            ) -> tuple[float, float, float]:
    """Return the volumes of the original, the parts and their intersection, by points."""
    import numpy
    shapes = [(part.solid(), part.kind != 'mesh' or hulls) for part in parts]
    corners = numpy.vstack([original.bounds] + [shape.bounds for shape, _ in shapes])
    low, high = corners.min(axis=0), corners.max(axis=0)
    points = low + numpy.random.default_rng(0).random((SAMPLES, 3)) * (high - low)
    cell = float(numpy.prod(high - low)) / SAMPLES
    was = inside(original, points, is_convex(original))
    new = numpy.zeros(SAMPLES, bool)
    for shape, convex in shapes:
        new |= inside(shape, points, convex or is_convex(shape))
    return (float(was.sum()) * cell, float(new.sum()) * cell,
            float((was & new).sum()) * cell)
