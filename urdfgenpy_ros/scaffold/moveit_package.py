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
``urdfgenpy init NAME --moveit --from SOURCE``: a moveit_config package for Jazzy.

What MoveIt's Setup Assistant writes: ``config/<robot>.srdf`` (:mod:`urdfgenpy_ros.moveit`),
the YAML files of :mod:`urdfgenpy_ros.moveit.config`, ``config/<robot>.urdf.xacro``
(the description package's file, with mock hardware for ros2_control when the robot has
no ``<ros2_control>``), the launch files of ``moveit_configs_utils`` (demo, move_group,
rsp, moveit_rviz, spawn_controllers, static_virtual_joint_tfs, warehouse_db,
setup_assistant), ``.setup_assistant`` so that the Setup Assistant can open it,
``package.xml`` and ``CMakeLists.txt``. SOURCE must lie in a ROS package (the description
package, made first by ``urdfgenpy init NAME --from ROBOT``): the config names it.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
import datetime
from pathlib import Path
import sys
from typing import Any, NoReturn

from lxml import etree
from urdfgenpy_ros.formats.open import open_description
from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.moveit import config
from urdfgenpy_ros.moveit.srdf import build_srdf
from urdfgenpy_ros.report import exit_status, FrontEnd
from urdfgenpy_ros.scaffold import INIT_INPUTS
from urdfgenpy_ros.scaffold.templates import template_root
import yaml

LAUNCHES = {  # file: moveit_configs_utils.launches function, what it starts
    'demo': ('generate_demo_launch', 'MoveIt, RViz and mock controllers: try planning.'),
    'move_group': ('generate_move_group_launch', 'The move_group node.'),
    'rsp': ('generate_rsp_launch', 'robot_state_publisher with the robot description.'),
    'moveit_rviz': ('generate_moveit_rviz_launch', 'RViz with the MotionPlanning panel.'),
    'spawn_controllers': ('generate_spawn_controllers_launch', 'The ros2_controllers.'),
    'static_virtual_joint_tfs': ('generate_static_virtual_joint_tfs_launch',
                                 'The virtual joint as a static transform.'),
    'warehouse_db': ('generate_warehouse_db_launch', 'The warehouse database.'),
    'setup_assistant': ('generate_setup_assistant_launch', 'The Setup Assistant on it.'),
}
EXEC_DEPENDS = (
    'controller_manager', 'gripper_controllers', 'joint_state_broadcaster',
    'joint_state_publisher', 'joint_state_publisher_gui', 'joint_trajectory_controller',
    'mock_components', 'moveit_configs_utils', 'moveit_kinematics', 'moveit_planners',
    'moveit_ros_move_group', 'moveit_ros_visualization', 'moveit_ros_warehouse',
    'moveit_setup_assistant', 'moveit_simple_controller_manager', 'robot_state_publisher',
    'rviz2', 'rviz_common', 'rviz_default_plugins', 'tf2_ros', 'warehouse_ros_mongo',
    'xacro')


def description_package(source: Path) -> tuple[str, str, Path]:
    """Return the ROS package holding ``source``, the file's path in it, and its folder."""
    for folder in source.resolve().parents:
        manifest = folder / 'package.xml'
        if manifest.is_file():
            name = etree.parse(str(manifest)).findtext('name')
            if name:
                return (name.strip(), source.resolve().relative_to(folder).as_posix(),
                        folder)
    raise UrdfgenpyError(f'{source} is in no ROS package (no package.xml above it): make '
                         'the description package first, urdfgenpy init NAME_description '
                         '--from ROBOT, then give --from its urdf/ file')


def render_package(args: argparse.Namespace) -> dict[str, str]:
    """Return the package's files (path inside the package: text)."""
    source = Path(args.source)
    package, urdf_path, folder = description_package(source)
    search = [*args.package_path, str(folder.parent)]  # its own package, found beside it
    robot = open_description(str(source), args.xacro_args, search)
    srdf = build_srdf(robot, samples=SAMPLES if args.samples is None else args.samples,
                      seed=args.seed or 0, groups=list(args.groups), search_paths=search)
    for note in srdf.notes:
        print(note)
    groups = [group.name for group in srdf.groups if group.base is not None]
    values: dict[str, Any] = {
        'name': args.package_name, 'robot': robot.name, 'description_package': package,
        'urdf_path': urdf_path, 'maintainer_name': args.maintainer_name,
        'maintainer_email': args.maintainer_email, 'license': args.license,
        'exec_depends': sorted({package, *EXEC_DEPENDS}),
        'timestamp': int(datetime.datetime.now().timestamp()),
        'year': datetime.date.today().year,
        'mock': not any(b.tag == 'ros2_control' for b in _blocks(robot)),
        'initial': config.initial_positions(robot)['initial_positions'],
        'planning_group': (groups or [g.name for g in srdf.groups] or [''])[0],
        'fixed_frame': robot.root.name}
    files = {f'config/{robot.name}.srdf': srdf.text}
    for name, document in (('kinematics', config.kinematics(srdf)),
                           ('joint_limits', config.joint_limits(robot)),
                           ('initial_positions', config.initial_positions(robot)),
                           ('ros2_controllers', config.ros2_controllers(robot, srdf)),
                           ('moveit_controllers', config.moveit_controllers(robot, srdf)),
                           ('pilz_cartesian_limits', config.pilz_cartesian_limits())):
        files[f'config/{name}.yaml'] = yaml.safe_dump(document, sort_keys=False)
    return {**files, **_templated(values)}


