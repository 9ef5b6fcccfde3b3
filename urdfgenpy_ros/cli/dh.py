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

"""``urdfgenpy dh``: the DH table of a robot's serial chain."""

from __future__ import annotations

from pathlib import Path
import warnings

import click

from urdfgenpy_ros.cli._options import input_options, read_robot
from urdfgenpy_ros.dh import DHTable
from urdfgenpy_ros.model.errors import UrdfgenpyError


@click.command()
@click.argument('source', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@click.option('--base', required=True, help='The link the chain starts from (DH frame 0).')
@click.option('--tip', required=True, help='The link it ends at (the flange).')
@click.option('--convention', type=click.Choice(['standard', 'modified']), default='standard',
              show_default=True, help='Denavit-Hartenberg (standard) or Craig (modified).')
@click.option('--output', '-o', required=True, type=click.Path(dir_okay=False, path_type=Path),
              help='The table: .yaml, .yml or .csv (CSV holds no base or tool transform).')
@click.option('--degrees', is_flag=True, help='Write angles in degrees.')
@click.option('--force', '-f', is_flag=True, help='Overwrite OUTPUT if it exists.')
@input_options
def dh(source: Path, arguments: tuple[str, ...], base: str, tip: str, convention: str,
       output: Path, degrees: bool, force: bool, package_paths: tuple[Path, ...]) -> None:
    """Write the DH table of SOURCE's chain from --base to --tip (FK equal to the URDF's)."""
    if output.suffix.lower() not in ('.yaml', '.yml', '.csv'):
        raise UrdfgenpyError(f'{output}: a DH table is .yaml, .yml or .csv')
    if output.exists() and not force:
        raise UrdfgenpyError(f'{output} exists: pass --force to overwrite it')
    robot = read_robot(source, arguments, package_paths)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        table = DHTable.from_robot(robot, base, tip, convention)
    for warning in caught:  # ours, as one line each
        if str(warning.message).startswith('dh:'):
            click.echo(f'warning: {warning.message}', err=True)
    table.save(output, degrees)  # refuses a .csv for a table with base or tool transforms
    click.echo(f'wrote {output}: {len(table.rows)} rows ({convention}) from {base!r} to '
               f'{tip!r}')
