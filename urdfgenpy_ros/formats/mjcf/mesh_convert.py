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
Mesh files made readable by MuJoCo: converted to OBJ once (kept by content), then checked.

A DAE becomes one OBJ of every triangle and one OBJ per material colour; GLB, GLTF, PLY,
ASCII STL and STL over MuJoCo's face limit become one OBJ. Every file written is read
with MuJoCo's own loader (:func:`mujoco_refusal`); an STL or OBJ it refuses as the vendor
wrote it is rewritten from trimesh's reading. Conversions and verdicts are kept in the
mesh cache (:mod:`urdfgenpy_ros.mesh_cache`); many conversions run in parallel.
"""

from __future__ import annotations

from dataclasses import dataclass, field
import json
import os
from pathlib import Path
from typing import Any

from urdfgenpy_ros import mesh_cache
from urdfgenpy_ros.model.errors import MissingDependencyError, ModelError

COPIED = ('.stl', '.obj')
CONVERTED = ('.dae', '.glb', '.gltf', '.ply')
VERSION = '2'  # of the written OBJ: a new version is a new cache key
STL_FACES = 200000  # MuJoCo's stl_decoder reads binary STL of 1 to 200000 triangles
PARALLEL = 4  # this many conversions to do, or more: in worker processes
Rgba = tuple[float, float, float, float]


@dataclass
class Converted:
    """A mesh file as OBJ: every triangle, and by colour (a DAE's materials)."""

    whole: bytes
    parts: list[tuple[bytes, Rgba | None, str]] = field(default_factory=list)
    textured: bool = False  # a part's colour is a texture image, not carried

    def encode(self) -> bytes:
        """Return the bytes kept in the cache."""
        head = {'whole': len(self.whole), 'textured': self.textured,
                'parts': [[len(data), rgba, name] for data, rgba, name in self.parts]}
        return b''.join([json.dumps(head).encode(), b'\n', self.whole,
                         *(data for data, _, _ in self.parts)])

    @classmethod
    def decode(cls, data: bytes) -> Converted:
        """Return the conversion kept as ``data`` by :meth:`encode`."""
        line, _, rest = data.partition(b'\n')
        head = json.loads(line)
        at = head['whole']
        found = cls(rest[:at], textured=head['textured'])
        for length, rgba, name in head['parts']:
            found.parts.append((rest[at:at + length], tuple(rgba) if rgba else None, name))
            at += length
        return found


def needs_conversion(path: Path) -> bool:
    """Return whether MuJoCo cannot read ``path`` as it is (by its kind, not its content)."""
    suffix = path.suffix.lower()
    return suffix in CONVERTED or (suffix == '.stl' and not is_mujoco_stl(path))


def is_mujoco_stl(path: Path) -> bool:
    """Return whether MuJoCo reads the STL file ``path`` (binary, at most 200000 faces)."""
    with open(path, 'rb') as stream:
        head = stream.read(1024)
    if head.lstrip().startswith(b'solid') and b'facet' in head:
        return False  # ASCII
    count = int.from_bytes(head[80:84], 'little') if len(head) >= 84 else 0
    return 1 <= count <= STL_FACES


def converted(path: Path) -> Converted:
    """Return ``path`` as OBJ (DAE: by colour too), converted once and kept by content."""
    name = _key(path)
    return Converted.decode(mesh_cache.cached(name, lambda: _convert(path).encode()))


def convert_many(paths: list[Path]) -> None:
    """Convert the ``paths`` not yet kept, in worker processes when there are many."""
    todo = sorted({path for path in paths if not mesh_cache.is_cached(_key(path))})
    workers = min(len(todo), os.cpu_count() or 1)
    if len(todo) < PARALLEL or workers < 2:
        return  # converted one by one when asked
    import concurrent.futures
    import multiprocessing
    import threading
    method = 'fork' if threading.active_count() == 1 and \
        'fork' in multiprocessing.get_all_start_methods() else 'spawn'
    context = multiprocessing.get_context(method)
    with concurrent.futures.ProcessPoolExecutor(workers, mp_context=context) as pool:
        for path, data in zip(todo, pool.map(_convert_quietly, todo)):
            if data is not None:
                mesh_cache.put(_key(path), data)


def _convert_quietly(path: Path) -> bytes | None:
    """Return the kept bytes of ``path``'s conversion; None when it fails (said later)."""
    try:
        return _convert(path).encode()
    except (ModelError, OSError, MissingDependencyError):
        return None


_keys: dict[tuple[Path, int, int], str] = {}  # (file, size, mtime) -> its key, this process


def _key(path: Path) -> str:
    status = path.stat()
    stamp = (path, status.st_size, status.st_mtime_ns)
    if stamp not in _keys:
        _keys[stamp] = mesh_cache.key(f'obj{VERSION}{path.suffix.lower()}', path.read_bytes())
    return _keys[stamp]


def _convert(path: Path) -> Converted:
    from urdfgenpy_ros.model.mesh_read import dae_parts, load_mesh
    if path.suffix.lower() != '.dae':
        mesh = load_mesh(path)
        return Converted(obj_text(mesh.vertices, mesh.faces))
    import numpy
    parts = dae_parts(path)
    offset, vertices, faces = 0, [], []
    for part in parts:
        vertices.append(part.vertices)
        faces.append(part.faces + offset)
        offset += len(part.vertices)
    whole = obj_text(numpy.concatenate(vertices), numpy.concatenate(faces))
    coloured = [(obj_text(part.vertices, part.faces), part.rgba, part.material)
                for part in parts] if any(part.rgba for part in parts) else []
    return Converted(whole, coloured, any(part.textured for part in parts))


def obj_text(vertices: Any, faces: Any) -> bytes:
    """Return OBJ text of a triangle mesh's used vertices, each coordinate exact (repr)."""
    import numpy
    faces = numpy.asarray(faces, dtype=numpy.int64)
    used = numpy.unique(faces)
    renumber = numpy.zeros(int(used[-1]) + 1 if len(used) else 1, dtype=numpy.int64)
    renumber[used] = numpy.arange(1, len(used) + 1)
    numbers = list(map(repr, numpy.asarray(vertices, dtype=float)[used].ravel().tolist()))
    corners = renumber[faces].ravel().tolist()
    lines = map('v {} {} {}'.format, numbers[0::3], numbers[1::3], numbers[2::3])
    faces_text = map('f {} {} {}'.format, corners[0::3], corners[1::3], corners[2::3])
    return ('\n'.join(lines) + '\n' + '\n'.join(faces_text) + '\n').encode('ascii')


def mujoco_refusal(file_name: str, data: bytes) -> str | None:
    """
    Return why MuJoCo's own loader refuses the mesh file ``data``, or None when it reads it.

    None too without MuJoCo (nothing to check with). The verdict is kept by content.
    """
    try:
        import mujoco
    except ImportError:
        return None
    suffix = Path(file_name).suffix.lower()
    name = mesh_cache.key(f'mujoco{mujoco.__version__}{suffix}', data)
    verdict = mesh_cache.cached(name, lambda: _mujoco_reads(mujoco, suffix, data))
    return verdict.decode() or None


_verdicts: dict[tuple[str, int], str | None] = {}  # (conversion's key, part): this process's


def conversion_refusal(path: Path, part: int, data: bytes) -> str | None:
    """
    Return :func:`mujoco_refusal` of ``data``, part ``part`` (-1: whole) of ``path``'s OBJ.

    Asked once a process per conversion, not hashed again on every write.
    """
    stamp = (_key(path), part)
    if stamp not in _verdicts:
        _verdicts[stamp] = mujoco_refusal('m.obj', data)
    return _verdicts[stamp]


def _mujoco_reads(mujoco: Any, suffix: str, data: bytes) -> bytes:
    text = ('<mujoco><default><mesh inertia="shell"/></default><asset>'
            f'<mesh name="m" file="m{suffix}"/></asset></mujoco>')
    try:
        mujoco.MjModel.from_xml_string(text, {f'm{suffix}': data})
    except ValueError as error:
        return str(error).replace('Error: ', '').split('\n')[0].strip().encode() or b'?'
    return b''


def rewritten(path: Path) -> bytes:
    """Return ``path`` (an STL or OBJ MuJoCo refuses) as trimesh reads it, written as OBJ."""
    def make() -> bytes:
        from urdfgenpy_ros.model.mesh_read import load_mesh
        mesh = load_mesh(path)
        mesh.merge_vertices()
        return obj_text(mesh.vertices, mesh.faces)
    return mesh_cache.cached(mesh_cache.key(f'rewrite{VERSION}{path.suffix.lower()}',
                                            path.read_bytes()), make)


_readable: dict[tuple[Path, int, int], tuple[bytes, str, str]] = {}  # this process's


def readable(path: Path) -> tuple[bytes, str, str]:
    """
    Return the bytes to write for an STL or OBJ, their suffix, and a note ('' for none).

    As the vendor wrote it when MuJoCo reads it; else trimesh's reading, written as OBJ.

    :raises ModelError: when MuJoCo reads neither.
    """
    status = path.stat()
    stamp = (path, status.st_size, status.st_mtime_ns)
    if stamp not in _readable:
        _readable[stamp] = _readable_now(path)
    return _readable[stamp]


def _readable_now(path: Path) -> tuple[bytes, str, str]:
    data = path.read_bytes()
    refusal = mujoco_refusal(path.name, data)
    if refusal is None:
        return data, path.suffix.lower(), ''
    try:
        data = rewritten(path)
    except ModelError as error:
        raise ModelError(f'{path}: MuJoCo cannot read it ({refusal}), nor trimesh ({error})')\
            from None
    again = mujoco_refusal('m.obj', data)
    if again is not None:
        raise ModelError(f"{path}: MuJoCo cannot read it ({refusal}), nor trimesh's "
                         f'rewrite of it ({again})')
    return data, '.obj', (f'{path}: MuJoCo cannot read it as written ({refusal}): written '
                          "as OBJ from trimesh's reading of it")
