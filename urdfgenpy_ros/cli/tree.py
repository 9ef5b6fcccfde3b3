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

"""``urdfgenpy tree``: print the kinematic tree of a description."""

from __future__ import annotations

from pathlib import Path

import click

from urdfgenpy_ros.cli._options import input_options, read_robot


@click.command()
@click.argument('path', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@input_options
def tree(path: Path, arguments: tuple[str, ...], package_paths: tuple[Path, ...]) -> None:
    """Print the tree of the URDF or Xacro file PATH (Xacro arguments as name:=value)."""
    read_robot(path, arguments, package_paths).print_tree()
