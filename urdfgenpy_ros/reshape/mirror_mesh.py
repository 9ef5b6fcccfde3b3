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
Meshes for a mirrored limb: each file written reflected, once, beside the original.

A mesh is read as RViz reads it (:mod:`urdfgenpy_ros.model.mesh_read`): a DAE is written back
with its unit applied, Z up, and its materials (colours) kept; a binary STL is reflected
byte for byte; other files through trimesh. Reflections are kept by content in the mesh
cache (:mod:`urdfgenpy_ros.mesh_cache`). With a mesh folder, the mirrored limb names its
files by ``package://`` where that folder is in a package found, else by ``file://``.

Nothing is written until the whole mirror is known to succeed (:meth:`MeshWriter.commit`);
then every file is written, or, when one cannot be, none is left behind. A file already
there is kept when it holds the same mirror image (compared by its vertices and faces, as
exporters stamp DAE files with dates and ids), and never overwritten otherwise.
"""

from __future__ import annotations

import io
from os import PathLike
from pathlib import Path
from typing import Any
import warnings

from urdfgenpy_ros.model.errors import MissingDependencyError, ModelError
from urdfgenpy_ros.model.geometry import Mesh

FLIPPED_AXIS = {'yz': 0, 'xz': 1, 'xy': 2}  # plane -> the axis its reflection flips
_VERSION = '1'  # of the mirrored files' format: a new version is a new cache key
_SAME = 1e-6  # vertices this close (relative to the mesh's size) are the same (STL: float32)


class _Planned:
    """One mirrored file to write: where, its bytes, and its geometry."""

    def __init__(self, target: Path, data: bytes, mesh: Any, uri: str) -> None:
        self.target, self.data, self.mesh, self.uri = target, data, mesh, uri


class MeshWriter:
    """Plan each mesh reflected, once; return the Mesh that names the new file."""

    def __init__(self, robot: Any, plane: str, folder: str | PathLike[str] | None,
                 search_paths: tuple) -> None:
        from urdfgenpy_ros.resources import PackageResolver
        self.resolver = PackageResolver(search_paths)
        source = getattr(robot, 'source', None)
        file = getattr(source, 'file', None) if source is not None else None
        self.relative_to = Path(file).parent if file else None
        self.plane = plane
        self.folder = Path(folder) if folder is not None else None
        self.done: dict[str, str] = {}  # URI as written -> the mirrored file's URI
        self.by_source: dict[Path, str] = {}  # resolved original -> the mirrored file's URI
        self.planned: dict[Path, _Planned] = {}  # target -> what goes there

    def mirrored(self, mesh: Mesh, link: str) -> Mesh:
        """Return ``mesh`` naming its mirror image (planned, written by :meth:`commit`)."""
        if mesh.filename not in self.done:
            self.done[mesh.filename] = self._plan(mesh.filename, link)
        return Mesh(self.done[mesh.filename], mesh.scale, source=mesh.source,
                    extras=mesh.extras)

    def _plan(self, uri: str, link: str) -> str:
        path = self.resolver.resolve(uri, self.relative_to).absolute()
        if path in self.by_source:
            return self.by_source[path]
        folder = self.folder or path.parent
        suffix = path.suffix
        target = folder / f'{path.stem}_mirror_{self.plane}{suffix}'
        number = 1
        while target in self.planned:  # another mesh of the same name: a name of its own
            target = folder / f'{path.stem}_mirror_{self.plane}_{number}{suffix}'
            number += 1
        data, beside = self._reflected(path, target, link)
        if target.exists() and not _same_geometry(target, data, suffix):
            raise ModelError(f'mirror: {target} exists and is not the mirror of {path} '
                             f'(link {link!r}): move it away, or pass mesh_folder=')
        for name, content in beside.items():  # an OBJ's material and texture image
            other = folder / name
            if other.exists() and other.read_bytes() != content:
                raise ModelError(f'mirror: {other} exists and is not the material of '
                                 f'{target.name} (link {link!r}): move it away, or pass '
                                 'mesh_folder=')
        if self.folder is not None:
            written = self._uri(target)
        else:
            head, _, _ = uri.rpartition('/')
            written = f'{head}/{target.name}' if head else target.name
        self.planned[target] = _Planned(target, data, None, written)
        for name, content in beside.items():
            self.planned.setdefault(folder / name, _Planned(folder / name, content, None, ''))
        self.by_source[path] = written
        return written

    def _reflected(self, path: Path, target: Path, link: str) -> tuple[bytes, dict[str, bytes]]:
        """Return the mirror image's bytes and the files it needs beside it."""
        from urdfgenpy_ros import mesh_cache
        source = path.read_bytes()
        kind = path.suffix.lower()
        axis = FLIPPED_AXIS[self.plane]
        if kind == '.dae' or (kind == '.stl' and _is_binary_stl(source)):
            if kind == '.dae' and b'<texture' in source:
                _warn_texture(path, target, link)
            name = mesh_cache.key(f'mirror{_VERSION}{self.plane}{kind}', source)
            return mesh_cache.cached(name, lambda: (
                _reflected_dae(path, axis) if kind == '.dae'
                else _reflected_stl(source, axis))), {}
        try:
            import numpy
            import trimesh
        except ImportError:
            raise MissingDependencyError('trimesh', 'mesh', 'Mirroring meshes') from None
        loaded = trimesh.load(str(path), force='mesh')
        flip = numpy.eye(4)
        flip[axis, axis] = -1.0
        loaded.apply_transform(flip)  # trimesh turns the faces round: normals stay outward
        data, beside = _export(loaded, target)
        if not beside and _has_image(loaded):
            _warn_texture(path, target, link)
        return data, beside

    def _uri(self, target: Path) -> str:
        """Return a ``package://`` URI of ``target`` where its package is found, else file://."""
        for folder in target.absolute().parents:
            if (folder / 'package.xml').is_file():
                from urdfgenpy_ros.resources import _package_name
                name = _package_name(folder)
                if name and self.resolver.find(name) == folder:
                    return f'package://{name}/{target.absolute().relative_to(folder).as_posix()}'
                break
        return target.absolute().as_uri()

    def commit(self) -> None:
        """Write every planned file not already there; on failure remove those written."""
        written: list[Path] = []
        try:
            for plan in self.planned.values():
                if plan.target.exists():  # the same mirror image (checked when planned)
                    continue
                plan.target.parent.mkdir(parents=True, exist_ok=True)
                with open(plan.target, 'xb') as stream:
                    written.append(plan.target)
                    stream.write(plan.data)
        except OSError as error:
            for path in written:
                path.unlink(missing_ok=True)
            raise ModelError(f'mirror: cannot write {error.filename}: {error.strerror} '
                             '(nothing was written; pass mesh_folder= a folder you can '
                             'write)') from None


