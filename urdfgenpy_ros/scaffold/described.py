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
What the description brings along that the package must say.

The Xacro argument values baked into it, the packages its plugins come from, and a
real-hardware plugin that its Gazebo launch would load.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from pathlib import Path
import re

from lxml import etree

from urdfgenpy_ros.formats.xacro import XACRO_NS
from urdfgenpy_ros.resources import PackageResolver
from urdfgenpy_ros.robot import Robot

# pluginlib namespaces whose package has another name
_PLUGIN_PACKAGES = {'mock_components': 'hardware_interface',
                    'fake_components': 'hardware_interface'}
# Gazebo plugin libraries (lib<name>.so, or gz-sim's short names) and their packages
_LIBRARIES = (('gz_ros2_control-system', 'gz_ros2_control'),
              ('ign_ros2_control-system', 'ign_ros2_control'),
              ('gazebo_ros2_control', 'gazebo_ros2_control'),
              ('gazebo_ros_', 'gazebo_plugins'))
# ros2_control hardware that runs in a simulator or in memory, not on the robot
SIMULATED = frozenset(('gz_ros2_control/GazeboSimSystem', 'ign_ros2_control/IgnitionSystem',
                       'gazebo_ros2_control/GazeboSystem', 'mock_components/GenericSystem',
                       'fake_components/GenericSystem'))
_SIMULATION_WORDS = re.compile(r'sim|gazebo|gz|mock|fake|hardware', re.IGNORECASE)


def baked_arguments(robot: Robot, given: Mapping[str, str]) -> list[tuple[str, str, bool]]:
    """
    Return each Xacro argument the source files declare: name, value used, whether given.

    The value used is the one given, else the declaration's default as written.
    """
    declared: dict[str, str] = {}
    for file in robot.included_files:
        for name, default in _declared(Path(file)):
            declared.setdefault(name, default)
    return [(name, given.get(name, default), name in given)
            for name, default in declared.items()]


def _declared(path: Path) -> Iterator[tuple[str, str]]:
    """Yield the ``<xacro:arg name default>`` declarations of a Xacro file."""
    try:
        tree = etree.parse(str(path), etree.XMLParser(remove_comments=True))
    except (OSError, etree.XMLSyntaxError):
        return
    for element in tree.iter(f'{{{XACRO_NS}}}arg'):
        name = element.get('name')
        if name:
            yield name, element.get('default', '')


def hardware_plugins(robot: Robot) -> list[tuple[str, str]]:
    """Return each ``<ros2_control>`` block's name and hardware plugin."""
    found = []
    for block in robot.extensions:
        if block.tag != 'ros2_control':
            continue
        for plugin in block.element.iterfind('hardware/plugin'):
            if plugin.text and plugin.text.strip():
                found.append((block.element.get('name', ''), plugin.text.strip()))
    return found


def referenced_packages(robot: Robot, resolver: PackageResolver) -> list[str]:
    """
    Return the packages the robot's plugins come from, where the package is known.

    A ``<ros2_control>`` hardware plugin ``pkg/Class`` names its package (pluginlib's
    convention); a ``<gazebo>`` plugin its library. A name is listed when it is a known
    package of ROS 2 control or Gazebo, or a package found (search paths, ament index).
    """
    names = [_PLUGIN_PACKAGES.get(plugin.split('/')[0].split('::')[0],
                                  plugin.split('/')[0].split('::')[0])
             for _, plugin in hardware_plugins(robot) if '/' in plugin or '::' in plugin]
    owners: list = [*robot.links, *robot.joints]
    blocks = [*robot.extensions, *(block for owner in owners for block in owner.extensions)]
    for block in blocks:
        for plugin in block.element.iter('plugin'):
            library = Path(plugin.get('filename', '')).name
            names += [package for prefix, package in _LIBRARIES
                      if library.removeprefix('lib').startswith(prefix)]
    known = {*_PLUGIN_PACKAGES.values(), *(package for _, package in _LIBRARIES),
             *(plugin.split('/')[0] for plugin in SIMULATED)}
    return sorted({name for name in names
                   if name in known or resolver.find(name) is not None})


def hardware_warnings(robot: Robot, baked: list[tuple[str, str, bool]]) -> list[str]:
    """Return a line per real-hardware plugin, which the Gazebo launch would load."""
    switches = ', '.join(f'{name}:={value or repr(value)}' for name, value, _ in baked
                         if _SIMULATION_WORDS.search(name))
    lines = []
    for block, plugin in hardware_plugins(robot):
        if plugin in SIMULATED:
            continue
        how = (f'run urdfgenpy init again with the argument that selects simulation (the '
               f'source has {switches})' if switches else
               'give the robot gz_ros2_control/GazeboSimSystem for Gazebo')
        lines.append(f'<ros2_control name="{block}"> uses the hardware plugin {plugin}, '
                     'which drives the real robot: the package keeps it, and '
                     f'launch/gazebo.launch.py would load it ({how})')
    return lines
