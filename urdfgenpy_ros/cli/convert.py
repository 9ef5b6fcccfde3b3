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

"""
``urdfgenpy convert``: read one format, write another.

An SDF that libsdformat would refuse (a link's inertia it finds invalid) is not written:
each such link gets one line naming the fix, and the exit status is 2.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any, cast

import click

from urdfgenpy_ros.cli._options import input_options, read_robot, say_read_warnings
from urdfgenpy_ros.cli.convert_rows import ConvertRun, refuse_misplaced, row_options
from urdfgenpy_ros.cli.convert_rows import write_plain
from urdfgenpy_ros.cli.words import CLI_WORDS
from urdfgenpy_ros.formats.prepare import tree_review
from urdfgenpy_ros.formats.table import Format, writer_for
from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.model.review import ReviewRecord
from urdfgenpy_ros.robot import Robot
from urdfgenpy_ros.validation.fix_output import DEFAULT_RADIUS, fix_for_output


@click.command()
@click.argument('source', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('target', type=click.Path(dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@click.option('--force', '-f', is_flag=True, help='Overwrite TARGET if it exists.')
@row_options(0, 50)
@click.option('--merge-fixed', is_flag=True,
              help='Merge links on fixed joints into their parents (exact lumped inertia); '
                   'each stays a massless frame unless --drop-frames.')
@click.option('--drop-frames', is_flag=True, help='With --merge-fixed: remove merged links.')
@click.option('--keep', 'keep', multiple=True, metavar='LINK',
              help='With --merge-fixed: never merge this link (repeatable).')
@click.option('--fix', 'repair', is_flag=True,
              help="Apply check --fix's repairs of errors to the model written (the source "
                   'is not touched); each is printed. Warnings it repairs (I205, J102) are '
                   'left: run check --fix on the file written.')
@click.option('--fix-radius', type=click.FloatRange(min=0.0, min_open=True),
              default=DEFAULT_RADIUS, show_default=True,
              help='With --fix: radius (m) of the solid sphere whose tensor a link with no '
                   'shape to take one from gets.')
@row_options(50, 1000)
@input_options
def convert(source: Path, target: Path, arguments: tuple[str, ...],
            package_paths: tuple[Path, ...], force: bool, merge_fixed: bool = False,
            drop_frames: bool = False, keep: tuple[str, ...] = (), repair: bool = False,
            fix_radius: float = DEFAULT_RADIUS, **given: Any) -> None:
    """
    Convert SOURCE to TARGET; the suffixes choose the formats.

    SOURCE is .urdf, .xacro (.urdf.xacro), a DH table (.yaml, .yml, .csv) or an assembly
    (.assembly.yaml); TARGET is .urdf, .xacro or .sdf, or MuJoCo's .xml/.mjcf. An SDF or
    MJCF of a robot that is not one tree, or that the engine would refuse (a link's
    inertia), is not written: exit status 2, one line per link. MJCF: what it cannot
    carry is reported, one line each (--strict: errors, exit status 1, nothing written);
    its meshes go to assets/ beside it. NAME:=VALUE arguments may come before TARGET too
    (TARGET is the one argument without ':=').
    """
    target, arguments = _target_among(target, arguments)
    row = writer_for(target)
    run = ConvertRun(source, target, given, package_paths, force)
    refuse_misplaced(row, run)
    for flag, option in ((drop_frames, '--drop-frames'), (keep, '--keep')):
        if flag and not merge_fixed:
            raise UrdfgenpyError(f'{option} applies with --merge-fixed only: add '
                                 '--merge-fixed or drop it')
    if target.exists() and not force:
        raise UrdfgenpyError(f'{target} exists: pass --force to overwrite it')
    robot = read_robot(source, arguments, package_paths, warn=False)
    if row.one_tree:  # not one tree: that one line, before any other word
        _say(tree_review(robot), lambda why: f'{why}: {target} not written')
    say_read_warnings(robot)
    if repair:
        for line in fix_for_output(robot, fix_radius, package_paths):
            click.echo(CLI_WORDS.worded(line), err=True)
    robot = _transformed(robot, row, run, (keep, drop_frames) if merge_fixed else None)
    if row.prepare is not None:  # what the target refuses: its lines, then the refusal
        _say(row.prepare(robot, run.keywords(row)), lambda why: f'{target} not written: {why}')
    status = _write_step(row)(robot, run)
    if status:
        raise SystemExit(status)


def _target_among(target: Path, arguments: tuple[str, ...]) -> tuple[Path, tuple[str, ...]]:
    """Take TARGET from among the arguments: the one word without ``:=``, wherever it is."""
    if ':=' not in str(target):
        return target, arguments
    words = (str(target), *arguments)
    paths = [word for word in words if ':=' not in word]
    if len(paths) != 1:
        raise click.UsageError('give one TARGET (a path without :=) and Xacro arguments as '
                               'NAME:=VALUE, e.g. convert ur.urdf.xacro out.urdf ur_type:=ur10e')
    return Path(paths[0]), tuple(word for word in words if ':=' in word)


def _transformed(robot: Robot, row: Format, run: ConvertRun,
                 merge: tuple[tuple[str, ...], bool] | None) -> Robot:
    """Return the robot the row's transforms (each change said) and --merge-fixed make."""
    for option, value in run.transforms(row):
        assert option.transform is not None
        robot, changes = cast(tuple[Robot, list], option.transform(robot, value))
        for change in changes:
            click.echo(str(change), err=True)
    if merge is not None:
        robot = robot.merge_fixed(merge[0], drop_frames=merge[1])
    return robot


def _say(found: ReviewRecord, refusal: Callable[[str], str]) -> None:
    """Print the review's lines on stderr; refuse in one line when it refuses."""
    for line in found.lines:
        click.echo(line, err=True)
    if found.refusal is not None:
        raise UrdfgenpyError(refusal(found.refusal))


def _write_step(row: Format) -> Callable[[Robot, ConvertRun], int]:
    """Return ``row``'s write step: its own when it says more, else ``write_plain``."""
    return _WRITE_STEPS.get(row.name, write_plain)


def _write_sdf(robot: Robot, run: ConvertRun) -> int:
    """Write the SDF; say what it does not carry and count its links, joints and frames."""
    from urdfgenpy_ros.cli.convert_write import write_sdf_file
    return write_sdf_file(robot, run)


def _write_mjcf(robot: Robot, run: ConvertRun) -> int:
    """Write the MJCF, its meshes and scene; print its loss report."""
    from urdfgenpy_ros.cli.convert_mjcf import write_mjcf_file
    return write_mjcf_file(robot, run)


_WRITE_STEPS: dict[str, Callable[[Robot, ConvertRun], int]] = {
    'sdf': _write_sdf, 'mjcf': _write_mjcf}
"""The formats whose ``convert`` says more than the links and joints it wrote."""