def _export(mesh: Any, target: Path) -> tuple[bytes, dict[str, bytes]]:
    """Return the file's bytes and the files it needs beside it (an OBJ's material)."""
    kind = target.suffix.lstrip('.').lower()
    if kind == 'obj' and getattr(mesh.visual, 'kind', None) == 'texture':
        from trimesh.exchange.obj import export_obj
        mesh.visual.material.name = target.stem  # its image is named after it: no clash
        text, files = export_obj(mesh, return_texture=True, mtl_name=f'{target.stem}.mtl')
        return text.encode(), {name: bytes(content) for name, content in files.items()}
    data = mesh.export(None, file_type=kind)
    return (data if isinstance(data, bytes) else data.encode()), {}


def _same_geometry(target: Path, data: bytes, suffix: str) -> bool:
    """Return whether ``target`` holds the triangles ``data`` does (in any order)."""
    if target.read_bytes() == data:  # a mirror written before: no mesh library to load
        return True
    import trimesh
    kind = suffix.lstrip('.').lower()
    try:
        there: Any = trimesh.load(str(target), force='mesh', process=False)
        new: Any = trimesh.load(io.BytesIO(data), file_type=kind, force='mesh', process=False)
    except Exception:  # noqa: BLE001 (not a mesh trimesh reads: not the same)
        return False
    if not hasattr(there, 'faces') or there.faces.shape != new.faces.shape:
        return False
    return _same_triangles(there.vertices[there.faces], new.vertices[new.faces])


def _same_triangles(first: Any, second: Any) -> bool:
    """Return whether two (n, 3, 3) triangle arrays hold the same triangles, wound alike."""
    import numpy
    size = max(float(numpy.max(numpy.ptp(second.reshape(-1, 3), axis=0))), 1e-9) \
        if len(second) else 1.0
    tolerance = _SAME * size

    def canonical(triangles: Any) -> Any:
        rounded = numpy.round(triangles.reshape(-1, 3) / tolerance).astype(numpy.int64)
        _, rank = numpy.unique(rounded, axis=0, return_inverse=True)
        start = numpy.argmin(rank.reshape(-1, 3), axis=1)  # corners in lexicographic order
        order = (start[:, None] + numpy.arange(3)) % 3  # the same corner first: winding kept
        turned = numpy.take_along_axis(triangles, order[:, :, None], axis=1)
        flat = turned.reshape(len(triangles), 9)
        return flat[numpy.lexsort(numpy.round(flat / tolerance).T[::-1])]
    return bool(numpy.allclose(canonical(first), canonical(second), rtol=0.0,
                               atol=2.0 * tolerance))


def _has_image(loaded: Any) -> bool:
    material = getattr(getattr(loaded, 'visual', None), 'material', None)
    return getattr(material, 'image', None) is not None or \
        getattr(material, 'baseColorTexture', None) is not None


