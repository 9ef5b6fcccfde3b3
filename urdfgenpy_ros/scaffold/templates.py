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
Find the package templates of the urdfgenpy_ros that is running.

The running installation comes first, so that a sourced ROS 2 workspace (whose ament index
may hold another urdfgenpy_ros, or none) cannot hide them: the source tree of a
development checkout, then the data files installed beside this very package (``share/``
of its prefix: a venv, ``~/.local``, a colcon install folder), then those the
distribution's record lists, then the interpreter's prefix; the ament index last.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
import sys
import sysconfig

from urdfgenpy_ros.model.errors import UrdfgenpyError

PACKAGE = 'urdfgenpy_ros'
_SHARED = Path('share') / PACKAGE / 'templates'


def _usable(folder: Path) -> bool:
    return (folder / 'common').is_dir()


def _source_tree(package: Path) -> Iterator[Path]:
    checkout = package.parent
    manifest = checkout / 'package.xml'
    if manifest.is_file() and f'<name>{PACKAGE}</name>' in manifest.read_text('utf-8',
                                                                              'replace'):
        yield checkout / 'templates'


def _beside(package: Path) -> Iterator[Path]:
    """Yield ``<prefix>/share/urdfgenpy_ros/templates`` for each prefix the package is in."""
    for prefix in list(package.parents)[:5]:
        yield prefix / _SHARED


def _recorded() -> Iterator[Path]:
    """Yield the templates folder the installed distribution's file list names."""
    from importlib import metadata
    try:
        files = metadata.distribution(PACKAGE).files or []
    except metadata.PackageNotFoundError:
        return
    marker = f'/{_SHARED.as_posix()}/'
    for file in files:
        located = Path(str(file.locate())).resolve().as_posix()
        if marker in located:
            yield Path(located[:located.index(marker) + len(marker) - 1])
            return


def _prefixes() -> Iterator[Path]:
    for prefix in (sys.prefix, sysconfig.get_path('data')):
        yield Path(prefix) / _SHARED


def _ament_index() -> Iterator[Path]:
    try:
        from ament_index_python.packages import get_package_share_directory
        yield Path(get_package_share_directory(PACKAGE)) / 'templates'
    except (ImportError, LookupError, OSError, ValueError):
        return


def candidates() -> Iterator[Path]:
    """Yield the places templates may be, in the order they are tried."""
    package = Path(__file__).resolve().parents[1]
    yield from _source_tree(package)
    yield from _beside(package)
    yield from _recorded()
    yield from _prefixes()
    yield from _ament_index()


def template_root() -> Path:
    """
    Return the templates folder of the running urdfgenpy_ros.

    :raises UrdfgenpyError: when no installation place holds them.
    """
    for folder in candidates():
        if _usable(folder):
            return folder
    raise UrdfgenpyError('the package templates are missing: reinstall urdfgenpy_ros '
                         '(pip install --force-reinstall urdfgenpy_ros), or pass templates=')
