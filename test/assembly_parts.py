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
Parts the assembly tests build in Python: a diff-drive base and a two-finger gripper.

Each carries what a prefix must reach: sensors, Gazebo plugins that name joints and
links, a ``<ros2_control>`` block, a transmission and mimic joints. Also importable as
``assembly_parts:gripper`` for assembly files and the node.
"""

from __future__ import annotations

from urdfgenpy_ros import (Box, Collision, Cylinder, Extension, Inertial, Joint, JointLimit,
                           JointMimic, Link, Material, Origin, Robot, Visual)
from urdfgenpy_ros.model.sensors import Camera, Imu, Lidar
from urdfgenpy_ros.plugins import diff_drive, joint_state_publisher, ros2_control

GREY = Material('grey', rgba=(0.5, 0.5, 0.5, 1.0))
BLACK = Material('black', rgba=(0.0, 0.0, 0.0, 1.0))


def _solid(name: str, shape: Box | Cylinder, mass: float, material: Material,
           origin: Origin | None = None) -> Link:
    origin = origin or Origin()
    link = Link(name)
    link.add_visual(Visual(shape, origin=origin, material=material))
    link.add_collision(Collision(shape, origin=origin))
    return link.set_inertial(Inertial.from_geometry(mass, shape, origin=origin))


def mobile_base() -> Robot:
    """Return a diff-drive base with a lidar, an IMU and Gazebo's drive plugins."""
    robot = Robot('rover').add_material(GREY).add_material(BLACK)
    body = Box(0.5, 0.4, 0.15)
    robot.add_link(Link('base_link'))
    robot.add_link(_solid('chassis', body, 12.0, GREY, Origin.above(body)))
    robot.add_joint(Joint('chassis_joint', 'fixed', 'base_link', 'chassis',
                          origin=Origin((0, 0, 0.05))))
    wheel = Cylinder(0.08, 0.04)
    for side, y in (('left', 0.23), ('right', -0.23)):
        robot.add_link(_solid(f'{side}_wheel', wheel, 0.8, BLACK,
                              Origin(rpy=(1.5707963267948966, 0, 0))))
        robot.add_joint(Joint(f'{side}_wheel_joint', 'continuous', 'chassis',
                              f'{side}_wheel', origin=Origin((0, y, 0.03)), axis=(0, 1, 0)))
    mast = Box(0.06, 0.06, 0.3)
    robot.add_link(_solid('mast', mast, 1.0, GREY, Origin.above(mast)))
    robot.add_joint(Joint('mast_joint', 'fixed', 'chassis', 'mast',
                          origin=Origin((-0.15, 0, 0.15))))
    robot.get_link('mast').add_sensor(Lidar('lidar', origin=Origin((0, 0, 0.32))))
    robot.get_link('chassis').add_sensor(Imu('imu'))
    robot.add_extension(diff_drive('left_wheel_joint', 'right_wheel_joint', 0.46, 0.08))
    robot.add_extension(joint_state_publisher(['left_wheel_joint', 'right_wheel_joint']))
    return robot


def gripper() -> Robot:
    """Return a two-finger gripper: a driven finger, a mimic one, a camera and ros2_control."""
    grey = Material('grey', rgba=(0.7, 0.7, 0.7, 1.0))  # not the base's grey
    robot = Robot('gripper').add_material(grey).add_material(BLACK)
    palm = Box(0.06, 0.12, 0.04)
    robot.add_link(_solid('palm', palm, 0.4, grey, Origin.above(palm)))
    finger = Box(0.02, 0.01, 0.06)
    for side in ('left', 'right'):
        robot.add_link(_solid(f'{side}_finger', finger, 0.05, BLACK, Origin.above(finger)))
    robot.add_joint(Joint('left_finger_joint', 'prismatic', 'palm', 'left_finger',
                          origin=Origin((0, 0.01, 0.04)), axis=(0, 1, 0),
                          limit=JointLimit(0.0, 0.04, effort=20, velocity=0.1)))
    robot.add_joint(Joint('right_finger_joint', 'prismatic', 'palm', 'right_finger',
                          origin=Origin((0, -0.01, 0.04)), axis=(0, -1, 0),
                          limit=JointLimit(0.0, 0.04, effort=20, velocity=0.1),
                          mimic=JointMimic('left_finger_joint')))
    robot.add_link(Link('tool_frame'))
    robot.add_joint(Joint('tool_joint', 'fixed', 'palm', 'tool_frame',
                          origin=Origin((0, 0, 0.1))))
    robot.get_link('palm').add_sensor(Camera('wrist_camera', origin=Origin((0.03, 0, 0.02))))
    robot.get_link('palm').add_extension(Extension.gazebo('<mu1>0.9</mu1>'))
    robot.add_extension(ros2_control(robot))
    robot.add_extension(Extension.transmission('finger_transmission', (
        '<type>transmission_interface/SimpleTransmission</type>'
        '<joint name="left_finger_joint">'
        '<hardwareInterface>hardware_interface/PositionJointInterface</hardwareInterface>'
        '</joint><actuator name="finger_motor"><mechanicalReduction>1</mechanicalReduction>'
        '</actuator>')))
    return robot
