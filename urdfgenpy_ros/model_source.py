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

"""Build the Robot the node publishes from its ``model`` parameter."""

from __future__ import annotations

from collections.abc import Sequence
import importlib
from pathlib import Path

from urdfgenpy_ros.errors import UrdfgenpyError
from urdfgenpy_ros.formats import find_format, load
from urdfgenpy_ros.robot import Robot


def parse_xacro_args(arguments: Sequence[str]) -> dict[str, str]:
    """Turn ``name:=value`` strings into a dict; raise UrdfgenpyError on a bad one."""
    mappings = {}
    for argument in arguments:
        name, separator, value = argument.partition(':=')
        if not separator or not name:
            raise UrdfgenpyError(f"parameter 'xacro_args': {argument!r} is not name:=value")
        mappings[name] = value
    return mappings


def load_model(model: str, xacro_args: Sequence[str] = (),
               package_paths: Sequence[str] = ()) -> tuple[Robot, list[str]]:
    """
    Return the robot ``model`` names and the files to watch for changes.

    ``model`` is a .urdf, a .xacro/.urdf.xacro (with ``xacro_args``), a DH table (.yaml,
    .yml, .csv), an assembly file (``*.assembly.yaml``: every part's files are watched), a
    ``package.module:function`` returning a Robot or URDF text, or '' for the built-in
    example robot.

    :raises UrdfgenpyError: with one line that says what is wrong and how to fix it.
    """
    if not model:
        from urdfgenpy_ros.examples import pan_tilt_unit
        return pan_tilt_unit(), []
    path = Path(model).expanduser()
    row = find_format(path)
    if row is not None:  # a format's file (load refuses one no format reads, in one line)
        if row.reader is not None and not path.is_file():
            raise UrdfgenpyError(f"parameter 'model': {model} does not exist (give the path "
                                 'of a .urdf, .xacro, DH table or assembly file)')
        robot = load(path, parse_xacro_args(xacro_args), package_paths)
        return robot, robot.included_files or [str(path.resolve())]
    if ':' in model and '/' not in model:
        return _from_function(model), []
    raise UrdfgenpyError(f"parameter 'model': {model!r} is neither a .urdf/.xacro file nor "
                         'package.module:function')


def robot_from_function(target: str) -> Robot:
    """
    Return the robot ``package.module:function`` builds (a Robot, or URDF text).

    :raises UrdfgenpyError: when it cannot be imported or returns something else.
    """
    module_name, _, function_name = target.partition(':')
    try:
        function = getattr(importlib.import_module(module_name), function_name)
    except (ImportError, AttributeError, ValueError) as error:
        raise UrdfgenpyError(f'cannot import {target!r}: {error} (write '
                             'package.module:function, importable from here)') from None
    result = function()
    if isinstance(result, Robot):
        return result
    if isinstance(result, (str, bytes)):
        return Robot.from_urdf_string(result, target)
    raise UrdfgenpyError(f'{target}() returned {type(result).__name__}, not a Robot or '
                         'URDF text')


def _from_function(target: str) -> Robot:
    try:
        return robot_from_function(target)
    except UrdfgenpyError as error:
        raise UrdfgenpyError(f"parameter 'model': {error}") from None
