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
Where a mesh goes in the new package, and the files it refers to beside itself.

A mesh keeps its file name; two different meshes of one name keep the folders their URIs
name below their package (``visual/base.stl``, ``collision/base.stl``), then the
package's name before them: readable names, never a hash. A COLLADA file's images and an
OBJ file's materials are copied along, under the same names relative to the mesh.
"""

from __future__ import annotations

from pathlib import Path, PurePosixPath
import posixpath
import re
from urllib.parse import unquote, urlparse

_INIT_FROM = re.compile(rb'<init_from>\s*([^<\s]+)\s*</init_from>')
_MTLLIB = re.compile(rb'^\s*mtllib\s+(.+?)\s*$', re.MULTILINE)
_MAPS = re.compile(rb'^\s*(?:map_\w+|bump|disp|decal|refl)\s+(?:-\S+\s+\S+\s+)*(\S+)\s*$',
                   re.MULTILINE)


def companions(mesh: Path, data: bytes) -> dict[str, Path]:
    """
    Return the files ``mesh`` (read as ``data``) names beside it: relative name to path.

    Only relative names inside the mesh's folder count (``textures/wood.png``, not
    ``../x.png`` or an absolute path); names that are no file are left out.
    """
    suffix = mesh.suffix.lower()
    if suffix == '.dae':
        names = [unquote(found.decode('utf-8', 'replace')) for found in _INIT_FROM.findall(data)]
    elif suffix == '.obj':
        names = [found.decode('utf-8', 'replace') for found in _MTLLIB.findall(data)]
    elif suffix == '.mtl':
        names = [found.decode('utf-8', 'replace') for found in _MAPS.findall(data)]
    else:
        return {}
    found: dict[str, Path] = {}
    for name in names:
        name = name.removeprefix('file://').removeprefix('./')
        relative = PurePosixPath(name)
        if relative.is_absolute() or '..' in relative.parts or not name:
            continue
        path = mesh.parent / relative
        if path.is_file():
            found[relative.as_posix()] = path
            if path.suffix.lower() == '.mtl':  # an OBJ's materials name its images
                found.update({f'{relative.parent}/{inner}'.lstrip('./'): inner_path
                              for inner, inner_path in companions(
                                  path, path.read_bytes()).items()})
    return found


def mesh_names(uri: str) -> list[str]:
    """
    Return the names ``uri``'s mesh may take under ``meshes/``, the shortest first.

    ``package://pkg/meshes/visual/../base.stl`` gives ``base.stl``, then ``pkg/base.stl``;
    ``package://pkg/meshes/visual/base.stl`` gives ``base.stl``, ``visual/base.stl``,
    ``pkg/visual/base.stl``. The path is normalised first (no ``..`` is left).
    """
    parsed = urlparse(uri)
    path = unquote(parsed.path if parsed.scheme in ('package', 'file') else uri)
    parts = [part for part in posixpath.normpath('/' + path.replace('\\', '/')).split('/')
             if part and part != '..']
    if not parts:
        return []
    if parsed.scheme == 'package' and parsed.netloc:
        package = parsed.netloc
    else:  # a path or file URI: the folders above it stand for a package
        package, parts = (parts[-3] if len(parts) > 2 else ''), parts[-2:]
    inside = parts[1:] if len(parts) > 1 and parts[0] in ('meshes', 'mesh', 'models') \
        else parts
    names = ['/'.join(inside[index:]) for index in range(len(inside) - 1, -1, -1)]
    return names + ([f'{package}/{names[-1]}'] if package else [])


def numbered(name: str, number: int) -> str:
    """Return ``name`` with ``_<number>`` before its suffix: ``base_2.stl``."""
    stem, dot, suffix = name.rpartition('.')
    return f'{stem}_{number}.{suffix}' if dot and stem else f'{name}_{number}'
