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

"""Built-in example robots, so every command has something to work on."""

from __future__ import annotations

from urdfgenpy_ros.model.geometry import Box, Cylinder, Origin
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.joint import Joint, JointLimit
from urdfgenpy_ros.model.link import Collision, Link, Visual
from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.robot import Robot


def pan_tilt_unit() -> Robot:
    """Return the 2-DOF pan-tilt unit of the getting-started guide, with collisions."""
    charcoal = Material('charcoal', rgba=(0.22, 0.22, 0.25, 1.0))
    amber = Material('amber', rgba=(1.0, 0.55, 0.0, 1.0))

    def part(name: str, shape: Box | Cylinder, origin: Origin, material: Material,
             mass: float) -> Link:
        link = Link(name)
        link.add_visual(Visual(shape, origin=origin, material=material))
        link.add_collision(Collision(shape, origin=origin))
        return link.set_inertial(Inertial.from_geometry(mass, shape, origin=origin))

    plate = Box(0.14, 0.14, 0.025)
    neck = Cylinder(0.028, 0.07)
    head = Box(0.09, 0.05, 0.05)
    robot = Robot('ptu')
    robot.add_material(charcoal).add_material(amber)
    robot.add_link(Link('base_link'))  # massless root: KDL ignores a root's inertia
    robot.add_link(part('base_plate', plate, Origin.above(plate), charcoal, 0.8))
    robot.add_joint(Joint('base_plate_joint', 'fixed', 'base_link', 'base_plate'))
    robot.add_link(part('pan_link', neck, Origin.above(neck), charcoal, 0.18))
    robot.add_link(part('tilt_link', head, Origin(xyz=(0.045, 0, 0)), amber, 0.12))
    robot.add_joint(Joint('pan_joint', 'revolute', 'base_plate', 'pan_link',
                          origin=Origin(xyz=(0, 0, 0.025)), axis=(0, 0, 1),
                          limit=JointLimit(-3.14, 3.14, effort=10, velocity=1.5)))
    robot.add_joint(Joint('tilt_joint', 'revolute', 'pan_link', 'tilt_link',
                          origin=Origin(xyz=(0, 0, 0.07)), axis=(0, 1, 0),
                          limit=JointLimit(-0.52, 1.57, effort=6, velocity=1.5)))
    return robot


EXAMPLES = {'ptu': pan_tilt_unit}
