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
The mesh assets of an MJCF model: resolved, named uniquely, written beside it.

URIs resolve as everywhere in the package (``package://``, ``file://``, paths relative to
the description). STL and OBJ files are copied as they are when MuJoCo's own loader reads
them, else rewritten; DAE, GLB, GLTF and PLY are converted to OBJ (:mod:`.mesh_convert`),
placed as RViz places them (a DAE's ``<unit meter>`` applied, its ``<up_axis>`` not). A
visual DAE of several colours becomes one OBJ per colour. A mesh's ``scale`` goes on its
asset.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
import re
from typing import Any, TYPE_CHECKING
from urllib.parse import urlparse

from urdfgenpy_ros.formats.mjcf.mesh_convert import (conversion_refusal, convert_many,
                                                     CONVERTED, Converted, converted,
                                                     COPIED, needs_conversion, readable,
                                                     Rgba)
from urdfgenpy_ros.model.errors import ModelError, UrdfgenpyError
from urdfgenpy_ros.model.floats import fmt_vec
from urdfgenpy_ros.model.geometry import Mesh
from urdfgenpy_ros.resources import PackageResolver

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

PACKAGE_HINT = ('source its workspace, or give the folder holding its package: '
                '--package-path on the command line, search_paths in Python')
UNREADABLE_HINT = 'the model has no such geom: repair or re-export the mesh file'


class MeshNotWritten(ModelError):
    """A mesh that cannot be found or read: its geom is left out, and that is a finding."""

    def __init__(self, message: str, hint: str = UNREADABLE_HINT) -> None:
        super().__init__(message)
        self.hint = hint


@dataclass
class MeshAssets:
    """Mesh assets by (file, scale, colour part): their names, and the files to write."""

    resolver: PackageResolver
    base: Path | None
    meshdir: str | None  # None: reference each file where it is (no conversion possible)
    assets: dict[tuple[Path, Any, int], tuple[str, str]] = field(default_factory=dict)
    files: dict[str, bytes] = field(default_factory=dict)  # name -> content (copied, or
    # converted to OBJ): read when added, so a bad file is a finding, not an abort
    notes: list[str] = field(default_factory=list)  # rewritten files, textures not carried
    _names: dict[tuple[Path, int], str] = field(default_factory=dict)
    _textured: list[str] = field(default_factory=list)
    _conversions: dict[Path, Converted] = field(default_factory=dict)

    def prepare(self, robot: RobotModel) -> None:
        """Convert the robot's mesh files that need it, in parallel when there are many."""
        if self.meshdir is None:
            return
        paths = []
        shapes: list[Any] = [shape for link in robot.links
                             for shape in (*link.visuals, *link.collisions)]
        for mesh in [shape.geometry for shape in shapes if isinstance(shape.geometry, Mesh)]:
            try:
                path = self.resolver.resolve(mesh.filename, self.base).resolve()
                if path.is_file() and needs_conversion(path):
                    paths.append(path)
            except (UrdfgenpyError, OSError):
                continue  # said when the geom is written
        convert_many(paths)

    def add(self, mesh: Mesh, where: str) -> str:
        """Return the asset name of ``mesh`` (read at ``where``), adding it when new."""
        return self._asset(self._path(mesh), mesh.scale, -1)

    def add_coloured(self, mesh: Mesh, where: str) -> list[tuple[str, Rgba | None, str]]:
        """
        Return the assets of a visual ``mesh``: one per colour its file gives (a DAE's).

        Each is (asset name, RGBA or None when the file gives none, the file's material).
        """
        path = self._path(mesh)
        if path.suffix.lower() != '.dae' or self.meshdir is None:
            return [(self._asset(path, mesh.scale, -1), None, '')]
        conversion = self._converted(path)
        if conversion.textured and str(path) not in self._textured:
            self._textured.append(str(path))
        if len(conversion.parts) <= 1:
            rgba, name = (conversion.parts[0][1:] if conversion.parts else (None, ''))
            return [(self._asset(path, mesh.scale, -1), rgba, name)]
        return [(self._asset(path, mesh.scale, number), rgba, name)
                for number, (_, rgba, name) in enumerate(conversion.parts)]

    def _path(self, mesh: Mesh) -> Path:
        try:
            path = self.resolver.resolve(mesh.filename, self.base).resolve()
        except UrdfgenpyError as error:  # one hint, said below, not the resolver's too
            reason = str(error)
            if reason.endswith(')') and ' (' in reason:
                reason = reason.rsplit(' (', 1)[0]
            raise MeshNotWritten(reason, self._where_hint(mesh.filename)) from None
        suffix = path.suffix.lower()
        if suffix not in COPIED + CONVERTED:
            raise MeshNotWritten(f'MuJoCo reads STL and OBJ, and urdfgenpy converts '
                                 f'{", ".join(CONVERTED)}', f'the model has no such '
                                 f'geom: convert the {suffix} file to one of them')
        return path

    def _asset(self, path: Path, scale: Any, part: int) -> str:
        key = (path, scale, part)
        if key not in self.assets:
            try:
                written = self._file_name(path, part)
            except (ModelError, OSError) as error:  # unreadable: its geom is left out
                if self.meshdir is None and isinstance(error, ModelError):
                    raise  # it needs a folder to go to: an option, not the mesh
                raise MeshNotWritten(str(error)) from None
            name = _unique(Path(written).stem, {n for n, _ in self.assets.values()})
            self.assets[key] = (name, written)
        return self.assets[key][0]

    def _where_hint(self, uri: str) -> str:
        """Return the fix for a mesh not found: the package's folder, if it was found."""
        parsed = urlparse(uri)
        folder = self.resolver.find(parsed.netloc) if parsed.scheme == 'package' else None
        if folder is None:
            return PACKAGE_HINT
        return (f'the model has no such geom: package {parsed.netloc!r} was found at '
                f'{folder}, and the file is not in it: correct the file name, or install the '
                'mesh into that package')

    def _converted(self, path: Path) -> Converted:
        if path not in self._conversions:
            try:
                self._conversions[path] = converted(path)
            except (ModelError, OSError) as error:
                raise MeshNotWritten(str(error)) from None
        return self._conversions[path]

    def _file_name(self, path: Path, part: int) -> str:
        if (path, part) in self._names:
            return self._names[(path, part)]
        suffix = path.suffix.lower()
        convert = needs_conversion(path)
        if self.meshdir is None:
            if convert:
                raise ModelError(f'{path.name}: a {suffix} mesh is converted to an OBJ file '
                                 'written beside the model: give the MJCF a path')
            name = str(path)
        else:
            stem = path.stem
            if convert:
                conversion = self._converted(path)
                data, suffix = conversion.whole, '.obj'
                if part >= 0:
                    data, _, material = conversion.parts[part]
                    stem = f'{stem}_{_safe(material) or part + 1}'
                refusal = conversion_refusal(path, part, data)
                if refusal is not None:
                    raise ModelError(f'{path}: MuJoCo cannot read its conversion to OBJ '
                                     f'({refusal})')
            else:
                data, suffix, note = readable(path)
                if note:
                    self.notes.append(note)
            taken = {Path(name).stem.lower() for name in self.files}
            name = _unique(stem, taken, lower=True) + suffix
            self.files[name] = data
        self._names[(path, part)] = name
        return name

    def elements(self) -> list[tuple[str, dict[str, str]]]:
        """Return the ``<mesh>`` assets' attributes, in the order they were added."""
        found = []
        for (_, scale, _), (name, written) in self.assets.items():
            attributes = {'name': name, 'file': written}
            if scale is not None:
                attributes['scale'] = fmt_vec(scale)
            found.append(('mesh', attributes))
        return found

    def contents(self) -> dict[str, bytes]:
        """Return each file to write in ``meshdir``: copied, or converted to OBJ."""
        return dict(self.files)

    def said(self) -> list[str]:
        """Return the lines to say: files rewritten, texture images not carried."""
        lines = list(self.notes)
        if self._textured:
            lines.append('meshes: the texture image of ' + ', '.join(self._textured) +
                         ' is not carried (MuJoCo takes a PNG texture with OBJ texture '
                         'coordinates; its geoms keep the colours the file gives)')
        return lines


def _safe(name: str) -> str:
    """Return ``name`` as a file-name part (letters, digits, ``_``, ``-``, ``.``)."""
    return re.sub(r'[^A-Za-z0-9_.-]+', '_', name).strip('._')[:40]


def _unique(name: str, taken: set[str], lower: bool = False) -> str:
    candidate, number = name, 2
    while (candidate.lower() if lower else candidate) in taken:
        candidate, number = f'{name}_{number}', number + 1
    return candidate
