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
the description). STL and OBJ files are copied as they are; DAE, GLB, GLTF and PLY are
converted to OBJ with trimesh, a DAE's ``<unit meter>`` and ``<up_axis>`` applied (as
RViz and Gazebo read it). A mesh's ``scale`` goes on its asset.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any
from urllib.parse import urlparse

from urdfgenpy_ros.errors import MissingDependencyError, ModelError, UrdfgenpyError
from urdfgenpy_ros.floats import fmt_vec
from urdfgenpy_ros.geometry import Mesh
from urdfgenpy_ros.resources import PackageResolver

COPIED = ('.stl', '.obj')
CONVERTED = ('.dae', '.glb', '.gltf', '.ply')


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
    """Mesh assets by (file, scale): their names, and the files to write in ``meshdir``."""

    resolver: PackageResolver
    base: Path | None
    meshdir: str | None  # None: reference each file where it is (no conversion possible)
    assets: dict[tuple[Path, Any], tuple[str, str]] = field(default_factory=dict)
    files: dict[str, bytes] = field(default_factory=dict)  # name -> content (copied, or
    # converted to OBJ): read when added, so a bad file is a finding, not an abort
    _names: dict[Path, str] = field(default_factory=dict)

    def add(self, mesh: Mesh, where: str) -> str:
        """Return the asset name of ``mesh`` (read at ``where``), adding it when new."""
        try:
            path = self.resolver.resolve(mesh.filename, self.base).resolve()
        except UrdfgenpyError as error:  # one hint, said below, not the resolver's too
            reason = str(error)
            if reason.endswith(')') and ' (' in reason:
                reason = reason.rsplit(' (', 1)[0]
            raise MeshNotWritten(reason, self._where_hint(mesh.filename)) from None
        key = (path, mesh.scale)
        if key not in self.assets:
            suffix = path.suffix.lower()
            if suffix not in COPIED + CONVERTED:
                raise MeshNotWritten(f'MuJoCo reads STL and OBJ, and urdfgenpy converts '
                                     f'{", ".join(CONVERTED)}', f'the model has no such '
                                     f'geom: convert the {suffix} file to one of them')
            try:
                written = self._file_name(path)
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

    def _file_name(self, path: Path) -> str:
        if path in self._names:
            return self._names[path]
        suffix = path.suffix.lower()
        convert = suffix in CONVERTED or (suffix == '.stl' and not is_mujoco_stl(path))
        if self.meshdir is None:
            if convert:
                raise ModelError(f'{path.name}: a {suffix} mesh is converted to an OBJ file '
                                 'written beside the model: give the MJCF a path')
            name = str(path)
        else:
            data = converted_obj(path) if convert else path.read_bytes()
            taken = {Path(name).stem.lower() for name in self.files}
            stem = _unique(path.stem, taken, lower=True)
            name = stem + ('.obj' if convert else suffix)
            self.files[name] = data
        self._names[path] = name
        return name

    def elements(self) -> list[tuple[str, dict[str, str]]]:
        """Return the ``<mesh>`` assets' attributes, in the order they were added."""
        found = []
        for (_, scale), (name, written) in self.assets.items():
            attributes = {'name': name, 'file': written}
            if scale is not None:
                attributes['scale'] = fmt_vec(scale)
            found.append(('mesh', attributes))
        return found

    def contents(self) -> dict[str, bytes]:
        """Return each file to write in ``meshdir``: copied, or converted to OBJ."""
        return dict(self.files)


STL_FACES = 200000  # MuJoCo's stl_decoder reads binary STL of 1 to 200000 triangles


def is_mujoco_stl(path: Path) -> bool:
    """Return whether MuJoCo reads the STL file ``path`` (binary, at most 200000 faces)."""
    with open(path, 'rb') as stream:
        head = stream.read(1024)
    if head.lstrip().startswith(b'solid') and b'facet' in head:
        return False  # ASCII
    count = int.from_bytes(head[80:84], 'little') if len(head) >= 84 else 0
    return 1 <= count <= STL_FACES


def _unique(name: str, taken: set[str], lower: bool = False) -> str:
    candidate, number = name, 2
    while (candidate.lower() if lower else candidate) in taken:
        candidate, number = f'{name}_{number}', number + 1
    return candidate


def converted_obj(path: Path) -> bytes:
    """Return the OBJ text of the mesh file ``path`` (a DAE's unit and up axis applied)."""
    try:
        import numpy
        import trimesh
    except ImportError:
        raise MissingDependencyError('trimesh', 'mesh', f'converting {path.name} for '
                                     'MuJoCo') from None
    mesh = load_mesh(path)
    if path.suffix.lower() == '.dae':
        unit, up = dae_frame(path)
        transform = numpy.eye(4) * unit
        transform[3, 3] = 1.0
        if up == 'Y_UP':  # +Y up becomes +Z up: +90 degrees about X
            transform = transform @ trimesh.transformations.rotation_matrix(
                numpy.pi / 2.0, (1, 0, 0))
        elif up == 'X_UP':  # +X up becomes +Z up: -90 degrees about Y
            transform = transform @ trimesh.transformations.rotation_matrix(
                -numpy.pi / 2.0, (0, 1, 0))
        mesh.apply_transform(transform)
    return obj_text(mesh.vertices.ravel().tolist(), (mesh.faces + 1).ravel().tolist())


def obj_text(coordinates: list[float], corners: list[int]) -> bytes:
    """
    Return OBJ text of a triangle mesh, each coordinate exact (the shortest repr).

    ``coordinates`` are x, y, z of each vertex in a row; ``corners`` the three 1-based
    vertex numbers of each face in a row.
    """
    numbers = list(map(repr, coordinates))
    vertices = map('v {} {} {}'.format, numbers[0::3], numbers[1::3], numbers[2::3])
    faces = map('f {} {} {}'.format, corners[0::3], corners[1::3], corners[2::3])
    return ('\n'.join(vertices) + '\n' + '\n'.join(faces) + '\n').encode('ascii')


def load_mesh(path: Path) -> Any:
    """Return the triangles of ``path`` as one trimesh mesh (scene transforms applied)."""
    import logging

    import trimesh
    logger = logging.getLogger('trimesh')
    level = logger.level
    logger.setLevel(logging.CRITICAL)  # textures it cannot find: MuJoCo takes no texture
    try:
        mesh = trimesh.load(str(path), force='mesh', process=False)
    except Exception as error:  # noqa: B902 - trimesh raises many kinds for a bad file
        raise ModelError(f'{path}: trimesh cannot read it ({error})') from None
    finally:
        logger.setLevel(level)
    if not len(getattr(mesh, 'faces', ())):
        raise ModelError(f'{path}: no triangles in it (MuJoCo needs a surface)')
    return mesh


def dae_frame(path: Path) -> tuple[float, str]:
    """Return a DAE file's ``<unit meter>`` (1 when absent) and ``<up_axis>`` (Z_UP)."""
    from lxml import etree
    try:
        root = etree.parse(str(path), etree.XMLParser(huge_tree=True, no_network=True,
                                                      resolve_entities=False)).getroot()
    except (OSError, etree.XMLSyntaxError) as error:
        raise ModelError(f'{path}: not readable as COLLADA ({error})') from None
    unit, up = 1.0, 'Z_UP'
    for element in root.iter('{*}unit'):
        try:
            unit = float(element.get('meter', '1') or 1.0)
        except ValueError:
            pass
        break
    for element in root.iter('{*}up_axis'):
        up = (element.text or 'Z_UP').strip().upper()
        break
    return unit, up
