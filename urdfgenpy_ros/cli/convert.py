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

from pathlib import Path
from typing import cast
import warnings

import click

from urdfgenpy_ros.cli._options import input_options, read_robot, say_read_warnings
from urdfgenpy_ros.cli.convert_mjcf import mjcf_options, MjcfOptions, write_mjcf_file
from urdfgenpy_ros.errors import UrdfgenpyError
from urdfgenpy_ros.formats import format_of
from urdfgenpy_ros.formats.sdf_frames import merge_for_sdf
from urdfgenpy_ros.formats.sdf_mass import default_mass_notes, mass_only_notes
from urdfgenpy_ros.formats.sdf_mimic import VERSIONS as SDF_VERSIONS
from urdfgenpy_ros.formats.urdf_downgrade import as_version, VERSIONS
from urdfgenpy_ros.model import RobotModel
from urdfgenpy_ros.report import counted
from urdfgenpy_ros.resources import rebase_meshes
from urdfgenpy_ros.robot import Robot
from urdfgenpy_ros.validation.checklist import review, ReviewOptions
from urdfgenpy_ros.validation.fix_output import DEFAULT_RADIUS, fix_for_output
from urdfgenpy_ros.validation.sdf_refusals import lumped_into


@click.command()
@click.argument('source', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('target', type=click.Path(dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@click.option('--force', '-f', is_flag=True, help='Overwrite TARGET if it exists.')
@click.option('--lump-fixed', is_flag=True,
              help='SDF output: merge links joined by fixed joints into their parents, as '
                   "libsdformat's own URDF conversion does.")
@click.option('--sdf-version', type=click.Choice(SDF_VERSIONS),
              help='SDF output: the SDFormat version (default: 1.11 when a joint mimics '
                   'another, which 1.9 cannot hold, else 1.9).')
@click.option('--urdf-version', type=click.Choice(VERSIONS),
              help='URDF output: write what this URDF version holds (1.0 is what ROS 2 '
                   'Jazzy reads: quaternions become rpy, a capsule a cylinder and two '
                   'spheres; each change is printed).')
@click.option('--merge-fixed', is_flag=True,
              help='Merge links on fixed joints into their parents (exact lumped inertia); '
                   'each stays a massless frame unless --drop-frames.')
@click.option('--drop-frames', is_flag=True, help='With --merge-fixed: remove merged links.')
@click.option('--keep', 'keep', multiple=True, metavar='LINK',
              help='With --merge-fixed: never merge this link (repeatable).')
@click.option('--fix', 'repair', is_flag=True,
              help="Apply check --fix's repairs to the model written (the source is not "
                   'touched); each is printed.')
@click.option('--fix-radius', type=click.FloatRange(min=0.0, min_open=True),
              default=DEFAULT_RADIUS, show_default=True,
              help='With --fix: radius (m) of the solid sphere whose tensor a link with no '
                   'shape to take one from gets.')
@mjcf_options
@input_options
def convert(source: Path, target: Path, arguments: tuple[str, ...],
            package_paths: tuple[Path, ...], force: bool, lump_fixed: bool,
            urdf_version: str | None, mjcf: MjcfOptions, sdf_version: str | None = None,
            merge_fixed: bool = False,
            drop_frames: bool = False, keep: tuple[str, ...] = (), repair: bool = False,
            fix_radius: float = DEFAULT_RADIUS) -> None:
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
    kind = format_of(target)
    if kind != 'mjcf' and mjcf.given():
        raise UrdfgenpyError(f"{target}: {', '.join(mjcf.given())} apply to MJCF output "
                             '(.xml, .mjcf) only: drop them or write .xml')
    for sdf_option, option in ((lump_fixed, '--lump-fixed'),
                               (sdf_version is not None, '--sdf-version')):
        if sdf_option and kind != 'sdf':
            raise UrdfgenpyError(f'{target}: {option} applies to .sdf output only: drop it '
                                 'or write .sdf')
    if urdf_version is not None and kind not in ('urdf', 'xacro'):
        raise UrdfgenpyError(f'{target}: --urdf-version applies to .urdf and .xacro output '
                             'only: drop it or write .urdf')
    for given, option in ((drop_frames, '--drop-frames'), (keep, '--keep')):
        if given and not merge_fixed:
            raise UrdfgenpyError(f'{option} applies with --merge-fixed only: add '
                                 '--merge-fixed or drop it')
    if target.exists() and not force:
        raise UrdfgenpyError(f'{target} exists: pass --force to overwrite it')
    robot = read_robot(source, arguments, package_paths, warn=False)
    if kind in ('sdf', 'mjcf'):  # not one tree: that one line, before any other word
        _refuse_broken_tree(robot, target)
    say_read_warnings(robot)
    if repair:
        for line in fix_for_output(robot, fix_radius, package_paths):
            click.echo(line, err=True)
    if urdf_version is not None:
        robot, changes = cast(tuple[Robot, list], as_version(robot, urdf_version))
        for change in changes:
            click.echo(str(change), err=True)
    if merge_fixed:
        robot = robot.merge_fixed(keep, drop_frames=drop_frames)
    if kind == 'sdf':
        merged = merge_for_sdf(robot, lump_fixed)[0]  # the links the SDF has
        _refuse_invalid_inertia(merged, target)
        for note in (*mass_only_notes(robot), *default_mass_notes(merged)):
            click.echo(note, err=True)  # a mass-only inertial kept as libsdformat keeps it
    if kind == 'mjcf':  # meshes are resolved from the source and copied beside the target
        raise SystemExit(write_mjcf_file(robot, target, mjcf, package_paths, force))
    rebase_meshes(robot, source.parent, target.parent)  # relative meshes still found
    if kind == 'sdf':
        _write_sdf(robot, target, lump_fixed, sdf_version)
        return
    robot.save(target)
    click.echo(f"wrote {target}: {counted(len(robot.links), 'link')}, "
               f"{counted(len(robot.joints), 'joint')}")


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


def _write_sdf(robot: Robot, target: Path, lump_fixed: bool, version: str | None) -> None:
    """Write the SDF; say each thing it does not carry in one line (the writer's warnings)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        robot.save(target, lump_fixed=lump_fixed, version=version)
    for warning in caught:
        line = str(warning.message)
        click.echo(line if ': warning: ' in line else f'warning: {line}', err=True)
    text = target.read_text(encoding='utf-8')  # what the SDF holds, counted
    click.echo(f"wrote {target}: {counted(text.count('<link '), 'link')}, "
               f"{counted(text.count('<joint '), 'joint')}, "
               f"{counted(text.count('<frame '), 'frame')}")


def _refuse_broken_tree(robot: Robot, target: Path) -> None:
    """Refuse, in one located line, a robot that is not one tree (SDF and MJCF need one)."""
    found = review(robot, ReviewOptions(check_meshes=False, suppressions=False,
                                        checks=('topology',)))
    for finding in found.errors:
        raise UrdfgenpyError(f'{finding}: {target} not written')


def _refuse_invalid_inertia(robot: RobotModel, target: Path) -> None:
    """Print one line per link of ``robot`` whose inertia libsdformat refuses; then refuse."""
    found = review(robot, ReviewOptions(check_meshes=False, write_sdf=True, suppressions=False,
                                        checks=('inertia', 'libsdformat')))
    refused = [(finding, lumped_into(robot, finding))
               for finding in found.refused['libsdformat']]
    for finding, parent in refused:
        fix = (f"pass --lump-fixed (it merges the link into {parent!r}, as libsdformat's "
               'conversion does) or --fix (a tensor from its shape)'
               if parent is not None else 'pass --fix (a tensor from its shape)')
        click.echo(f'{finding.location}: error {finding.code} {finding.element}: '
                   f'{finding.message}, which libsdformat refuses: {fix}', err=True)
    if refused:
        lumpable = all(parent is not None for _, parent in refused)
        raise UrdfgenpyError(
            f'{target} not written: libsdformat would refuse the inertia of '
            f'{len(refused)} link(s) (above): '
            + ('pass --lump-fixed' if lumpable else 'pass --fix, or fix them and convert again'))