def _warn_texture(path: Path, target: Path, link: str) -> None:
    """Warn, in one line, when the mirrored file loses the original's texture image."""
    warnings.warn(f'mirror: {path} (link {link!r}) has a texture image, which its '
                  f'mirror image {target.name} does not keep (its colours are kept): give '
                  'the mirrored visual a <material> or retexture it', stacklevel=5)


def _is_binary_stl(data: bytes) -> bool:
    """Return whether ``data`` is a binary STL file (its size says so exactly)."""
    return len(data) >= 84 and len(data) == 84 + 50 * int.from_bytes(data[80:84], 'little')


def _reflected_stl(data: bytes, axis: int) -> bytes:
    """Return a binary STL reflected across the plane normal to ``axis`` (bytes exact)."""
    import numpy
    record = numpy.dtype([('normal', '<f4', 3), ('corners', '<f4', (3, 3)), ('extra', '<u2')])
    faces = numpy.frombuffer(data, dtype=record, offset=84).copy()
    faces['normal'][:, axis] *= -1.0
    faces['corners'][:, :, axis] *= -1.0
    faces['corners'][:, [1, 2]] = faces['corners'][:, [2, 1]]  # the normals stay outward
    return data[:84] + faces.tobytes()


def _reflected_dae(path: Path, axis: int) -> bytes:
    """Return a DAE reflected, as RViz places it (unit applied), its materials kept."""
    from lxml import etree

    from urdfgenpy_ros.model.mesh_read import dae_parts
    parts = dae_parts(path)
    source = etree.parse(str(path), etree.XMLParser(huge_tree=True, no_network=True,
                                                    resolve_entities=False)).getroot()
    space = etree.QName(source).namespace
    tag = (lambda name: f'{{{space}}}{name}') if space else (lambda name: name)
    root = etree.Element(tag('COLLADA'), nsmap={None: space} if space else None,
                         version=source.get('version', '1.4.1'))
    asset = etree.SubElement(root, tag('asset'))
    etree.SubElement(asset, tag('unit'), name='meter', meter='1')
    etree.SubElement(asset, tag('up_axis')).text = 'Z_UP'
    for library in ('library_images', 'library_effects', 'library_materials'):
        for found in source.findall(tag(library)):
            root.append(found)  # each colour as the file gave it
    geometries = etree.SubElement(root, tag('library_geometries'))
    scene = etree.SubElement(etree.SubElement(root, tag('library_visual_scenes')),
                             tag('visual_scene'), id='scene')
    for number, part in enumerate(parts):
        _dae_geometry(geometries, scene, tag, number, part, axis)
    etree.SubElement(etree.SubElement(root, tag('scene')), tag('instance_visual_scene'),
                     url='#scene')
    return etree.tostring(root, xml_declaration=True, encoding='utf-8')


def _dae_geometry(geometries: Any, scene: Any, tag: Any, number: int, part: Any,
                  axis: int) -> None:
    """Add one part's triangles, reflected, and the node that places it."""
    import numpy
    from lxml import etree
    used, corners = numpy.unique(part.faces, return_inverse=True)
    vertices = numpy.asarray(part.vertices, dtype=float)[used]
    vertices[:, axis] *= -1.0
    faces = corners.reshape(-1, 3)[:, [0, 2, 1]]  # the normals stay outward
    name = f'part{number}'
    geometry = etree.SubElement(geometries, tag('geometry'), id=name)
    mesh = etree.SubElement(geometry, tag('mesh'))
    source = etree.SubElement(mesh, tag('source'), id=f'{name}-positions')
    etree.SubElement(source, tag('float_array'), id=f'{name}-array',
                     count=str(vertices.size)).text = ' '.join(map(repr, vertices.ravel()
                                                                   .tolist()))
    accessor = etree.SubElement(etree.SubElement(source, tag('technique_common')),
                                tag('accessor'), source=f'#{name}-array',
                                count=str(len(vertices)), stride='3')
    for axis_name in 'XYZ':
        etree.SubElement(accessor, tag('param'), name=axis_name, type='float')
    points = etree.SubElement(mesh, tag('vertices'), id=f'{name}-vertices')
    etree.SubElement(points, tag('input'), semantic='POSITION', source=f'#{name}-positions')
    triangles = etree.SubElement(mesh, tag('triangles'), count=str(len(faces)))
    etree.SubElement(triangles, tag('input'), semantic='VERTEX', source=f'#{name}-vertices',
                     offset='0')
    etree.SubElement(triangles, tag('p')).text = ' '.join(map(str, faces.ravel().tolist()))
    node = etree.SubElement(scene, tag('node'), id=f'{name}-node')
    instance = etree.SubElement(node, tag('instance_geometry'), url=f'#{name}')
    if part.material_id:
        triangles.set('material', 'material')
        common = etree.SubElement(etree.SubElement(instance, tag('bind_material')),
                                  tag('technique_common'))
        etree.SubElement(common, tag('instance_material'), symbol='material',
                         target=f'#{part.material_id}')
