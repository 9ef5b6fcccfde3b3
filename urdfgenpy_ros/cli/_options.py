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

"""Options and arguments several commands share: the input file and its Xacro args."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any, cast

import click

from urdfgenpy_ros.formats.open import open_description, parse_args
from urdfgenpy_ros.model.errors import InputError
from urdfgenpy_ros.robot import Robot
from urdfgenpy_ros.validation.suppressions import parse_codes


def parse_mappings(arguments: tuple[str, ...]) -> dict[str, str]:
    """Turn ``name:=value`` arguments into a dict; a bad one is a usage error of ARGS."""
    try:
        return parse_args(arguments)
    except InputError as error:
        plain, equals, given = error.value.partition('=')
        spelt = f' (write {plain}:={given})' if equals and plain else ''
        raise click.BadParameter(f'{error.what}{spelt}', param_hint='ARGS') from None


def _codes(ctx: click.Context, param: click.Parameter, values: tuple[str, ...]
           ) -> frozenset[str]:
    try:
        return frozenset().union(*(parse_codes(value) for value in values))
    except ValueError as error:
        raise click.BadParameter(str(error)) from None


def ignore_option(function: Callable[..., Any]) -> Callable[..., Any]:
    """Add ``--ignore CODES`` (repeatable): finding codes the review silences."""
    return click.option('--ignore', 'ignored', multiple=True, callback=_codes,
                        metavar='CODES',
                        help='Codes to silence, e.g. I205,C401 (repeatable).')(function)


def input_options(function: Callable[..., Any]) -> Callable[..., Any]:
    """Add ``--package-path`` (repeatable) to a command reading a description."""
    return click.option(
        '--package-path', '-p', 'package_paths', multiple=True,
        type=click.Path(exists=True, file_okay=False, path_type=Path),
        help='A folder holding ROS packages, for $(find pkg) and package:// (repeatable).'
    )(function)


def read_robot(path: Path, arguments: tuple[str, ...], package_paths: tuple[Path, ...],
               warn: bool = True) -> Robot:
    """Read ``path`` with its Xacro arguments; print the reader's warnings on stderr."""
    robot = cast(Robot, open_description(path, parse_mappings(arguments), package_paths))
    if warn:
        say_read_warnings(robot)
    return robot


def say_read_warnings(robot: Robot) -> None:
    """Print the reader's warnings about ``robot`` on stderr, one line each."""
    for warning in robot.read_warnings:
        click.echo(str(warning), err=True)
