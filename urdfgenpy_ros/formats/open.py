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
The one front door: a robot from what a user names, for every front end.

A file in a format the table reads (Xacro with its ``name:=value`` arguments, DH tables,
assembly files) or a ``package.module:function`` builder. Its refusals are
:class:`~urdfgenpy_ros.model.errors.InputError`: the input at fault is data, which each front
end says in its own words (``--from``, the node's ``model`` parameter).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from os import PathLike
from pathlib import Path
from typing import TYPE_CHECKING

from urdfgenpy_ros.formats.table import find_format, load
from urdfgenpy_ros.model.errors import InputError, UrdfgenpyError

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

Arguments = Sequence[str] | Mapping[str, str]
"""Xacro arguments: ``name:=value`` strings, or a mapping of them."""


def parse_args(arguments: Arguments) -> dict[str, str]:
    """
    Return ``name:=value`` strings as a mapping, as xacro's command line reads them.

    :raises InputError: ``where='args'``, ``value`` the argument, for one that is not.
    """
    if isinstance(arguments, Mapping):
        return dict(arguments)
    mappings = {}
    for argument in arguments:
        name, separator, value = argument.partition(':=')
        if not separator or not name:
            raise InputError('args', f'{argument!r} is not name:=value', value=argument)
        mappings[name] = value
    return mappings


def open_description(source: str | PathLike[str], args: Arguments = (),
                     package_paths: Iterable[str | PathLike[str]] = ()) -> RobotModel:
    """
    Return the robot ``source`` names: a file, or a ``package.module:function``.

    A file is a path object or a name ending in a suffix of the format table (.urdf,
    .xacro/.urdf.xacro with ``args``, a DH table, an assembly file); ``package_paths``
    are folders holding ROS packages, for ``$(find pkg)`` and ``package://``.

    :raises InputError: for a missing file or a ``source`` that is neither.
    :raises UrdfgenpyError: for what the reader or the builder refuses, in one line.
    """
    if isinstance(source, PathLike) or find_format(source) is not None:
        path = Path(source).expanduser()
        row = find_format(path)
        if row is not None and row.reader is not None and not path.is_file():
            raise InputError('source', f'{source} does not exist', 'give the path of a .urdf, '
                             '.xacro, DH table or assembly file', str(source))
        return load(path, parse_args(args), package_paths)  # refuses what no row reads
    if ':' in source and '/' not in source:
        from urdfgenpy_ros.formats.builders import robot_from_function
        try:
            return robot_from_function(source)
        except UrdfgenpyError as error:
            raise InputError('source', str(error), value=source) from None
    raise InputError('source', f'{source!r} is neither a .urdf/.xacro file nor '
                     'package.module:function', value=source)


def files_read(source: str | PathLike[str], robot: RobotModel) -> list[str]:
    """Return the files ``robot``, opened from ``source``, was read from (to watch them)."""
    if not isinstance(source, PathLike) and find_format(source) is None:
        return []  # a function's robot
    return robot.included_files or [str(Path(source).expanduser().resolve())]
