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
Converted meshes kept by content, so a mesh is converted once across runs and processes.

An entry's key is a hash of what made it (the source file's bytes, the kind of conversion
and its version): a changed file is a new key, never a stale answer. Entries live in
``$URDFGENPY_CACHE_DIR`` when set (``off`` turns the cache off), else
``$XDG_CACHE_HOME/urdfgenpy`` (``~/.cache/urdfgenpy``). A folder that cannot be written
only costs time: the conversion is done again, in memory for the rest of the process.
"""

from __future__ import annotations

from collections.abc import Callable
import hashlib
import os
from pathlib import Path
import tempfile

CACHE_ENV = 'URDFGENPY_CACHE_DIR'
_memory: dict[str, bytes] = {}  # this process's entries, whatever the folder allows


def folder() -> Path | None:
    """Return the cache folder, or None when the cache is off."""
    chosen = os.environ.get(CACHE_ENV)
    if chosen is not None:
        return None if chosen.strip().lower() in ('', 'off', '0', 'none') else Path(chosen)
    base = os.environ.get('XDG_CACHE_HOME') or str(Path.home() / '.cache')
    return Path(base) / 'urdfgenpy'


def key(kind: str, *contents: bytes) -> str:
    """Return the key of an entry made by ``kind`` from ``contents``."""
    digest = hashlib.sha256(kind.encode())
    for content in contents:
        digest.update(len(content).to_bytes(8, 'little'))
        digest.update(content)
    return f'{kind}-{digest.hexdigest()}'


def get(name: str) -> bytes | None:
    """Return the entry ``name`` (a :func:`key`), or None when there is none."""
    if name in _memory:
        return _memory[name]
    where = folder()
    if where is None:
        return None
    try:
        data = (where / name[:2 + name.index('-')] / name).read_bytes()
    except (OSError, ValueError):
        return None
    _memory[name] = data
    return data


def put(name: str, data: bytes) -> None:
    """Keep ``data`` as the entry ``name``: written whole (renamed into place) or not at all."""
    _memory[name] = data
    where = folder()
    if where is None:
        return
    target = where / name[:2 + name.index('-')] / name
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(dir=target.parent, prefix='.part-')
        with os.fdopen(handle, 'wb') as stream:
            stream.write(data)
        os.replace(temporary, target)
    except OSError:  # a read-only or full cache: the next run converts again
        try:
            os.unlink(temporary)
        except (OSError, UnboundLocalError):
            pass


def cached(name: str, make: Callable[[], bytes]) -> bytes:
    """Return the entry ``name``, made by ``make()`` and kept when there is none."""
    data = get(name)
    if data is None:
        data = make()
        put(name, data)
    return data


def is_cached(name: str) -> bool:
    """Return whether the entry ``name`` is there (in this process or in the folder)."""
    return get(name) is not None