def _blocks(robot: Any) -> list[Any]:
    from urdfgenpy_ros.formats.mjcf.actuators import blocks
    return blocks(robot, 'ros2_control')


def _templated(values: dict[str, Any]) -> dict[str, str]:
    from jinja2 import Environment, FileSystemLoader, StrictUndefined
    root = template_root() / 'moveit_config'
    environment = Environment(loader=FileSystemLoader(str(root)), undefined=StrictUndefined,
                              keep_trailing_newline=True, autoescape=False)
    robot = values['robot']
    files = {'package.xml': 'package.xml.jinja', 'CMakeLists.txt': 'CMakeLists.txt.jinja',
             '.setup_assistant': '.setup_assistant.jinja',
             f'config/{robot}.urdf.xacro': 'config/robot.urdf.xacro.jinja',
             'config/moveit.rviz': 'config/moveit.rviz.jinja'}
    if values['mock']:
        files[f'config/{robot}.ros2_control.xacro'] = 'config/robot.ros2_control.xacro.jinja'
    written = {path: environment.get_template(name).render(values)
               for path, name in files.items()}
    for launch, (function, summary) in LAUNCHES.items():
        written[f'launch/{launch}.launch.py'] = environment.get_template(
            'launch/launch.py.jinja').render(values, function=function, summary=summary)
    return written


def _create(args: argparse.Namespace) -> int:
    if not args.source:
        raise UrdfgenpyError('--moveit needs --from SOURCE: the robot of a description '
                             'package (e.g. my_robot_description/urdf/my_robot.urdf.xacro)')
    root = Path(args.destination_directory) / args.package_name
    files = render_package(args)  # all in memory first: nothing half-written
    existing = [path for path in files if (root / path).exists()]
    if existing and not args.force:
        raise UrdfgenpyError(f'{root / existing[0]} exists: pass --force to overwrite '
                             f'({len(existing)} file(s) of the package exist)')
    for path, text in files.items():
        (root / path).parent.mkdir(parents=True, exist_ok=True)
        (root / path).write_text(text, encoding='utf-8')
    print(f'created {root} ({len(files)} files, moveit_config): colcon build '
          f'--packages-select {args.package_name}')
    return 0


SAMPLES = 10000  # the Setup Assistant's, as urdfgenpy srdf


def add_moveit_arguments(parser: argparse.ArgumentParser) -> None:
    """Add the options only a moveit_config package has (init --help lists them too)."""
    group = parser.add_argument_group('a moveit_config package instead',
                                      'urdfgenpy init NAME --moveit --from SOURCE (see '
                                      'urdfgenpy init --moveit --help)')
    group.add_argument('--moveit', action='store_true',
                       help="create a moveit_config package for ROS 2 Jazzy: MoveIt's SRDF, "
                            'config/*.yaml and launch files, as the Setup Assistant writes '
                            'them, for the robot of a description package')
    group.add_argument('--samples', type=int, default=None,
                       help='with --moveit: random states of the collision matrix (default '
                            f'{SAMPLES}, as urdfgenpy srdf)')
    group.add_argument('--seed', type=int, default=None,
                       help='with --moveit: seed of the random states (default 0)')
    group.add_argument('--group', dest='groups', action='append', default=[],
                       metavar='NAME=BASE:TIP',
                       help='with --moveit: a chain group to name, or to replace the found '
                            'one over the same joints (repeatable)')


def moveit_only(args: argparse.Namespace) -> list[str]:
    """Return the options given that go with --moveit only."""
    return [option for option, given in (('--samples', args.samples is not None),
                                         ('--seed', args.seed is not None),
                                         ('--group', bool(args.groups))) if given]


class _Parser(argparse.ArgumentParser):
    """argparse's parser, whose usage errors are the boundary's one line."""

    def error(self, message: str) -> NoReturn:
        """Raise the usage error, naming where the options are listed."""
        raise UrdfgenpyError(f'{message} (see {self.prog} --help)')


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``urdfgenpy init NAME --moveit --from SOURCE``; a mistake is one line."""
    parser = _Parser(prog='urdfgenpy init --moveit',
                     description='Create a moveit_config package for ROS 2 Jazzy.')
    parser.add_argument('package_name', help='the package to create, e.g. my_robot_moveit_config')
    parser.add_argument('--from', dest='source', default='',
                        help='the robot: a .urdf or .xacro file inside its description package')
    parser.add_argument('--destination-directory', default='.', type=Path)
    parser.add_argument('--license', default='Apache-2.0')
    parser.add_argument('--maintainer-name', default='maintainer')
    parser.add_argument('--maintainer-email', default='maintainer@example.com')
    parser.add_argument('--xacro-args', nargs='*', default=[], metavar='NAME:=VALUE')
    parser.add_argument('--package-path', '-p', action='append', default=[])
    parser.add_argument('--force', action='store_true', help='overwrite existing files')
    add_moveit_arguments(parser)
    return exit_status(FrontEnd(parser.prog, inputs=INIT_INPUTS),
                       lambda: _create(parser.parse_args(argv)))


if __name__ == '__main__':  # pragma: no cover
    sys.exit(main())
