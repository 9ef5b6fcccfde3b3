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

"""URDF writer: deterministic, diff-friendly text that reads back as the same model."""

from __future__ import annotations

from os import PathLike
from typing import TYPE_CHECKING

from urdfgenpy_ros.formats._xml import (
    Attr, element, fmt, fmt_vec, fragment, INDENT, write_text)
from urdfgenpy_ros.geometry import Box, Cylinder, Geometry, Mesh, Origin, Sphere
from urdfgenpy_ros.inertial import Inertial
from urdfgenpy_ros.joint import Joint
from urdfgenpy_ros.link import Collision, Link, Visual
from urdfgenpy_ros.material import Material
from urdfgenpy_ros.preserved import Preserved

if TYPE_CHECKING:
    from urdfgenpy_ros.robot import Robot

_ZERO3 = (0.0, 0.0, 0.0)
_ONE3 = (1.0, 1.0, 1.0)


def _sub(extras: Preserved | None, tag: str) -> Preserved | None:
    return extras.nested.get(tag) if extras is not None else None


class UrdfWriter:
    """Turn a Robot into URDF text; the Xacro writer overrides a few hooks."""

    declaration = '<?xml version="1.0"?>'

    def __init__(self, robot: Robot) -> None:
        self.robot = robot

    def document(self) -> str:
        """Return the whole file."""
        return f'{self.declaration}\n{self.write_robot()}\n'

    # ---- hooks ----------------------------------------------------------------------

    def robot_attrs(self) -> list[Attr]:
        """Return the root element's attributes."""
        return [('name', self.robot.name, self.robot.name, None)]

    def prologue(self) -> list[str]:
        """Return top-level lines written before the materials."""
        return []

    def write_inertial(self, inertial: Inertial, pad: str, link: Link) -> str:
        """Return the ``<inertial>`` element."""
        inner = pad + INDENT
        children = []
        if inertial.origin.source is not None or not inertial.origin.is_identity:
            children.append(self.write_origin(inertial.origin, inner))
        mass = [('value', inertial.mass, fmt(inertial.mass), None)]
        children.append(element(inner, 'mass', mass, _sub(inertial.extras, 'mass'), []))
        children.append(self.write_inertia(inertial, inner))
        return element(pad, 'inertial', [], inertial.extras, children)

    # ---- elements -------------------------------------------------------------------

    def write_robot(self) -> str:
        """Return the ``<robot>`` element."""
        robot = self.robot
        pad = INDENT
        children = self.prologue()
        children.extend(self.write_material(material, pad) for material in robot.materials)
        for link in robot.links:
            children.append(self.write_link(link, pad))
            children.extend(fragment(block.with_reference(link.name), pad)
                            for block in link.extensions)
        for joint in robot.joints:
            children.append(self.write_joint(joint, pad))
            children.extend(
                fragment(block.with_reference(joint.name) if block.tag == 'gazebo'
                         else block.element, pad)
                for block in joint.extensions)
        children.extend(fragment(block.element, pad) for block in robot.extensions)
        return element('', 'robot', self.robot_attrs(), robot.extras, children)

    def write_material(self, material: Material, pad: str) -> str:
        """Return a ``<material>`` definition or reference."""
        inner = pad + INDENT
        children = []
        if material.rgba is not None:
            rgba = [('rgba', material.rgba, fmt_vec(material.rgba), None)]
            children.append(element(inner, 'color', rgba, _sub(material.extras, 'color'), []))
        if material.texture is not None:
            texture = [('filename', material.texture, material.texture, None)]
            children.append(element(inner, 'texture', texture,
                                    _sub(material.extras, 'texture'), []))
        return element(pad, 'material', [('name', material.name, material.name, None)],
                       material.extras, children)

    def write_link(self, link: Link, pad: str) -> str:
        """Return a ``<link>`` element."""
        inner = pad + INDENT
        children = []
        if link.inertial is not None:
            children.append(self.write_inertial(link.inertial, inner, link))
        children.extend(self.write_visual(visual, inner) for visual in link.visuals)
        children.extend(self.write_collision(collision, inner)
                        for collision in link.collisions)
        return element(pad, 'link', [('name', link.name, link.name, None)], link.extras,
                       children)

    def write_origin(self, origin: Origin, pad: str) -> str:
        """Return an ``<origin>`` element."""
        if origin.extras is None:
            return f'{pad}<origin xyz="{fmt_vec(origin.xyz)}" rpy="{fmt_vec(origin.rpy)}"/>'
        return element(pad, 'origin', [('xyz', origin.xyz, fmt_vec(origin.xyz), _ZERO3),
                                       ('rpy', origin.rpy, fmt_vec(origin.rpy), _ZERO3)],
                       origin.extras, [])

    def write_inertia(self, inertial: Inertial, pad: str) -> str:
        """Return the ``<inertia>`` element."""
        attrs = [(name, getattr(inertial, name), fmt(getattr(inertial, name)), None)
                 for name in ('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz')]
        extras = _sub(inertial.extras, 'inertia')
        return element(pad, 'inertia', attrs, extras, [])

    def _placed(self, tag: str, shape: Visual | Collision, pad: str,
                extra: list[str]) -> str:
        inner = pad + INDENT
        children = []
        if shape.origin.source is not None or not shape.origin.is_identity:
            children.append(self.write_origin(shape.origin, inner))
        children.append(self.write_geometry(shape.geometry, inner))
        children.extend(extra)
        attrs = [] if shape.name is None else [('name', shape.name, shape.name, None)]
        return element(pad, tag, attrs, shape.extras, children)

    def write_visual(self, visual: Visual, pad: str) -> str:
        """Return a ``<visual>`` element."""
        extra = []
        material = visual.material
        if material is not None:
            defined = self.robot._materials.get(material.name)
            if defined is not None and (material.is_reference or defined == material):
                material = Material(material.name, source=material.source,
                                    extras=material.extras)
            extra.append(self.write_material(material, pad + INDENT))
        return self._placed('visual', visual, pad, extra)

    def write_collision(self, collision: Collision, pad: str) -> str:
        """Return a ``<collision>`` element."""
        return self._placed('collision', collision, pad, [])

    def write_geometry(self, geometry: Geometry, pad: str) -> str:
        """Return a ``<geometry>`` element holding one shape."""
        inner = pad + INDENT
        if isinstance(geometry, Box):
            attrs = [('size', geometry.size, fmt_vec(geometry.size), None)]
            shape = element(inner, 'box', attrs, geometry.extras, [])
        elif isinstance(geometry, Cylinder):
            attrs = [('radius', geometry.radius, fmt(geometry.radius), None),
                     ('length', geometry.length, fmt(geometry.length), None)]
            shape = element(inner, 'cylinder', attrs, geometry.extras, [])
        elif isinstance(geometry, Sphere):
            attrs = [('radius', geometry.radius, fmt(geometry.radius), None)]
            shape = element(inner, 'sphere', attrs, geometry.extras, [])
        elif isinstance(geometry, Mesh):
            attrs = [('filename', geometry.filename, geometry.filename, None)]
            if geometry.scale is not None:
                attrs.append(('scale', geometry.scale, fmt_vec(geometry.scale), _ONE3))
            shape = element(inner, 'mesh', attrs, geometry.extras, [])
        else:
            raise TypeError(f'cannot write geometry of type {type(geometry).__name__}')
        outer = _sub(geometry.extras, 'geometry')
        return element(pad, 'geometry', [], outer, [shape])

    def write_joint(self, joint: Joint, pad: str) -> str:
        """Return a ``<joint>`` element."""
        inner = pad + INDENT
        children = []
        if joint.origin.source is not None or not joint.origin.is_identity:
            children.append(self.write_origin(joint.origin, inner))
        extras = joint.extras
        children.append(element(inner, 'parent', [('link', joint.parent, joint.parent, None)],
                                _sub(extras, 'parent'), []))
        children.append(element(inner, 'child', [('link', joint.child, joint.child, None)],
                                _sub(extras, 'child'), []))
        if joint.axis is not None:
            children.append(element(inner, 'axis', [('xyz', joint.axis, fmt_vec(joint.axis),
                                                     None)], _sub(extras, 'axis'), []))
        if joint.calibration is not None:
            calibration = joint.calibration
            attrs = [(name, value, fmt(value), None)
                     for name, value in (('rising', calibration.rising),
                                         ('falling', calibration.falling))
                     if value is not None]
            children.append(element(inner, 'calibration', attrs, calibration.extras, []))
        if joint.dynamics is not None:
            dynamics = joint.dynamics
            children.append(element(inner, 'dynamics', [
                ('damping', dynamics.damping, fmt(dynamics.damping), 0.0),
                ('friction', dynamics.friction, fmt(dynamics.friction), 0.0)],
                dynamics.extras, []))
        if joint.limit is not None:
            limit = joint.limit
            children.append(element(inner, 'limit', [
                ('lower', limit.lower, fmt(limit.lower), 0.0),
                ('upper', limit.upper, fmt(limit.upper), 0.0),
                ('effort', limit.effort, fmt(limit.effort), None),
                ('velocity', limit.velocity, fmt(limit.velocity), None)],
                limit.extras, []))
        if joint.mimic is not None:
            mimic = joint.mimic
            children.append(element(inner, 'mimic', [
                ('joint', mimic.joint, mimic.joint, None),
                ('multiplier', mimic.multiplier, fmt(mimic.multiplier), 1.0),
                ('offset', mimic.offset, fmt(mimic.offset), 0.0)], mimic.extras, []))
        if joint.safety_controller is not None:
            safety = joint.safety_controller
            children.append(element(inner, 'safety_controller', [
                ('soft_lower_limit', safety.soft_lower_limit,
                 fmt(safety.soft_lower_limit), 0.0),
                ('soft_upper_limit', safety.soft_upper_limit,
                 fmt(safety.soft_upper_limit), 0.0),
                ('k_position', safety.k_position, fmt(safety.k_position), 0.0),
                ('k_velocity', safety.k_velocity, fmt(safety.k_velocity), None)],
                safety.extras, []))
        return element(pad, 'joint', [('name', joint.name, joint.name, None),
                                      ('type', joint.type, joint.type.value, None)],
                       joint.extras, children)


def write_urdf(robot: Robot, path: str | PathLike[str] | None = None) -> str:
    """Return the URDF text of ``robot``; also write it to ``path`` when given."""
    text = UrdfWriter(robot).document()
    if path is not None:
        write_text(path, text)
    return text
