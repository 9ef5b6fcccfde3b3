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

"""Gazebo (Harmonic) plugins and ros2_control hardware blocks, as ``Extension`` objects."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING
from xml.sax.saxutils import escape, quoteattr

from urdfgenpy_ros.formats._xml import fmt
from urdfgenpy_ros.model.extensions import Extension
from urdfgenpy_ros.model.joint import JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def _value(value: object) -> str:
    return fmt(value) if isinstance(value, float) else escape(str(value))


def gazebo_plugin(filename: str, name: str, parameters: Mapping[str, object] | None = None,
                  reference: str | None = None) -> Extension:
    """Return ``<gazebo><plugin filename=... name=...>`` with one element per parameter."""
    body = ''.join(f'<{key}>{_value(value)}</{key}>' for key, value in (parameters or {}).items())
    return Extension.gazebo(f'<plugin filename={quoteattr(filename)} name={quoteattr(name)}>'
                            f'{body}</plugin>', reference)


def diff_drive(left_joint: str, right_joint: str, wheel_separation: float,
               wheel_radius: float, *, topic: str = 'cmd_vel', odom_topic: str = 'odom',
               frame_id: str = 'odom', child_frame_id: str = 'base_link') -> Extension:
    """Return Gazebo Harmonic's DiffDrive system for two wheel joints."""
    return gazebo_plugin('gz-sim-diff-drive-system', 'gz::sim::systems::DiffDrive', {
        'left_joint': left_joint, 'right_joint': right_joint,
        'wheel_separation': float(wheel_separation), 'wheel_radius': float(wheel_radius),
        'topic': topic, 'odom_topic': odom_topic, 'frame_id': frame_id,
        'child_frame_id': child_frame_id})


def joint_state_publisher(joints: Iterable[str] = ()) -> Extension:
    """Return Gazebo Harmonic's JointStatePublisher system (all joints when none given)."""
    block = gazebo_plugin('gz-sim-joint-state-publisher-system',
                          'gz::sim::systems::JointStatePublisher')
    plugin = block.element[0]
    for joint in joints:
        plugin.append(Extension(f'<joint_name>{escape(joint)}</joint_name>').element)
    return block


def gz_ros2_control(parameters: str) -> Extension:
    """Return the gz_ros2_control plugin loading the controller ``parameters`` YAML."""
    return gazebo_plugin('gz_ros2_control-system',
                         'gz_ros2_control::GazeboSimROS2ControlPlugin',
                         {'parameters': parameters})


def ros2_control(robot: RobotModel, name: str | None = None,
                 plugin: str = 'gz_ros2_control/GazeboSimSystem',
                 command: Iterable[str] = ('position',),
                 state: Iterable[str] = ('position', 'velocity')) -> Extension:
    """
    Return a ``<ros2_control>`` system with every movable, non-mimic joint of ``robot``.

    Position command interfaces carry the joint's limits as ``min``/``max`` parameters.
    """
    commands, states = list(command), list(state)
    joints = []
    for joint in robot.joints:
        if not joint.type.is_movable or joint.mimic is not None:
            continue
        parts = []
        for interface in commands:
            bounds = ''
            if (interface == 'position' and joint.limit is not None
                    and joint.type is not JointType.CONTINUOUS):
                bounds = (f'<param name="min">{fmt(joint.limit.lower)}</param>'
                          f'<param name="max">{fmt(joint.limit.upper)}</param>')
            parts.append(f'<command_interface name={quoteattr(interface)}>{bounds}'
                         '</command_interface>')
        parts += [f'<state_interface name={quoteattr(interface)}/>' for interface in states]
        joints.append(f'<joint name={quoteattr(joint.name)}>{"".join(parts)}</joint>')
    body = f'<hardware><plugin>{escape(plugin)}</plugin></hardware>{"".join(joints)}'
    return Extension.ros2_control(name or robot.name, body)
