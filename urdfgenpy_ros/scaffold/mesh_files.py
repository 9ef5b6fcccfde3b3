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
The files a mesh refers to beside itself: a COLLADA file's images, an OBJ file's materials.

A mesh copied into a package without them loses its textures; they are copied along,
under the same relative names.
"""

from __future__ import annotations

from pathlib import Path, PurePosixPath
import re
from urllib.parse import unquote

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
