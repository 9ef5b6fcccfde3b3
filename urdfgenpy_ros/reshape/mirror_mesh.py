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

"""Meshes for a mirrored limb: each file written reflected, once, beside the original."""

from __future__ import annotations

import hashlib
from os import PathLike
from pathlib import Path
from typing import Any

from urdfgenpy_ros.errors import MissingDependencyError, ModelError
from urdfgenpy_ros.geometry import Mesh

FLIPPED_AXIS = {'yz': 0, 'xz': 1, 'xy': 2}  # plane -> the axis its reflection flips


class MeshWriter:
    """Write each mesh reflected, once, and return the Mesh that names the new file."""

    def __init__(self, robot: Any, plane: str, folder: str | PathLike[str] | None,
                 search_paths: tuple) -> None:
        from urdfgenpy_ros.resources import PackageResolver
        self.resolver = PackageResolver(search_paths)
        source = getattr(robot, 'source', None)
        file = getattr(source, 'file', None) if source is not None else None
        self.relative_to = Path(file).parent if file else None
        self.plane = plane
        self.folder = Path(folder) if folder is not None else None
        self.done: dict[str, str] = {}

    def mirrored(self, mesh: Mesh, link: str) -> Mesh:
        if mesh.filename not in self.done:
            self.done[mesh.filename] = self._write(mesh.filename, link)
        return Mesh(self.done[mesh.filename], mesh.scale, source=mesh.source,
                    extras=mesh.extras)

    def _write(self, uri: str, link: str) -> str:
        try:
            import numpy
            import trimesh
        except ImportError:
            raise MissingDependencyError('trimesh', 'mesh', 'Mirroring meshes') from None
        path = self.resolver.resolve(uri, self.relative_to)
        loaded = trimesh.load(str(path), force='mesh')
        flip = numpy.eye(4)
        axis = FLIPPED_AXIS[self.plane]
        flip[axis, axis] = -1.0
        loaded.apply_transform(flip)  # trimesh turns the faces round: normals stay outward
        name = f'{path.stem}_mirror_{self.plane}{path.suffix}'
        folder = self.folder or path.parent
        folder.mkdir(parents=True, exist_ok=True)
        target = folder / name
        data = loaded.export(None, file_type=path.suffix.lstrip('.').lower())
        data = data if isinstance(data, bytes) else data.encode()
        if target.exists() and hashlib.sha256(target.read_bytes()).digest() != \
                hashlib.sha256(data).digest():
            raise ModelError(f'mirror: {target} exists and is not the mirror of {path} '
                             f'(link {link!r}): move it away, or pass mesh_folder=')
        target.write_bytes(data)
        if self.folder is not None:
            return str(target.absolute())
        head, _, _ = uri.rpartition('/')
        return f'{head}/{name}' if head else name
