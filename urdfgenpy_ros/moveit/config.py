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
The YAML files of a moveit_config package, as MoveIt's Setup Assistant writes them.

``kinematics.yaml`` (KDL for each chain group), ``joint_limits.yaml`` (velocities from
the URDF, accelerations from URDF 1.2 ``<limit acceleration>`` where given),
``initial_positions.yaml``, ``ros2_controllers.yaml`` and ``moveit_controllers.yaml`` (a
joint_trajectory_controller per chain group, a gripper action controller per gripper, on
the command interface the robot's ``<ros2_control>`` declares, else position), and
``pilz_cartesian_limits.yaml``. Each is a plain dict; the package writer dumps them.
"""

from __future__ import annotations

from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.dynamics import movable_joints
from urdfgenpy_ros.formats.mjcf.actuators import blocks, initial_values
from urdfgenpy_ros.moveit import sampling
from urdfgenpy_ros.moveit.srdf import group_joints, Srdf

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

KDL = 'kdl_kinematics_plugin/KDLKinematicsPlugin'
DEFAULT_SCALING = 0.1  # the Setup Assistant's velocity and acceleration scaling


def kinematics(srdf: Srdf) -> dict[str, Any]:
    """Return kinematics.yaml: the KDL solver for each chain group."""
    return {group.name: {'kinematics_solver': KDL,
                         'kinematics_solver_search_resolution': 0.005,
                         'kinematics_solver_timeout': 0.005}
            for group in srdf.groups if group.base is not None}


def joint_limits(robot: RobotModel) -> dict[str, Any]:
    """Return joint_limits.yaml: each active joint's velocity and acceleration limits."""
    limits = {}
    for name in movable_joints(robot):
        limit = robot.get_joint(name).limit
        velocity = float(limit.velocity) if limit is not None else 0.0
        acceleration = limit.acceleration if limit is not None else None
        limits[name] = {'has_velocity_limits': velocity > 0.0,
                        'max_velocity': velocity,
                        'has_acceleration_limits': acceleration is not None,
                        'max_acceleration': float(acceleration or 0.0)}
    return {'default_velocity_scaling_factor': DEFAULT_SCALING,
            'default_acceleration_scaling_factor': DEFAULT_SCALING,
            'joint_limits': limits}


def initial_positions(robot: RobotModel) -> dict[str, Any]:
    """Return initial_positions.yaml: ros2_control's initial values, else MoveIt's default."""
    given = initial_values(robot)
    default = dict(zip(movable_joints(robot), sampling.default_state(robot)))
    return {'initial_positions': {name: float(given.get(name, default[name]))
                                  for name in movable_joints(robot)}}


def command_interface(robot: RobotModel, joint: str) -> str:
    """Return the first command interface ``<ros2_control>`` declares for ``joint``."""
    for block in blocks(robot, 'ros2_control'):
        for element in block.findall('joint'):
            if element.get('name') == joint:
                for interface in element.findall('command_interface'):
                    if interface.get('name'):
                        return str(interface.get('name'))
    return 'position'


def controllers(robot: RobotModel, srdf: Srdf) -> list[tuple[str, str, list[str]]]:
    """Return each controller: its name, kind (``arm`` or ``gripper``) and joints."""
    found = []
    for group in srdf.groups:
        joints = group_joints(robot, group)
        if joints:
            found.append((f'{group.name}_controller',
                          'arm' if group.base is not None else 'gripper', joints))
    return found


def ros2_controllers(robot: RobotModel, srdf: Srdf, rate: int = 100) -> dict[str, Any]:
    """Return ros2_controllers.yaml for the controllers of :func:`controllers`."""
    manager: dict[str, Any] = {'update_rate': rate, 'joint_state_broadcaster': {
        'type': 'joint_state_broadcaster/JointStateBroadcaster'}}
    document: dict[str, Any] = {'controller_manager': {'ros__parameters': manager}}
    for name, kind, joints in controllers(robot, srdf):
        interface = command_interface(robot, joints[0])
        if kind == 'arm':
            manager[name] = {'type': 'joint_trajectory_controller/JointTrajectoryController'}
            parameters = {'joints': joints, 'command_interfaces': [interface],
                          'state_interfaces': ['position', 'velocity'],
                          'allow_nonzero_velocity_at_trajectory_end': True}
        else:
            manager[name] = {'type': 'position_controllers/GripperActionController'}
            parameters = {'joint': joints[0]}
        document[name] = {'ros__parameters': parameters}
    return document


def moveit_controllers(robot: RobotModel, srdf: Srdf) -> dict[str, Any]:
    """Return moveit_controllers.yaml: MoveIt's simple controller manager over them."""
    manager: dict[str, Any] = {'controller_names': []}
    for name, kind, joints in controllers(robot, srdf):
        manager['controller_names'].append(name)
        manager[name] = {'type': 'FollowJointTrajectory' if kind == 'arm'
                         else 'GripperCommand',
                         'joints': joints if kind == 'arm' else joints[:1],
                         'action_ns': 'follow_joint_trajectory' if kind == 'arm'
                         else 'gripper_cmd',
                         'default': True}
    return {'moveit_controller_manager':
            'moveit_simple_controller_manager/MoveItSimpleControllerManager',
            'moveit_simple_controller_manager': manager}


def pilz_cartesian_limits() -> dict[str, Any]:
    """Return pilz_cartesian_limits.yaml: the Setup Assistant's defaults."""
    return {'cartesian_limits': {'max_trans_vel': 1.0, 'max_trans_acc': 2.25,
                                 'max_trans_dec': -5.0, 'max_rot_vel': 1.57}}
