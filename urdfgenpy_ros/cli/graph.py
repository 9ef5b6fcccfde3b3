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


"""``urdfgenpy graph``: draw the kinematic tree with Graphviz."""

from __future__ import annotations

from pathlib import Path

import click

from urdfgenpy_ros.cli._options import input_options, read_robot


@click.command()
@click.argument('path', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@click.option('--output', '-o', required=True, type=click.Path(dir_okay=False, path_type=Path),
              help='The diagram to write: .svg, .png, .pdf (or .dot for the source).')
@input_options
def graph(path: Path, arguments: tuple[str, ...], output: Path,
          package_paths: tuple[Path, ...]) -> None:
    """Draw the tree of PATH: links as boxes, joints as labelled edges, fixed ones dimmed."""
    from urdfgenpy_ros.viewer.graph import save_graph
    robot = read_robot(path, arguments, package_paths)
    click.echo(save_graph(robot, output))
