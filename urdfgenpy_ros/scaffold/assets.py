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
Bring every file the robot names into the new package, referred to through the package.

A Gazebo block's ``$(find pkg)/config/controllers.yaml`` has become, once xacro expanded it,
an absolute path of this machine; a material's texture a ``package://`` URI of another
package. Each such file is copied into the package (``config/``, or ``meshes/`` for meshes
and images) and named ``$(find <package>)/...`` in Xacro text, ``package://<package>/...``
where a URI was. A path that is no file but lies in the folder of a package the resolver
finds (a controllers YAML that package installs, not in the folder given) is written back
as ``$(find <that package>)/...``, and the package depends on it. Meshes themselves are
copied by the scaffolder's mesh pass.
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path
import re

from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.resources import _package_name, PackageResolver, ResourceError
from urdfgenpy_ros.robot import Robot

FIND_MARK = 'urdfgenpyfindmark'
"""Stands for ``$(find <package>)`` until the Xacro files are written (the writer escapes $)."""

_MESHES = {'.stl', '.dae', '.obj', '.ply', '.glb', '.gltf', '.mtl', '.png', '.jpg', '.jpeg',
           '.tga', '.bmp', '.tif', '.tiff'}
_TOKENS = re.compile(r'(\s+)')
_FIND = re.compile(FIND_MARK + r'(?:\.([A-Za-z0-9_]+)\.)?')


class _Copier:
    """Copy the files values name, remembering what each became."""

    def __init__(self, package: str, resolver: PackageResolver, reserved: set[str]) -> None:
        self.package = package
        self.resolver = resolver
        self.reserved = reserved
        self.files: dict[str, bytes] = {}
        self.done: dict[Path, str] = {}
        self.borrowed: dict[str, tuple[str, str]] = {}  # path: its package, the rest

    def value(self, text: str, uri: bool = False) -> str:
        """
        Return ``text`` with every file path or URI in it pointing into the package.

        A path becomes ``$(find <package>)/...``, or ``package://<package>/...`` with ``uri``.
        """
        return ''.join(self._token(token, uri) for token in _TOKENS.split(text))

    def _token(self, token: str, uri: bool) -> str:
        if token.startswith('package://'):
            try:
                path = self.resolver.resolve(token)
            except ResourceError:
                return token
            prefix = f'package://{self.package}/'
        elif token.startswith('file://') and os.path.isabs(token[len('file://'):]):
            path, prefix = Path(token[len('file://'):]), f'file://{FIND_MARK}/'
        elif os.path.isabs(token):
            path = Path(token)
            prefix = f'package://{self.package}/' if uri else f'{FIND_MARK}/'
        else:
            return token
        if not path.is_file():
            return self._borrowed(token, path, uri)
        return prefix + self._copy(path.resolve())

    def _borrowed(self, token: str, path: Path, uri: bool) -> str:
        """Return a path in another package's folder as found through it, else ``token``."""
        for folder in path.parents:
            name = _package_name(folder)
            if name is None:
                continue
            found = self.resolver.find(name)
            if found is None or found.resolve() != folder.resolve():
                return token
            rest = path.relative_to(folder).as_posix()
            self.borrowed[str(path)] = name, rest
            return f'package://{name}/{rest}' if uri else f'{FIND_MARK}.{name}./{rest}'
        return token

    def _copy(self, path: Path) -> str:
        """Copy ``path`` into the package once; return its path relative to the package."""
        if path not in self.done:
            data = path.read_bytes()
            folder = 'meshes' if path.suffix.lower() in _MESHES else 'config'
            name = path.name
            relative = f'{folder}/{name}'
            if relative in self.reserved or self.files.get(relative, data) != data:
                relative = f'{folder}/{hashlib.sha1(data).hexdigest()[:8]}_{name}'
            self.files[relative] = data
            self.done[path] = relative
        return self.done[path]


def copy_referenced_files(package: str, robot: Robot, search_paths: list[str],
                          reserved: set[str],
                          borrowed: dict[str, tuple[str, str]] | None = None
                          ) -> dict[str, bytes]:
    """
    Copy the files ``robot``'s blocks and textures name into the package; point them there.

    ``robot`` is edited (give it a copy); ``reserved`` are package paths the templates
    write. Return the files to add (package path: bytes). Each path written back through
    another package goes into ``borrowed``: path, that package and the path in it.
    """
    copier = _Copier(package, PackageResolver(search_paths), reserved)
    owners: list = [*robot.links, *robot.joints]
    blocks = [*robot.extensions, *(block for owner in owners for block in owner.extensions)]
    for block in blocks:
        for element in block.element.iter():
            if not isinstance(element.tag, str):
                continue
            for key, value in element.attrib.items():
                element.set(key, copier.value(value))
            if element.text and element.text.strip():
                element.text = copier.value(element.text)
    textures: dict[int, Material] = {}

    def moved(material: Material) -> Material:
        if material.texture is None:
            return material
        if id(material) not in textures:
            texture = copier.value(material.texture, uri=True)
            textures[id(material)] = material if texture == material.texture else Material(
                material.name, material.rgba, texture, source=material.source,
                extras=material.extras)
        return textures[id(material)]

    robot._map_materials(moved)
    for link in robot.links:
        for visual in link.visuals:
            if visual.material is not None:
                visual.material = moved(visual.material)
    if borrowed is not None:
        borrowed.update(copier.borrowed)
    return copier.files


def with_find(text: str, package: str) -> str:
    """Return Xacro text with the marks replaced by ``$(find <package>)`` (or another's)."""
    return _FIND.sub(lambda found: f'$(find {found.group(1) or package})', text)
