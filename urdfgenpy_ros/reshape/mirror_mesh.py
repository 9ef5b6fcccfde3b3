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

from urdfgenpy_ros.errors import MissingDependencyError, ModelError
from urdfgenpy_ros.geometry import Mesh

FLIPPED_AXIS = {'yz': 0, 'xz': 1, 'xy': 2}  # plane -> the axis its reflection flips
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
        try:
            import numpy
            import trimesh
        except ImportError:
            raise MissingDependencyError('trimesh', 'mesh', 'Mirroring meshes') from None
        path = self.resolver.resolve(uri, self.relative_to).absolute()
        if path in self.by_source:
            return self.by_source[path]
        loaded = trimesh.load(str(path), force='mesh')
        flip = numpy.eye(4)
        axis = FLIPPED_AXIS[self.plane]
        flip[axis, axis] = -1.0
        loaded.apply_transform(flip)  # trimesh turns the faces round: normals stay outward
        folder = self.folder or path.parent
        suffix = path.suffix
        target = folder / f'{path.stem}_mirror_{self.plane}{suffix}'
        number = 1
        while target in self.planned:  # another mesh of the same name: a name of its own
            target = folder / f'{path.stem}_mirror_{self.plane}_{number}{suffix}'
            number += 1
        data, beside = _export(loaded, target)
        if not beside:
            _warn_texture(loaded, path, target, link)
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
            written = str(target.absolute())
        else:
            head, _, _ = uri.rpartition('/')
            written = f'{head}/{target.name}' if head else target.name
        self.planned[target] = _Planned(target, data, loaded, written)
        for name, content in beside.items():
            self.planned.setdefault(folder / name, _Planned(folder / name, content, None, ''))
        self.by_source[path] = written
        return written

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
    """Return whether ``target`` holds the mesh ``data`` does (vertices and faces)."""
    import numpy
    import trimesh
    if target.read_bytes() == data:
        return True
    kind = suffix.lstrip('.').lower()
    try:
        there: Any = trimesh.load(str(target), force='mesh')
        new: Any = trimesh.load(io.BytesIO(data), file_type=kind, force='mesh')
    except Exception:  # noqa: BLE001 (not a mesh trimesh reads: not the same)
        return False
    if not hasattr(there, 'vertices') or there.vertices.shape != new.vertices.shape \
            or there.faces.shape != new.faces.shape:
        return False
    size = max(float(numpy.max(numpy.ptp(new.vertices, axis=0))), 1e-9) \
        if len(new.vertices) else 1.0
    return bool(numpy.array_equal(there.faces, new.faces)
                and numpy.allclose(there.vertices, new.vertices, rtol=0.0, atol=_SAME * size))


def _warn_texture(loaded: Any, path: Path, target: Path, link: str) -> None:
    """Warn, in one line, when the mirrored file loses the original's texture image."""
    material = getattr(getattr(loaded, 'visual', None), 'material', None)
    image = getattr(material, 'image', None)
    if image is None:
        image = getattr(material, 'baseColorTexture', None)
    if image is not None:
        warnings.warn(f'mirror: {path} (link {link!r}) has a texture image, which its '
                      f'mirror image {target.name} does not keep (trimesh writes the shape '
                      'and colours only): give the mirrored visual a <material> or retexture '
                      'it', stacklevel=4)
