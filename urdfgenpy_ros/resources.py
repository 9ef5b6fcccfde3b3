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

"""Find ROS packages and the files ``package://`` and ``file://`` URIs name."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
import os
from os import PathLike
from pathlib import Path
import posixpath
from typing import TYPE_CHECKING
from urllib.parse import unquote, urlparse

from urdfgenpy_ros.model.errors import PACKAGE_FOLDER, UrdfgenpyError
from urdfgenpy_ros.package_search import package_name, search

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


class ResourceError(UrdfgenpyError):
    """A package or file a description names cannot be found."""


def _package_name(directory: Path) -> str | None:
    return package_name(directory)


class PackageResolver:
    """
    Find a ROS package's directory by name.

    A package is a folder whose ``package.xml`` names it. Looked up in order: ``packages``
    (name to directory), ``search_paths`` (directories holding packages, up to three levels
    down), the ament index of a sourced ROS 2 install, then ``ROS_PACKAGE_PATH``. A folder
    that only bears the name (a Python module folder of the same name, say) is passed by;
    only when no package of that name exists anywhere is such a folder in the search
    paths used, so that trees copied without their package.xml still resolve.
    """

    def __init__(self, search_paths: Iterable[str | PathLike[str]] = (),
                 packages: Mapping[str, str | PathLike[str]] | None = None) -> None:
        self.packages = {name: Path(path).absolute() for name, path in (packages or {}).items()}
        self.search_paths = [Path(path).absolute() for path in search_paths]
        self._found: dict[str, Path | None] = {}

    def find(self, name: str) -> Path | None:
        """Return the package directory of ``name``, or None."""
        if name not in self._found:
            self._found[name] = self._find(name)
        return self._found[name]

    def _find(self, name: str) -> Path | None:
        if name in self.packages:
            return self.packages[name]
        for root in self.search_paths:
            found = search(root, name, depth=3)
            if found is not None:
                return found
        found = self._installed(name)
        if found is not None:
            return found
        for root in self._ros_package_path():
            found = search(root, name, depth=3)
            if found is not None:
                return found
        for root in (*self.search_paths, *self._ros_package_path()):
            found = search(root, name, depth=3, by_folder_name=True)
            if found is not None:
                return found
        return None

    def _without_package(self, uri: str, relative_to: str | PathLike[str] | None) -> Path:
        """
        Return the file of ``package:///a/b``: ``a/b`` under a folder of packages.

        pinocchio reads it so (under each of its package folders: ``search_paths``, then
        ``ROS_PACKAGE_PATH``), and yourdfpy (under a folder above the description's).

        :raises ResourceError: when no such folder holds it.
        """
        rest = unquote(urlparse(uri).path).lstrip('/')
        above = list(Path(relative_to).absolute().parents) if relative_to is not None else []
        if relative_to is not None:
            above.insert(0, Path(relative_to).absolute())
        for root in (*self.search_paths, *self._ros_package_path(), *above):
            if (root / rest).exists():
                return root / rest
        raise ResourceError(f'{uri!r} names no package (package:/// with an empty name): '
                            f'{rest!r} is under none of the folders of packages (write '
                            f'package://{rest}, or {PACKAGE_FOLDER.text})',
                            fixes=(PACKAGE_FOLDER,))

    @staticmethod
    def _ros_package_path() -> list[Path]:
        return [Path(entry) for entry in os.environ.get('ROS_PACKAGE_PATH', '').split(
            os.pathsep) if entry]

    @staticmethod
    def _installed(name: str) -> Path | None:
        """Return the share folder of ``name`` in the ament index, or None."""
        if not os.environ.get('AMENT_PREFIX_PATH'):
            return None
        try:
            from ament_index_python.packages import (
                get_package_share_directory, PackageNotFoundError)
        except ImportError:
            pass
        else:
            try:
                return Path(get_package_share_directory(name))
            except (PackageNotFoundError, ValueError, LookupError, OSError):
                pass
        return None

    def resolve(self, uri: str, relative_to: str | PathLike[str] | None = None) -> Path:
        """
        Return the file ``uri`` names (``package://``, ``file://`` or a path).

        :raises ResourceError: when the package or the file does not exist.
        """
        parsed = urlparse(uri)
        if parsed.scheme == 'package' and not parsed.netloc:
            path = self._without_package(uri, relative_to)
        elif parsed.scheme == 'package':
            directory = self.find(parsed.netloc)
            if directory is None:
                raise ResourceError(f'package {parsed.netloc!r} of {uri!r} not found (source '
                                    f'its workspace, or {PACKAGE_FOLDER.text})',
                                    fixes=(PACKAGE_FOLDER,))
            # a/../b/x.stl: normalised, as a missing folder 'a' would stop the OS
            path = directory / posixpath.normpath(unquote(parsed.path).lstrip('/') or '.')
        elif parsed.scheme == 'file':
            relative = relative_file_uri(uri)
            if relative is None:
                path = Path(unquote(parsed.path))
            else:  # file://meshes/x.stl: a relative path, against the file's folder
                path = Path(relative_to) / relative if relative_to is not None \
                    else Path(relative)
        elif parsed.scheme in ('', ) or len(parsed.scheme) == 1:  # a path (or C:\\)
            path = Path(uri)
            if not path.is_absolute() and relative_to is not None:
                path = Path(relative_to) / path
        else:
            raise ResourceError(f'{uri!r}: unsupported URI scheme {parsed.scheme!r} (use '
                                'package://, file:// or a path)')
        if not path.exists():
            raise ResourceError(f'{uri!r} resolves to {path}, which does not exist')
        return path


def relative_file_uri(uri: str) -> str | None:
    """
    Return the relative path a ``file:`` URI wrongly holds (``file://meshes/x.stl``), or None.

    Exporters often write a path relative to the description as a file URI; read strictly,
    ``meshes`` would be a host name.
    """
    parsed = urlparse(uri)
    if parsed.scheme != 'file':
        return None
    if parsed.netloc and parsed.netloc != 'localhost':
        return unquote(parsed.netloc + parsed.path)
    if not parsed.netloc and parsed.path and not parsed.path.startswith('/'):
        return unquote(parsed.path)  # file:meshes/x.stl
    return None


def uri_warning(uri: str) -> str | None:
    """Return a one-line warning when ``uri`` resolves only by guessing, else None."""
    parsed = urlparse(uri)
    if parsed.scheme == 'package' and not parsed.netloc:
        rest = unquote(parsed.path).lstrip('/')
        return (f'{uri!r} has an empty package name: pinocchio and yourdfpy read it as '
                f"{rest!r} under a folder of packages, but ROS's resource_retriever (RViz) "
                f'does not find it: write package://{rest}')
    relative = relative_file_uri(uri)
    if relative is None:
        return None
    return (f'{uri!r} is a relative path written as a file URI, read against the folder of '
            f'the file; it is not portable: write {relative!r} or '
            f'package://<package>/{relative}')


def rebase_meshes(robot: RobotModel, source_folder: Path, target_folder: Path) -> None:
    """
    Make the relative mesh paths of ``robot`` right from where it is about to be written.

    They were relative to ``source_folder`` (the file it was read from); they become
    relative to ``target_folder``. ``package://`` URIs and absolute paths stay.
    """
    from urdfgenpy_ros.model.geometry import Mesh
    from urdfgenpy_ros.model.link import Shape
    if source_folder.resolve() == target_folder.resolve():
        return
    for link in robot.links:
        shapes: list[Shape] = [*link.visuals, *link.collisions]
        for shape in shapes:
            mesh = shape.geometry
            if not isinstance(mesh, Mesh):
                continue
            relative = relative_file_uri(mesh.filename)
            if relative is None and ('://' in mesh.filename or Path(mesh.filename).is_absolute()):
                continue
            moved = os.path.relpath(source_folder / (relative or mesh.filename), target_folder)
            shape.geometry = Mesh(Path(moved).as_posix(), mesh.scale, source=mesh.source,
                                  extras=mesh.extras)
