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
The files a documentation page's reader brings, by name.

A page asks for them with ``<!-- docs-test: given NAME ... -->`` before a block;
test_docs.py writes each into the page's scratch folder unless a block made it already.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from urdfgenpy_ros import Box, Inertial, Joint, Link, Origin, Robot, Visual


def _robot_urdf(path: Path) -> None:
    """Write the example pan-tilt unit, with an inertia on its root as many files have."""
    from urdfgenpy_ros.examples import pan_tilt_unit
    robot = pan_tilt_unit()
    robot.get_link('base_link').set_inertial(Inertial.from_sphere(1.0, 0.1))
    robot.save(path)


def _dof_xacro(path: Path) -> None:
    """Write a Xacro arm whose argument ``dof`` says how many segments it has."""
    path.write_text("""<?xml version="1.0"?>
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="dof" default="6"/>
  <xacro:property name="segment_length" value="0.2"/>
  <xacro:macro name="segment" params="n parent">
    <link name="segment_${n}">
      <visual>
        <origin xyz="0 0 ${segment_length / 2}"/>
        <geometry><cylinder radius="0.03" length="${segment_length}"/></geometry>
      </visual>
      <inertial>
        <origin xyz="0 0 ${segment_length / 2}"/>
        <mass value="0.5"/>
        <inertia ixx="0.0018" ixy="0" ixz="0" iyy="0.0018" iyz="0" izz="0.000225"/>
      </inertial>
    </link>
    <joint name="joint_${n}" type="revolute">
      <parent link="${parent}"/>
      <child link="segment_${n}"/>
      <origin xyz="0 0 ${segment_length if n > 1 else 0.05}"/>
      <axis xyz="${n % 2} ${1 - n % 2} 0"/>
      <limit lower="-2" upper="2" effort="10" velocity="1"/>
    </joint>
    <xacro:if value="${n &lt; dof}">
      <xacro:segment n="${n + 1}" parent="segment_${n}"/>
    </xacro:if>
  </xacro:macro>
  <xacro:property name="dof" value="$(arg dof)"/>
  <link name="base_link"/>
  <xacro:segment n="1" parent="base_link"/>
</robot>
""")


def _rover_urdf(path: Path) -> None:
    """Write a small mobile base: base_link and a chassis on a fixed joint."""
    body = Box(0.6, 0.4, 0.15)
    chassis = Link('chassis').set_inertial(
        Inertial.from_geometry(8.0, body, origin=Origin.above(body)))
    robot = Robot('rover').add_link(Link('base_link')).add_link(chassis)
    chassis.add_visual(Visual(body, origin=Origin.above(body)))
    robot.add_joint(Joint('chassis_joint', 'fixed', 'base_link', 'chassis',
                          origin=Origin(xyz=(0, 0, 0.1))))
    robot.save(path)


def _box_stl(path: Path) -> None:
    """Write a closed box 0.1 x 0.05 x 0.02 m as ASCII STL, triangles facing out."""
    x, y, z = 0.05, 0.025, 0.01
    corners = [(sx * x, sy * y, sz * z) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    lines = ['solid box']
    for a, b, c, d in faces:
        for triangle in ((a, b, c), (a, c, d)):
            lines.append('  facet normal 0 0 0\n    outer loop')
            lines += [f'      vertex {" ".join(map(repr, corners[i]))}' for i in triangle]
            lines.append('    endloop\n  endfacet')
    lines.append('endsolid box')
    path.write_text('\n'.join(lines) + '\n')


def _ur5_yaml(path: Path) -> None:
    """Write Universal Robots' UR5 standard DH table (UR's published figures), in degrees."""
    path.write_text("""convention: standard
degrees: true
tool: {xyz: [0, 0, 0.1], rpy: [0, 0, 0]}
rows:
  - {joint: 1, a: 0, alpha: 90, d: 0.089159, lower: -360, upper: 360}
  - {joint: 2, a: -0.425, alpha: 0, d: 0, lower: -360, upper: 360}
  - {joint: 3, a: -0.39225, alpha: 0, d: 0, lower: -180, upper: 180}
  - {joint: 4, a: 0, alpha: 90, d: 0.10915, lower: -360, upper: 360}
  - {joint: 5, a: 0, alpha: -90, d: 0.09465, lower: -360, upper: 360}
  - {joint: 6, a: 0, alpha: 0, d: 0.0823, lower: -360, upper: 360}
""")


GIVEN: dict[str, Callable[[Path], None]] = {
    'robot.urdf': _robot_urdf,
    'robot.urdf.xacro': _dof_xacro,
    'arm.urdf.xacro': _dof_xacro,
    'rover.urdf': _rover_urdf,
    'part.stl': _box_stl,
    'ur5.yaml': _ur5_yaml,
}
