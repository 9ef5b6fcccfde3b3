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

"""``urdfgenpy example``: print and write a built-in example robot."""

from __future__ import annotations

from pathlib import Path

import click

from urdfgenpy_ros.examples import EXAMPLES


@click.command()
@click.argument('name', type=click.Choice(sorted(EXAMPLES)), default='ptu')
@click.option('--output-dir', '-o', type=click.Path(file_okay=False, path_type=Path),
              default=Path('.'), show_default=True, help='Where to write the files.')
def example(name: str, output_dir: Path) -> None:
    """Print the tree of example robot NAME and write NAME.urdf and NAME.urdf.xacro."""
    robot = EXAMPLES[name]()
    paths = [output_dir / f'{name}{suffix}' for suffix in ('.urdf', '.urdf.xacro')]
    for path in paths:
        robot.save(path)
    robot.print_tree()
    for path in paths:
        click.echo(f'wrote {path}')
