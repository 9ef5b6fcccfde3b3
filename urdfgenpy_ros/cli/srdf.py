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

"""``urdfgenpy srdf``: MoveIt's SRDF, its collision matrix computed as MoveIt does."""

from __future__ import annotations

from collections import Counter
import os
from pathlib import Path
import tempfile
from typing import TYPE_CHECKING

import click

from urdfgenpy_ros.cli._options import input_options, read_robot
from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.moveit import VIRTUAL_JOINTS

if TYPE_CHECKING:
    from urdfgenpy_ros.moveit.srdf import Srdf


@click.command()
@click.argument('source', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@click.option('--output', '-o', type=click.Path(dir_okay=False, path_type=Path),
              help='The SRDF file to write (with --update, by default the updated file).')
@click.option('--samples', type=click.IntRange(min=0), default=10000, show_default=True,
              help='Random states of the "Never" step (the Setup Assistant\'s default).')
@click.option('--seed', type=int, default=0, show_default=True,
              help='Seed of the random states: the same seed, the same matrix.')
@click.option('--group', 'groups', multiple=True, metavar='NAME=BASE:TIP',
              help='A chain group to name, or to replace the found one ending at TIP '
                   '(repeatable).')
@click.option('--default-state', default=None, metavar='NAME',
              help='The group state (e.g. home) of the "Default" step, instead of zeros.')
@click.option('--virtual-joint', type=click.Choice([*VIRTUAL_JOINTS, 'none']),
              default='fixed', show_default=True,
              help='How the root is held to the world: fixed for an arm, floating or '
                   'planar for a legged or mobile base.')
@click.option('--update', 'existing', metavar='EXISTING',
              type=click.Path(exists=True, dir_okay=False, path_type=Path),
              help='Recompute the collision matrix of this SRDF and keep the rest as written '
                   '(groups, states, comments, layout, User pairs); without -o, the file is '
                   'updated in place.')
@click.option('--force', '-f', is_flag=True, help='Overwrite OUTPUT if it exists.')
@input_options
def srdf(source: Path, arguments: tuple[str, ...], output: Path | None, samples: int,
         seed: int, groups: tuple[str, ...], default_state: str | None, virtual_joint: str,
         existing: Path | None, force: bool, package_paths: tuple[Path, ...]) -> None:
    """Write the SRDF of SOURCE: groups, states, end effectors and collision matrix."""
    if output is None:
        if existing is None:
            raise click.UsageError("Missing option '--output' / '-o' (or --update EXISTING "
                                   'to update a file in place)')
        output = existing
    same = existing is not None and output.exists() and output.samefile(existing)
    if output.exists() and not force and not same:
        raise UrdfgenpyError(f'{output} exists: pass --force to overwrite it')
    robot = read_robot(source, arguments, package_paths)
    if existing is not None:
        if groups:
            raise click.UsageError('--group makes a new SRDF: with --update, edit the '
                                   "file's groups by hand")
        from urdfgenpy_ros.moveit.srdf_update import update_srdf  # numpy: when asked
        update = update_srdf(robot, existing, samples, seed, default_state, package_paths)
        replace_file(output, update.text.encode('utf-8', 'surrogateescape'))
        for line in update.lines() or ['the collision matrix is unchanged']:
            click.echo(line)
        click.echo(f'wrote {output}')
        return
    from urdfgenpy_ros.moveit.srdf import write_srdf
    result = write_srdf(robot, output, samples=samples, seed=seed, groups=list(groups),
                        default_state=default_state,
                        virtual_joint=None if virtual_joint == 'none' else virtual_joint,
                        search_paths=package_paths, rates=True)
    for line in summary(result):
        click.echo(line)
    click.echo(f'wrote {output}')


def replace_file(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` atomically: a temporary file beside it, then a rename."""
    handle, temporary = tempfile.mkstemp(prefix=f'.{path.name}.', dir=path.parent or '.')
    try:
        with os.fdopen(handle, 'wb') as stream:
            stream.write(data)
        if path.exists():
            os.chmod(temporary, path.stat().st_mode & 0o7777)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def summary(result: Srdf) -> list[str]:
    """Return what the SRDF holds, and each Default pair with its collision rate."""
    from urdfgenpy_ros.moveit.collision_matrix import Reason
    matrix = result.matrix
    counts = Counter(matrix.disabled.values())
    total = len(matrix.links) * (len(matrix.links) - 1) // 2
    lines = [f'{len(result.groups)} groups ({", ".join(group.name for group in result.groups)}'
             f'), {len(result.end_effectors)} end effectors, {len(result.states)} states',
             f'{len(matrix.disabled)} of {total} pairs of {len(matrix.links)} links disabled ('
             + ', '.join(f'{counts[reason]} {reason.value}' for reason in Reason)
             + f'), {matrix.samples} samples, seed {matrix.seed}', *result.notes]
    for (one, two), rate in matrix.rates.items():
        lines.append(f'  Default {one} {two}: in contact in {rate:.2%} of the samples')
    return lines
