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
Mesh files read as RViz reads them, for every place the package reads a mesh.

RViz (rviz_rendering's assimp loader) applies a COLLADA file's node transforms and its
``<asset><unit meter>``, and ignores its ``<up_axis>`` (it sets assimp's
``IGNORE_UP_DIRECTION``): a ``Y_UP`` file is shown as its coordinates say, not turned.
trimesh reads node transforms and ignores both the up axis and the unit, so the unit is
applied here. A DAE's material colours are read per primitive (:func:`dae_parts`).
"""

from __future__ import annotations

from dataclasses import dataclass
import logging
from os import PathLike
from pathlib import Path
from typing import Any

from urdfgenpy_ros.model.errors import MissingDependencyError, ModelError


@dataclass
class Part:
    """Triangles of one colour of a mesh file: vertices (n, 3), faces (m, 3), colour."""

    vertices: Any
    faces: Any
    rgba: tuple[float, float, float, float] | None  # None: the file gives no colour
    material: str = ''  # the file's material name (id), for a readable MJCF name
    textured: bool = False  # its colour is a texture image (not carried)
    material_id: str = ''  # the file's material id ('' for none)


def dae_unit(path: str | PathLike[str]) -> float:
    """Return a COLLADA file's ``<asset><unit meter>`` (1 when absent), as RViz reads it."""
    from lxml import etree
    try:
        for _, element in etree.iterparse(str(path), events=('end',), tag='{*}unit',
                                          huge_tree=True, no_network=True,
                                          resolve_entities=False):
            parent = element.getparent()
            if parent is None or etree.QName(parent).localname != 'asset' \
                    or parent.getparent() is None or parent.getparent().getparent() is not None:
                continue  # only the document's own <asset>, not a node's
            try:
                unit = float(element.get('meter', '1') or 1.0)
            except ValueError:
                return 1.0  # RViz keeps 1 when the number does not convert
            return unit if unit > 0.0 else 1.0
    except (OSError, etree.XMLSyntaxError) as error:
        raise ModelError(f'{path}: not readable as COLLADA ({error})') from None
    return 1.0


def load_mesh(path: str | PathLike[str]) -> Any:
    """
    Return the triangles of ``path`` as one trimesh mesh, placed as RViz places them.

    Scene transforms applied; a DAE's unit applied and its up axis ignored.

    :raises ModelError: when trimesh cannot read it or it holds no triangles.
    """
    try:
        import trimesh
    except ImportError:
        raise MissingDependencyError('trimesh', 'mesh', f'reading {Path(path).name}') \
            from None
    with _quiet():
        try:
            mesh: Any = trimesh.load(str(path), force='mesh', process=False)
        except Exception as error:  # noqa: B902 - trimesh raises many kinds for a bad file
            raise ModelError(f'{path}: trimesh cannot read it ({error})') from None
    if not len(getattr(mesh, 'faces', ())):
        raise ModelError(f'{path}: no triangles in it (a mesh needs a surface)')
    if Path(path).suffix.lower() == '.dae':
        unit = dae_unit(path)
        if unit != 1.0:
            mesh.vertices = mesh.vertices * unit
    return mesh


def dae_parts(path: str | PathLike[str]) -> list[Part]:
    """
    Return a COLLADA file's triangles grouped by material colour, as RViz places them.

    Each primitive's material gives its diffuse colour (a texture image gives none, and
    ``textured``); primitives of one colour are one part.
    """
    try:
        import collada
        import numpy
    except ImportError:
        raise MissingDependencyError('pycollada', 'mesh', f'reading {Path(path).name}') \
            from None
    try:
        document = collada.Collada(str(path), ignore=[collada.common.DaeUnsupportedError,
                                                      collada.common.DaeBrokenRefError])
    except Exception as error:  # noqa: B902 - pycollada raises many kinds for a bad file
        raise ModelError(f'{path}: not readable as COLLADA ({error})') from None
    unit = dae_unit(path)
    groups: dict[Any, list[Any]] = {}
    for primitive in _primitives(document, collada):
        material = getattr(primitive, 'material', None)
        rgba, name, textured = _colour(material)
        vertices = numpy.asarray(primitive.vertex, dtype=float) * unit
        faces = numpy.asarray(primitive.vertex_index, dtype=numpy.int64).reshape(-1, 3)
        if not len(faces):
            continue
        groups.setdefault((rgba, textured), []).append(
            (vertices, faces, name, str(getattr(material, 'id', '') or '')))
    parts = []
    for (rgba, textured), pieces in groups.items():
        offset, all_vertices, all_faces = 0, [], []
        for vertices, faces, _, _ in pieces:
            all_vertices.append(vertices)
            all_faces.append(faces + offset)
            offset += len(vertices)
        parts.append(Part(numpy.concatenate(all_vertices), numpy.concatenate(all_faces),
                          rgba, pieces[0][2], textured, pieces[0][3]))
    if not parts:
        raise ModelError(f'{path}: no triangles in it (a mesh needs a surface)')
    return parts


def _primitives(document: Any, collada: Any) -> list[Any]:
    """Return the file's triangle sets, node transforms applied (the scene's, else raw)."""
    scene = document.scene
    if scene is not None:
        found = [primitive for bound in scene.objects('geometry')
                 for primitive in bound.primitives()]
    else:
        found = [primitive for geometry in document.geometries
                 for primitive in geometry.primitives]
    triangles = []
    for primitive in found:
        if isinstance(primitive, (collada.triangleset.TriangleSet,
                                  collada.triangleset.BoundTriangleSet)):
            triangles.append(primitive)
        elif hasattr(primitive, 'triangleset'):  # polylist, polygons: triangulated
            triangles.append(primitive.triangleset())
    for triangle in triangles:  # an unbound primitive names its material by symbol only
        if not hasattr(triangle, 'material') or isinstance(triangle.material, str):
            triangle.material = None
    return triangles


def _colour(material: Any) -> tuple[Any, str, bool]:
    """Return a material's diffuse RGBA (None for none or a texture), name, textured."""
    if material is None:
        return None, '', False
    name = str(getattr(material, 'name', None) or getattr(material, 'id', '') or '')
    diffuse = getattr(getattr(material, 'effect', None), 'diffuse', None)
    if isinstance(diffuse, tuple) and len(diffuse) >= 3:
        values = [float(value) for value in diffuse[:4]]
        if len(values) == 3:
            values.append(1.0)
        return tuple(values), name, False
    return None, name, diffuse is not None  # a Map: an image


class _quiet:
    """Silence trimesh's log while it reads (textures it cannot find are not ours to say)."""

    def __enter__(self) -> None:
        self.logger = logging.getLogger('trimesh')
        self.level = self.logger.level
        self.logger.setLevel(logging.CRITICAL)

    def __exit__(self, *_: Any) -> None:
        self.logger.setLevel(self.level)
