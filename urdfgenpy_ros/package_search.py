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
Search folders for a ROS package, each folder listed once per process while it is unchanged.

A search of site-packages three levels down visits thousands of folders, and every
:class:`~urdfgenpy_ros.resources.PackageResolver` searched them again. Each folder's
listing (its sub-folders, whether it holds a ``package.xml``, the name that file gives) is
kept with the folder's modification time, and that of its ``package.xml``: a folder
whose entries or manifest changed since is listed again, so the answers are those of a
fresh search.
"""

from __future__ import annotations

import os
from pathlib import Path
import stat
import time

from lxml import etree

_Listing = tuple[int, tuple[str, ...], bool]
_LISTINGS: dict[str, _Listing] = {}
_MANIFESTS: dict[str, tuple[int, int, str | None]] = {}
_RACY = 2_000_000_000  # ns: a file changed this recently is read again (coarse clocks)


def _listing(folder: str) -> _Listing | None:
    """Return (modified, sub-folder names sorted, holds package.xml), or None if no folder."""
    try:
        status = os.stat(folder)
    except OSError:
        return None
    if not stat.S_ISDIR(status.st_mode):
        return None
    cached = _LISTINGS.get(folder)
    if cached is not None and cached[0] == status.st_mtime_ns:
        return cached
    try:
        with os.scandir(folder) as entries:
            found = [(entry.name, _is_dir(entry)) for entry in entries]
    except OSError:  # not readable: no sub-folders, as iterdir() failing gave
        found = []
    listing = (status.st_mtime_ns,
               tuple(sorted(name for name, sub in found if sub and not name.startswith('.'))),
               os.path.isfile(os.path.join(folder, 'package.xml')))
    if _settled(status):
        _LISTINGS[folder] = listing
    return listing


def _settled(status: os.stat_result) -> bool:
    """Return whether a change now would show in the modification time (not the same tick)."""
    return status.st_mtime_ns < time.time_ns() - _RACY


def _is_dir(entry: os.DirEntry[str]) -> bool:
    try:
        return entry.is_dir()
    except OSError:
        return False


def package_name(directory: str | Path) -> str | None:
    """Return the name the ``package.xml`` of ``directory`` gives, or None."""
    manifest = os.path.join(directory, 'package.xml')
    try:
        status = os.stat(manifest)
    except OSError:
        return None
    if not stat.S_ISREG(status.st_mode):
        return None
    stamp = status.st_mtime_ns, status.st_size
    cached = _MANIFESTS.get(manifest)
    if cached is not None and cached[:2] == stamp:
        return cached[2]
    try:
        name = etree.parse(manifest).findtext('name')
    except (OSError, etree.XMLSyntaxError):
        name = None
    found = name.strip() if name else None
    if _settled(status):
        _MANIFESTS[manifest] = (*stamp, found)
    return found


def search(root: Path, name: str, depth: int, by_folder_name: bool = False) -> Path | None:
    """
    Find the package ``name`` under ``root`` (or, ``by_folder_name``, a folder so named).

    Up to ``depth`` levels down; packages do not nest. A folder bearing the name is tried
    before the others at each level, then the sub-folders in sorted order.
    """
    found = _search(str(root), name, depth, by_folder_name)
    return root if found == str(root) else (Path(found) if found is not None else None)


def _search(root: str, name: str, depth: int, by_folder_name: bool) -> str | None:
    listing = _listing(root)
    if listing is None:
        return None
    own = package_name(root) if listing[2] else None
    if own == name or (by_folder_name and os.path.basename(root) == name):
        return root
    if depth == 0 or own is not None:
        return None
    children = listing[1]
    if name in children:  # the likely place first: a folder bearing the name
        child = os.path.join(root, name)
        if by_folder_name or package_name(child) == name:
            return child
    for child_name in children:
        found = _search(os.path.join(root, child_name), name, depth - 1, by_folder_name)
        if found is not None:
            return found
    return None
