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


"""``urdfgenpy attach``: join one description to another at a link, names prefixed."""

from __future__ import annotations

import math
from pathlib import Path
import re

import click

from urdfgenpy_ros.cli._options import input_options, read_robot
from urdfgenpy_ros.formats import format_of
from urdfgenpy_ros.model.errors import ModelError, UrdfgenpyError
from urdfgenpy_ros.model.geometry import Origin
from urdfgenpy_ros.report import counted
from urdfgenpy_ros.resources import rebase_meshes


def _vector(option: str, text: str, degrees: bool = False) -> tuple[float, float, float]:
    parts = text.replace(',', ' ').split()
    try:
        values = [float(part) for part in parts]
    except ValueError:
        values = []
    if len(values) != 3:
        raise click.BadParameter(f'{text!r} is not 3 numbers (e.g. "0.1 0 0.25")',
                                 param_hint=option)
    if degrees:
        values = [math.radians(value) for value in values]
    elif option == '--rpy' and any(abs(value) > 2 * math.pi for value in values):
        click.echo(f'urdfgenpy: warning: --rpy {text!r} is in radians; pass --degrees if you '
                   'meant degrees', err=True)
    if not all(math.isfinite(value) for value in values):
        raise click.BadParameter(f'{text!r} has a number that is not finite',
                                 param_hint=option)
    return values[0], values[1], values[2]


@click.command()
@click.argument('base', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('part', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.option('--at', 'at', required=True, help="The base's link the part is fixed to.")
@click.option('--prefix', default='', help='Put before every name of the part (e.g. arm_).')
@click.option('--xyz', default='0 0 0', show_default=True,
              help='Position of the part on the link, metres ("x y z").')
@click.option('--rpy', default='0 0 0', show_default=True,
              help='Orientation of the part, radians ("roll pitch yaw").')
@click.option('--degrees', is_flag=True, help='--rpy is in degrees.')
@click.option('--joint-name', default=None,
              help='Name of the fixed joint (default: <at>_to_<prefix><part root>).')
@click.option('--base-arg', 'base_args', multiple=True, metavar='NAME:=VALUE',
              help='A Xacro argument of BASE (repeatable).')
@click.option('--part-arg', 'part_args', multiple=True, metavar='NAME:=VALUE',
              help='A Xacro argument of PART (repeatable).')
@click.option('--output', '-o', required=True, type=click.Path(dir_okay=False, path_type=Path),
              help='The assembly: .urdf, .urdf.xacro or .sdf.')
@click.option('--force', '-f', is_flag=True, help='Overwrite OUTPUT if it exists.')
@input_options
def attach(base: Path, part: Path, at: str, prefix: str, xyz: str, rpy: str, degrees: bool,
           joint_name: str | None, base_args: tuple[str, ...], part_args: tuple[str, ...],
           output: Path, force: bool, package_paths: tuple[Path, ...]) -> None:
    """Fix PART (URDF, Xacro, DH table, assembly) to the link --at of BASE; write OUTPUT."""
    format_of(output)
    if output.exists() and not force:
        raise UrdfgenpyError(f'{output} exists: pass --force to overwrite it')
    origin = Origin(_vector('--xyz', xyz), _vector('--rpy', rpy, degrees))
    robot = read_robot(base, base_args, package_paths)
    piece = read_robot(part, part_args, package_paths)
    rebase_meshes(robot, base.parent, output.parent)  # relative meshes still found
    rebase_meshes(piece, part.parent, output.parent)
    try:
        robot.attach(piece, at, origin, prefix=prefix, joint_name=joint_name)
    except ModelError as error:  # its fix in the words of this command's options
        text = re.sub(r"prefix='([^']*)'", r'--prefix \1', str(error))
        raise ModelError(text.replace('pass joint_name= for', 'pass --joint-name for')
                         .replace('another joint_name', 'another --joint-name')) from None
    robot.save(output)
    joint = robot.parent_joint(prefix + piece.root.name)
    click.echo(f'wrote {output}: {counted(len(robot.links), "link")}, '
               f'{counted(len(robot.joints), "joint")} '
               f'({piece.name!r} on {at!r} by joint {joint.name if joint else "?"!r})')
