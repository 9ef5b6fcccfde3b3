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
How much shape a simplified collision loses, measured with manifold3d's exact booleans.

Where a solid is no valid manifold (open, overlapping bodies) the volumes are sampled
with points instead (:mod:`.solids`); ``Measures.how`` says which.

IoU is the volume of the intersection over that of the union of the original solid and
the new shape; coverage the share of the original inside the new shape (a collision must
not lose material a gripper touches); excess the volume the new shape adds, as a share
of the original's.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.collision.parts import Part
from urdfgenpy_ros.collision.solids import parts_manifold, sampled, solid_manifold
from urdfgenpy_ros.model.errors import ModelError

if TYPE_CHECKING:
    from urdfgenpy_ros.model.inertial import Inertial

_FROM_COLLISION = 0.01  # a link tensor this close to the mesh's came from it


class OpenMeshError(ModelError):
    """A collision mesh that is not a closed solid and that trimesh cannot close."""


@dataclass(frozen=True)
class Measures:
    """What one simplified collision loses and gains, against the original solid."""

    iou: float
    coverage: float
    excess: float
    faces_before: int
    faces_after: int
    parts: int
    inertia_change: float | None = None  # largest principal moment's, when from the mesh
    how: str = 'exact'  # 'exact' (manifold3d booleans), 'sampled' (points inside), 'none'

    def as_dict(self) -> dict[str, Any]:
        """Return the measures as plain data (for JSON and the cache)."""
        return asdict(self)


def closed_solid(mesh: Any, name: str) -> tuple[Any, list[str]]:
    """
    Return ``mesh`` as a closed solid, and what was repaired to make it one.

    :raises OpenMeshError: naming ``name``, when trimesh cannot close it.
    """
    import trimesh
    repairs = []
    if not mesh.is_watertight or not mesh.is_winding_consistent:
        mesh = mesh.copy()
        mesh.merge_vertices()
        mesh.update_faces(mesh.nondegenerate_faces())
        mesh.update_faces(mesh.unique_faces())
        if not mesh.is_watertight:
            trimesh.repair.fill_holes(mesh)
            repairs.append('holes filled')
        trimesh.repair.fix_winding(mesh)
        repairs.insert(0, 'open or non-manifold mesh repaired by trimesh')
        if not mesh.is_watertight or not mesh.is_winding_consistent:
            raise OpenMeshError(f'{name} is open or non-manifold and trimesh cannot close it: '
                                'close it in a mesh editor (or make its collision a '
                                'primitive by hand)')
    if mesh.volume < 0:
        mesh = mesh.copy()
        mesh.invert()
        repairs.append('faces turned outward')
    return mesh, repairs


def measure(original: Any, parts: list[Part], inertial: Inertial | None = None,
            hulls: bool = False) -> Measures:
    """
    Return the measures of ``parts`` against the closed solid ``original``.

    Exact (manifold3d) when both are valid manifolds and the volumes agree, else sampled;
    with ``hulls`` every mesh part is measured as its convex hull (as MuJoCo collides).
    """
    solid, new = solid_manifold(original), parts_manifold(parts, hulls)
    how = 'exact'
    if solid is not None and new is not None:
        before, after = solid.volume(), new.volume()
        common = (solid ^ new).volume()
    if solid is None or new is None or not _consistent(before, after, common):
        before, after, common = sampled(original, parts, hulls)
        how = 'sampled'
    if before <= 0 or after <= 0:
        how, before, after, common = 'none', 1.0, 1.0, 0.0
    union = before + after - common
    return Measures(iou=min(common / union, 1.0), coverage=min(common / before, 1.0),
                    excess=max(after - common, 0.0) / before,
                    faces_before=len(original.faces),
                    faces_after=sum(part.face_count for part in parts), parts=len(parts),
                    inertia_change=None if new is None else
                    _inertia_change(original, new, inertial), how=how)


def _consistent(before: float, after: float, common: float) -> bool:
    """Return whether exact volumes can be (an intersection is no larger than either)."""
    return before > 0 and after > 0 and 0 <= common <= min(before, after) * (1 + 1e-6)


def _principal(mesh: Any, mass: float) -> Any:
    """Return the sorted principal moments of a closed solid of ``mass``."""
    import numpy
    tensor = mesh.moment_inertia * (mass / mesh.volume)  # trimesh's is for density 1
    return numpy.sort(numpy.linalg.eigvalsh(tensor))


def _inertia_change(original: Any, new: Any, inertial: Inertial | None) -> float | None:
    """Return how the link's principal moments would change, when they came from the mesh."""
    import numpy
    import trimesh
    if inertial is None or inertial.mass <= 0 or original.volume <= 0:
        return None
    given = numpy.array([[inertial.ixx, inertial.ixy, inertial.ixz],
                         [inertial.ixy, inertial.iyy, inertial.iyz],
                         [inertial.ixz, inertial.iyz, inertial.izz]])
    given = numpy.sort(numpy.linalg.eigvalsh(given))
    before = _principal(original, inertial.mass)
    scale = float(numpy.max(numpy.abs(before)))
    if scale <= 0 or numpy.max(numpy.abs(given - before)) > _FROM_COLLISION * scale:
        return None  # the tensor did not come from this mesh
    shape = new.to_mesh()
    made = trimesh.Trimesh(shape.vert_properties[:, :3], shape.tri_verts, process=False)
    if made.volume <= 0:
        return None
    after = _principal(made, inertial.mass)
    return float(numpy.max(numpy.abs(after - before)) / scale)
