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
from pathlib import Path
from typing import cast, NamedTuple

from urdfgenpy_ros.builders import robot_from_function
from urdfgenpy_ros.errors import ParseError, UrdfgenpyError
from urdfgenpy_ros.formats import find_format, load
from urdfgenpy_ros.robot import Robot


class Words(NamedTuple):
    """How a front end names the model, its Xacro arguments and its package folders."""

    model: str = "parameter 'model'"
    xacro_args: str = "parameter 'xacro_args'"
    package_paths: str = "parameter 'package_paths'"


NODE_WORDS = Words()
"""The publisher node's parameters."""
INIT_WORDS = Words('--from', '--xacro-args', '--package-path')
"""``urdfgenpy init``'s (and ``ros2 pkg scaffold``'s) options."""


def parse_xacro_args(arguments: Sequence[str], words: Words = NODE_WORDS) -> dict[str, str]:
    """Turn ``name:=value`` strings into a dict; raise UrdfgenpyError on a bad one."""
    mappings = {}
    for argument in arguments:
        name, separator, value = argument.partition(':=')
        if not separator or not name:
            raise UrdfgenpyError(f'{words.xacro_args}: {argument!r} is not name:=value')
        mappings[name] = value
    return mappings


def load_model(model: str, xacro_args: Sequence[str] = (),
               package_paths: Sequence[str] = (), words: Words = NODE_WORDS
               ) -> tuple[Robot, list[str]]:
    """
    Return the robot ``model`` names and the files to watch for changes.

    ``model`` is a .urdf, a .xacro/.urdf.xacro (with ``xacro_args``), a DH table (.yaml,
    .yml, .csv), an assembly file (``*.assembly.yaml``: every part's files are watched), a
    ``package.module:function`` returning a Robot or URDF text, or '' for the built-in
    example robot. Messages name the options in ``words`` (the node's parameters unless
    told otherwise).

    :raises UrdfgenpyError: with one line that says what is wrong and how to fix it.
    """
    try:
        return _load_model(model, xacro_args, package_paths, words)
    except ParseError as error:  # the reader's hint names the command line's option
        if '--package-path' not in error.message or words.package_paths == '--package-path':
            raise
        message = error.message.replace('--package-path', words.package_paths)
        raise ParseError(message, error.location, error.code) from None


def _load_model(model: str, xacro_args: Sequence[str], package_paths: Sequence[str],
                words: Words) -> tuple[Robot, list[str]]:
    if not model:
        from urdfgenpy_ros.examples import pan_tilt_unit
        return pan_tilt_unit(), []
    path = Path(model).expanduser()
    row = find_format(path)
    if row is not None:  # a format's file (load refuses one no format reads, in one line)
        if row.reader is not None and not path.is_file():
            raise UrdfgenpyError(f'{words.model}: {model} does not exist (give the path '
                                 'of a .urdf, .xacro, DH table or assembly file)')
        robot = cast(Robot, load(path, parse_xacro_args(xacro_args, words), package_paths))
        return robot, robot.included_files or [str(path.resolve())]
    if ':' in model and '/' not in model:
        try:
            return cast(Robot, robot_from_function(model)), []
        except UrdfgenpyError as error:
            raise UrdfgenpyError(f'{words.model}: {error}') from None
    raise UrdfgenpyError(f'{words.model}: {model!r} is neither a .urdf/.xacro file nor '
                         'package.module:function')
