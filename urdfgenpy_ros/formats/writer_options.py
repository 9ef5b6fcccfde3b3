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
The options of the URDF, Xacro, SDF and MJCF writers, declared once each.

Each function is the ``options`` of one row of :data:`~urdfgenpy_ros.formats.table.FORMATS`,
called when the options are first asked for (the MJCF writer's package loads then, not
when ``formats`` is imported).
"""

from __future__ import annotations

from functools import cache
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.formats.options import Option

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def _as_version(robot: RobotModel, version: Any) -> tuple[RobotModel, list[Any]]:
    from urdfgenpy_ros.formats.urdf_downgrade import as_version
    return as_version(robot, version)


@cache
def urdf_options() -> tuple[Option, ...]:
    """Return the URDF writer's options (``--urdf-version`` also for Xacro output)."""
    from urdfgenpy_ros.formats.urdf_downgrade import VERSIONS
    return (Option('version', '--urdf-version', choices=VERSIONS, rank=20, also=('xacro',),
                   transform=_as_version,
                   help_text='URDF output: write what this URDF version holds (1.0 is what ROS 2 '
                             'Jazzy reads: quaternions become rpy, a capsule a cylinder and two '
                             'spheres; each change is printed).'),)


def xacro_options() -> tuple[Option, ...]:
    """Return the Xacro writer's options."""
    return (Option('macro'),)


@cache
def sdf_options() -> tuple[Option, ...]:
    """Return the SDF writer's options."""
    from urdfgenpy_ros.formats.sdf_mimic import VERSIONS
    return (
        Option('lump_fixed', '--lump-fixed', is_flag=True, default=False, rank=10,
               help_text='SDF output: merge links joined by fixed joints into their parents, as '
                         "libsdformat's own URDF conversion does."),
        Option('version', '--sdf-version', choices=VERSIONS, rank=10,
               help_text='SDF output: the SDFormat version (default: 1.11 when a joint mimics '
                         'another, which 1.9 cannot hold, else 1.9).'))


def _gains(option: str, positive: bool) -> Any:
    def parse(words: tuple[str, ...]) -> Any:
        from urdfgenpy_ros.formats.mjcf.gains import parse_gain_words
        return parse_gain_words(option, words, positive)
    return parse


@cache
def mjcf_options() -> tuple[Option, ...]:
    """Return the MJCF writer's options (``--collision`` and ``--report`` are convert's)."""
    from urdfgenpy_ros.collision.methods import METHODS
    from urdfgenpy_ros.formats.mjcf import BASES
    from urdfgenpy_ros.formats.mjcf.actuators import ACTUATOR_TYPES
    return (
        Option('fuse_fixed', '--fuse-fixed', is_flag=True, default=False,
               help_text='MJCF output: merge fixed-joint links into their parents (lumped '
                         'inertia); each merged link stays a <site>.'),
        Option('base', '--base', choices=BASES,
               help_text='MJCF output: weld the root to the world (fixed, the default) or give '
                         "it a free joint (floating). A root link named 'world' welds it."),
        Option('actuators', '--actuators', choices=ACTUATOR_TYPES,
               help_text='MJCF output: this actuator on every joint, instead of the ones '
                         '<ros2_control> declares.'),
        Option('kp', '--kp', multiple=True, metavar='[JOINT=]GAIN', parse=_gains('kp', True),
               help_text="MJCF output: position actuators' gain (MuJoCo's default 1); "
                         'JOINT=GAIN for one joint, repeatable: --kp 2000 --kp '
                         'wrist_3_joint=500.'),
        Option('kv', '--kv', multiple=True, metavar='[JOINT=]GAIN', parse=_gains('kv', False),
               help_text="MJCF output: velocity actuators' gain (MuJoCo's default 1), and the "
                         "position actuators' damping; JOINT=GAIN for one joint, repeatable."),
        Option('scene', '--scene', is_flag=True, default=False,
               help_text='MJCF output: also write scene.xml (floor, light, the robot).'),
        Option('overlay', '--overlay', file=True,
               help_text='MJCF output: merge this MJCF file in by element name (gains, '
                         'contacts, sites, keyframes tuned by hand).'),
        Option('meshdir'), Option('search_paths'), Option('overwrite'),
        Option('strict', '--strict', is_flag=True, default=False,
               help_text='MJCF output: what the MJCF cannot carry is an error: exit 1, '
                         'nothing written.'),
        Option(None, '--report', choices=('text', 'json', 'sarif'), default='text', rank=101,
               help_text="MJCF output: the loss report's format (JSON and SARIF on stdout)."),
        Option(None, '--collision', choices=METHODS,
               help_text='MJCF output: make each collision mesh light first (hull, decompose, '
                         'primitive, decimate, auto; see urdfgenpy collision).'))
