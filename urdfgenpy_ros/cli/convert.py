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

"""``urdfgenpy convert``: read one format, write another."""

from __future__ import annotations

from pathlib import Path

import click

from urdfgenpy_ros.cli._options import input_options, read_robot
from urdfgenpy_ros.errors import UrdfgenpyError
from urdfgenpy_ros.formats import format_of
from urdfgenpy_ros.resources import rebase_meshes


@click.command()
@click.argument('source', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('target', type=click.Path(dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@click.option('--force', '-f', is_flag=True, help='Overwrite TARGET if it exists.')
@input_options
def convert(source: Path, target: Path, arguments: tuple[str, ...],
            package_paths: tuple[Path, ...], force: bool) -> None:
    """Convert SOURCE to TARGET; the suffixes choose the formats (.urdf, .xacro)."""
    format_of(target)
    if target.exists() and not force:
        raise UrdfgenpyError(f'{target} exists: pass --force to overwrite it')
    robot = read_robot(source, arguments, package_paths)
    rebase_meshes(robot, source.parent, target.parent)  # relative meshes still found
    robot.save(target)
    click.echo(f'wrote {target}: {len(robot.links)} links, {len(robot.joints)} joints')
