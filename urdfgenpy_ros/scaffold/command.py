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
from pathlib import Path
import sys
from typing import NoReturn

from urdfgenpy_ros.errors import UrdfgenpyError
from urdfgenpy_ros.model_source import INIT_WORDS, load_model
from urdfgenpy_ros.report import exit_status, FrontEnd
from urdfgenpy_ros.scaffold.preflight import preflight
from urdfgenpy_ros.scaffold.render import create_package
from urdfgenpy_ros.scaffold.spec import BUILD_TYPES, PackageSpec


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the options, named as ``ros2 pkg create`` names them."""
    parser.add_argument('package_name', help='the package to create, e.g. my_robot_description')
    parser.add_argument('--build-type', default='ament_cmake', choices=BUILD_TYPES)
    parser.add_argument('--destination-directory', default='.', type=Path,
                        help='where the package folder is created')
    parser.add_argument('--license', default='Apache-2.0')
    parser.add_argument('--maintainer-name', default='maintainer')
    parser.add_argument('--maintainer-email', default='maintainer@example.com')
    parser.add_argument('--description', default='')
    parser.add_argument('--dependencies', nargs='*', default=[],
                        help='more packages to list as exec_depend')
    parser.add_argument('--from', dest='source', default='',
                        help='a .urdf, .xacro, DH table (.yaml/.csv) or module:function; '
                             'default: the built-in example robot')
    parser.add_argument('--xacro-args', nargs='*', default=[], metavar='NAME:=VALUE')
    parser.add_argument('--package-path', '-p', action='append', default=[],
                        help='a folder holding ROS packages (repeatable)')
    parser.add_argument('--force', action='store_true', help='overwrite existing files')
    parser.add_argument('--fix', action='store_true',
                        help="repair the robot's errors that urdfgenpy check --fix can, "
                             'in the package (the source is not touched)')
    parser.add_argument('--allow-errors', action='store_true',
                        help='scaffold a robot that has errors as it is (its colcon test '
                             'will report them)')


def run(args: argparse.Namespace, prog: str = 'urdfgenpy init') -> int:
    """
    Create the package; return the exit code.

    A user's mistake is one line on stderr, ``prog: message (fix)``, after the findings
    behind it, and status 2 (the boundary every front end uses); a bug keeps its traceback.
    """
    return exit_status(FrontEnd(prog), lambda: _create(args))


def _create(args: argparse.Namespace) -> int:
    spec = PackageSpec(args.package_name, args.build_type, args.destination_directory,
                       args.maintainer_name, args.maintainer_email, args.license,
                       args.description, list(args.dependencies))
    for folder in args.package_path:  # as urdfgenpy check refuses it
        if not Path(folder).is_dir():
            raise UrdfgenpyError(f'--package-path {folder}: no such folder (give a folder '
                                 'holding ROS packages)')
    robot, _ = load_model(args.source, args.xacro_args, args.package_path, INIT_WORDS)
    for note in robot.read_warnings:  # e.g. X101: a .urdf file expanded as Xacro
        print(note, file=sys.stderr)
    if args.fix:
        robot = copy.deepcopy(robot)
    for line in preflight(robot, repair=args.fix, allow_errors=args.allow_errors):
        print(line, file=sys.stderr)
    written, warnings = create_package(
        spec, robot, force=args.force, source=args.source or 'the built-in example',
        search_paths=args.package_path)
    for warning in warnings:
        print(f'warning: {warning}', file=sys.stderr)
    print(f'created {spec.root} ({len(written)} files, {spec.build_type}): '
          f'colcon build --packages-select {spec.name}')
    return 0


class _Parser(argparse.ArgumentParser):
    """argparse's parser, whose usage errors are the boundary's one line."""

    def error(self, message: str) -> NoReturn:
        """Raise the usage error, naming where the options are listed."""
        raise UrdfgenpyError(f'{message} (see {self.prog} --help)')


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command with ``argv``; a usage error is one line too."""
    parser = _Parser(prog='urdfgenpy init', description='Create a ROS 2 description package.')
    add_arguments(parser)
    front_end = FrontEnd(parser.prog)
    return exit_status(front_end, lambda: run(parser.parse_args(argv), parser.prog))
