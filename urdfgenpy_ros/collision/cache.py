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
Results cached by content: the mesh file's bytes, its scale, the method and its options.

A second run over the same meshes reads each result back instead of computing it. The
cache is the ``collision`` folder of the package's mesh cache (``$URDFGENPY_CACHE_DIR``,
``off`` for none, else ``$XDG_CACHE_HOME/urdfgenpy``); each entry is one ``.npz`` file of
plain arrays (read without pickle). A cache that cannot be written is passed by: it only
saves time.
"""

from __future__ import annotations

import hashlib
import json
import os
from pathlib import Path
from typing import Any

from urdfgenpy_ros.collision.measure import Measures
from urdfgenpy_ros.collision.parts import Part

VERSION = 3  # bump when a method's result changes for the same input


def folder() -> Path | None:
    """Return where the cache is (made when something is stored); None when it is off."""
    from urdfgenpy_ros.mesh_cache import folder as cache_folder
    root = cache_folder()
    return None if root is None else root / 'collision'


def key(data: bytes, scale: tuple[float, ...], method: str, options: tuple,
        extra: tuple = ()) -> str:
    """Return the cache key of one mesh's result by one method."""
    digest = hashlib.sha256(data)
    digest.update(json.dumps([VERSION, list(scale), method, list(options), list(extra)]
                             ).encode())
    return digest.hexdigest()


def load(name: str) -> tuple[list[Part], Measures, list[str]] | None:
    """Return the parts, measures and repairs stored under ``name``, or None."""
    import numpy
    root = folder()
    if root is None:
        return None
    path = root / f'{name}.npz'
    try:
        with numpy.load(path, allow_pickle=False) as stored:
            header = json.loads(str(stored['header']))
            parts = [Part(kind, stored.get(f'v{index}'), stored.get(f'f{index}'),
                          tuple(size), None if pose is None else
                          tuple(tuple(row) for row in pose))
                     for index, (kind, size, pose) in enumerate(header['parts'])]
            return parts, Measures(**header['measures']), header['repairs']
    except (OSError, ValueError, KeyError, TypeError):
        return None


def store(name: str, parts: list[Part], measures: Measures, repairs: list[str]) -> None:
    """Store a result under ``name`` (silently not, when the folder cannot be written)."""
    import numpy
    header = {'parts': [(part.kind, part.size, part.pose) for part in parts],
              'measures': measures.as_dict(), 'repairs': repairs}
    arrays: dict[str, Any] = {'header': numpy.array(json.dumps(header))}
    for index, part in enumerate(parts):
        if part.kind == 'mesh':
            arrays[f'v{index}'] = numpy.asarray(part.vertices, float)
            arrays[f'f{index}'] = numpy.asarray(part.faces, numpy.int64)
    root = folder()
    if root is None:
        return
    target = root / f'{name}.npz'
    partial = target.with_suffix(f'.{os.getpid()}.tmp.npz')
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        numpy.savez(partial, **arrays)
        os.replace(partial, target)
    except OSError:
        partial.unlink(missing_ok=True)
