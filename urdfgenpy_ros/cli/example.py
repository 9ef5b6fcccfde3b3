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
from urdfgenpy_ros.formats._xml import write_text, xml_bytes
from urdfgenpy_ros.model.errors import UrdfgenpyError


@click.command()
@click.argument('name', type=click.Choice(sorted(EXAMPLES)), default='ptu')
@click.option('--output-dir', '-o', type=click.Path(file_okay=False, path_type=Path),
              default=Path('.'), show_default=True, help='Where to write the files.')
@click.option('--force', '-f', is_flag=True,
              help='Overwrite the files if they exist with other content.')
def example(name: str, output_dir: Path, force: bool) -> None:
    """Print the tree of example robot NAME and write NAME.urdf and NAME.urdf.xacro."""
    robot = EXAMPLES[name]()
    texts = {output_dir / f'{name}.urdf': robot.to_urdf(),
             output_dir / f'{name}.urdf.xacro': robot.to_xacro()}
    for path, text in texts.items():  # a file as the example writes it is written again
        if not force and path.is_file() and path.read_bytes() != xml_bytes(text):
            raise UrdfgenpyError(f'{path} exists and differs from the example (edited?): '
                                 'pass --force to overwrite it, or --output-dir elsewhere')
    for path, text in texts.items():  # the texts compared above, not written anew
        write_text(path, text)
    paths = list(texts)
    robot.print_tree()
    for path in paths:
        click.echo(f'wrote {path}')
