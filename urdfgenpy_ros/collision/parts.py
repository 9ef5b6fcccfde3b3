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

"""The pieces a simplified collision is made of: meshes and primitives, in the mesh frame."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

PRIMITIVES = ('box', 'cylinder', 'capsule', 'sphere')
_SECTIONS = 64  # around a round primitive, when it is made a mesh to be measured


@dataclass(frozen=True)
class Part:
    """
    One piece of a simplified collision, in the frame of the (scaled) source mesh.

    ``kind`` is 'mesh' (``vertices`` and ``faces``) or a primitive: 'box' (``size`` the
    three edge lengths), 'cylinder' and 'capsule' (radius and length of the straight
    part, along z), 'sphere' (radius); a primitive sits at ``pose`` (4x4).
    """

    kind: str
    vertices: Any = field(default=None, compare=False)
    faces: Any = field(default=None, compare=False)
    size: tuple[float, ...] = ()
    pose: tuple[tuple[float, ...], ...] | None = None

    @property
    def face_count(self) -> int:
        """Return the number of triangles (0 for a primitive)."""
        return 0 if self.faces is None else len(self.faces)

    def solid(self) -> Any:
        """Return this part as a closed ``trimesh.Trimesh`` (round ones tessellated)."""
        import numpy
        import trimesh
        if self.kind == 'mesh':
            return trimesh.Trimesh(numpy.asarray(self.vertices, float),
                                   numpy.asarray(self.faces, int), process=False)
        pose = numpy.asarray(self.pose, float)
        if self.kind == 'box':
            return trimesh.creation.box(self.size, transform=pose)
        if self.kind == 'cylinder':
            return trimesh.creation.cylinder(self.size[0], self.size[1], sections=_SECTIONS,
                                             transform=pose)
        if self.kind == 'capsule':
            made = trimesh.creation.capsule(self.size[1], self.size[0],
                                            count=[_SECTIONS, _SECTIONS])
            made.apply_transform(pose)
            return made
        made = trimesh.creation.icosphere(subdivisions=4, radius=self.size[0])
        made.apply_transform(pose)
        return made


def mesh_part(mesh: Any) -> Part:
    """Return a trimesh mesh as a 'mesh' part."""
    import numpy
    return Part('mesh', numpy.asarray(mesh.vertices, float), numpy.asarray(mesh.faces, int))


def pose_tuple(matrix: Any) -> tuple[tuple[float, ...], ...]:
    """Return a 4x4 array as nested float tuples (a value: it compares and caches)."""
    return tuple(tuple(float(value) for value in row) for row in matrix)
