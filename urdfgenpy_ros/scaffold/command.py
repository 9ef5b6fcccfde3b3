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

"""The scaffolding command shared by ``urdfgenpy init`` and ``ros2 pkg scaffold``."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
import copy
import math
from pathlib import Path
import sys
from typing import cast, NoReturn, TYPE_CHECKING

from urdfgenpy_ros.formats.open import open_description, parse_args
from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.report import exit_status, FrontEnd
from urdfgenpy_ros.scaffold import INIT_INPUTS
from urdfgenpy_ros.scaffold.preflight import preflight
from urdfgenpy_ros.scaffold.render import create_package
from urdfgenpy_ros.scaffold.spec import BUILD_TYPES, PackageSpec
from urdfgenpy_ros.validation.fix_output import DEFAULT_RADIUS

if TYPE_CHECKING:
    from urdfgenpy_ros.robot import Robot


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """
    Declare the options, named as ``ros2 pkg create`` names them.

    Each group is a function of its own, so a new kind of package adds its options beside
    them; ``run`` reads the namespace.
    """
    parser.add_argument('package_name', help='the package to create, e.g. my_robot_description')
    parser.add_argument('mappings', nargs='*', default=[], metavar='NAME:=VALUE',
                        help='Xacro arguments of --from, as every urdfgenpy command takes '
                             'them (or after --xacro-args)')
    _package_arguments(parser)
    _source_arguments(parser)
    _repair_arguments(parser)


def _package_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare what the package is: ``ros2 pkg create``'s options."""
    parser.add_argument('--build-type', default='ament_cmake', choices=BUILD_TYPES)
    parser.add_argument('--destination-directory', default='.', type=Path,
                        help='where the package folder is created')
    parser.add_argument('--license', default='Apache-2.0')
    parser.add_argument('--maintainer-name', default='maintainer')
    parser.add_argument('--maintainer-email', default='maintainer@example.com')
    parser.add_argument('--description', default='')
    parser.add_argument('--dependencies', nargs='*', default=[],
                        help='more packages to list as exec_depend')
    parser.add_argument('--force', action='store_true', help='overwrite existing files')


def _source_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the robot to start from and how to read it."""
    parser.add_argument('--from', dest='source', default='',
                        help='a .urdf, .xacro, DH table (.yaml/.csv) or module:function; '
                             'default: the built-in example robot')
    parser.add_argument('--xacro-args', nargs='*', default=[], metavar='NAME:=VALUE')
    parser.add_argument('--package-path', '-p', action='append', default=[],
                        help='a folder holding ROS packages (repeatable)')


def _repair_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare what to do about a robot with errors."""
    parser.add_argument('--fix', action='store_true',
                        help="repair the robot's errors that urdfgenpy check --fix can, "
                             'in the package (the source is not touched)')
    parser.add_argument('--fix-radius', type=_positive, default=DEFAULT_RADIUS, metavar='M',
                        help='with --fix: the radius of the solid sphere whose tensor a link '
                             f'with no shape to take one from gets (default {DEFAULT_RADIUS})')
    parser.add_argument('--allow-errors', action='store_true',
                        help='scaffold a robot that has errors as it is (its colcon test '
                             'will report them)')


def run(args: argparse.Namespace, prog: str = 'urdfgenpy init') -> int:
    """
    Create the package; return the exit code.

    A user's mistake is one line on stderr, ``prog: message (fix)``, after the findings
    behind it, and status 2 (the boundary every front end uses); a bug keeps its traceback.
    """
    return exit_status(FrontEnd(prog, inputs=INIT_INPUTS), lambda: _create(args))


def _create(args: argparse.Namespace) -> int:
    spec = PackageSpec(args.package_name, args.build_type, args.destination_directory,
                       args.maintainer_name, args.maintainer_email, args.license,
                       args.description, list(args.dependencies))
    for folder in args.package_path:  # as urdfgenpy check refuses it
        if not Path(folder).is_dir():
            raise UrdfgenpyError(f'--package-path {folder}: no such folder (give a folder '
                                 'holding ROS packages)')
    given = xacro_arguments(args)
    robot = _robot(args.source, given, args.package_path)
    for note in robot.read_warnings:  # e.g. X101: a .urdf file expanded as Xacro
        print(note, file=sys.stderr)
    if args.fix:
        robot = copy.deepcopy(robot)
    for line in preflight(robot, repair=args.fix, allow_errors=args.allow_errors,
                          radius=args.fix_radius, search_paths=args.package_path):
        print(line, file=sys.stderr)
    written, warnings = create_package(
        spec, robot, force=args.force, source=args.source or 'the built-in example',
        search_paths=args.package_path,
        xacro_args=parse_args(given))
    for warning in warnings:
        print(f'warning: {warning}', file=sys.stderr)
    print(f'created {spec.root} ({len(written)} files, {spec.build_type}): '
          f'colcon build --packages-select {spec.name}')
    return 0


def _robot(source: str, given: list[str], package_paths: list[str]) -> Robot:
    """Return the robot ``--from`` names, or the built-in example without it."""
    if not source:
        from urdfgenpy_ros.examples import pan_tilt_unit
        return pan_tilt_unit()
    return cast('Robot', open_description(source, given, package_paths))


def xacro_arguments(args: argparse.Namespace) -> list[str]:
    """
    Return the Xacro arguments given, as ``NAME:=VALUE`` or after ``--xacro-args``.

    :raises UrdfgenpyError: for a word that is neither, or arguments without ``--from``.
    """
    for word in args.mappings:
        if ':=' not in word:
            raise UrdfgenpyError(f'unexpected argument {word!r}: after the package name come '
                                 'Xacro arguments, NAME:=VALUE (see urdfgenpy init --help)')
    given = [*args.xacro_args, *args.mappings]
    if given and not args.source:
        raise UrdfgenpyError(f'Xacro arguments {" ".join(given)} without --from: name the '
                             'Xacro file they are for (--from robot.urdf.xacro)')
    return given


def _positive(text: str) -> float:
    """Return ``text`` as a positive number of metres (argparse's type)."""
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (value > 0.0 and math.isfinite(value)):
        raise argparse.ArgumentTypeError(f'{text!r} is not a positive length in metres')
    return value


class _Parser(argparse.ArgumentParser):
    """argparse's parser, whose usage errors are the boundary's one line."""

    def error(self, message: str) -> NoReturn:
        """Raise the usage error, naming where the options are listed."""
        raise UrdfgenpyError(f'{message} (see {self.prog} --help)')


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command with ``argv``; a usage error is one line too."""
    from urdfgenpy_ros.scaffold.moveit_package import add_moveit_arguments
    parser = _Parser(prog='urdfgenpy init', description='Create a ROS 2 description package '
                     '(or, with --moveit, a moveit_config package).')
    add_arguments(parser)
    add_moveit_arguments(parser)  # listed here; cli/init.py hands --moveit to its own parser
    front_end = FrontEnd(parser.prog, inputs=INIT_INPUTS)
    # intermixed: NAME:=VALUE may come after the options, as in every other command
    return exit_status(front_end, lambda: run(_description_only(
        parser.parse_intermixed_args(argv)), parser.prog))


def _description_only(args: argparse.Namespace) -> argparse.Namespace:
    """Return ``args``, or a UrdfgenpyError for options of a moveit_config package."""
    from urdfgenpy_ros.scaffold.moveit_package import moveit_only
    given = (['--moveit'] if args.moveit else []) + moveit_only(args)
    if given:
        raise UrdfgenpyError(f'{", ".join(given)}: for a moveit_config package, give '
                             '--moveit (urdfgenpy init NAME --moveit --from SOURCE)')
    return args
