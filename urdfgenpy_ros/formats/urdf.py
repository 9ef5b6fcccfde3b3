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
URDF writer: deterministic, diff-friendly text that reads back as the same model.

Every element has a fast path (an f-string) for what was built in Python and a general
path, :func:`~urdfgenpy_ros.formats._xml.element`, for elements a reader preserved
something of (original number text, unknown attributes or children).
"""

from __future__ import annotations

from os import PathLike
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.errors import ModelTypeError
from urdfgenpy_ros.extensions import Extension
from urdfgenpy_ros.formats._xml import (
    Attr, element, esc, fmt, fmt_vec, fragment, INDENT, verbatim, write_text)
from urdfgenpy_ros.formats.state import state
from urdfgenpy_ros.geometry import (
    Box, Cylinder, Geometry, Mesh, Origin, set_origin_text, Sphere)
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


def _wrap(pad: str, open_tag: str, close_tag: str, children: list[str]) -> str:
    if not children:
        return f'{pad}<{open_tag}/>'
    inside = '\n'.join(children)
    return f'{pad}<{open_tag}>\n{inside}\n{pad}</{close_tag}>'


def _sensor_block(sensor: Any, reference: str, pad: str) -> str:
    """Return the ``<gazebo reference=...>`` block that carries a sensor in URDF."""
    block = Extension('<gazebo/>')
    block.reference = reference
    block.element.append(sensor.to_sdf())
    return fragment(block.element, pad)


class UrdfWriter:
    """Turn a Robot into URDF text; the Xacro writer overrides a few hooks."""

    declaration = '<?xml version="1.0"?>'
    verbatim = True  # write unedited elements read from a file exactly as they were

    def __init__(self, robot: Robot) -> None:
        self.robot = robot
        self._owners: dict[int, Link | Joint] | None = None
        extras = robot.extras
        self.declared = {prefix or '': uri for prefix, uri in extras.node.nsmap.items()
                         } if extras is not None else {}

    def document(self) -> str:
        """Return the whole file, with the comments a read file had around its root."""
        extras = self.robot.extras
        if extras is None or not any(extras.outside):
            return f'{self.declaration}\n{self.write_robot()}\n'
        before, after = ([fragment(node, '') for node in nodes] for nodes in extras.outside)
        return '\n'.join([self.declaration, *before, self.write_robot(), *after]) + '\n'

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
        origin = self._optional_origin(inertial.origin, inner)
        extras = inertial.extras
        if extras is None:
            return (f'{pad}<inertial>\n{origin}{inner}<mass value="{fmt(inertial.mass)}"/>\n'
                    f'{inner}<inertia ixx="{fmt(inertial.ixx)}" ixy="{fmt(inertial.ixy)}" '
                    f'ixz="{fmt(inertial.ixz)}" iyy="{fmt(inertial.iyy)}" '
                    f'iyz="{fmt(inertial.iyz)}" izz="{fmt(inertial.izz)}"/>\n{pad}</inertial>')
        children = [origin[:-1]] if origin else []
        mass = [('value', inertial.mass, fmt(inertial.mass), None)]
        children.append(element(inner, 'mass', mass, _sub(extras, 'mass'), []))
        tensor: list[Attr] = [(name, getattr(inertial, name), fmt(getattr(inertial, name)),
                               None) for name in ('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz')]
        children.append(element(inner, 'inertia', tensor, _sub(extras, 'inertia'), []))
        tags = ['origin', 'mass', 'inertia'] if origin else ['mass', 'inertia']
        return element(pad, 'inertial', [], extras, children, tags)

    def _optional_origin(self, origin: Origin, pad: str) -> str:
        """Return the origin line with its newline, or '' for an identity nobody wrote."""
        if origin.source is None and origin.xyz == _ZERO3 and origin.rpy == _ZERO3:
            return ''
        return self.write_origin(origin, pad) + '\n'

    # ---- elements -------------------------------------------------------------------

    def write_robot(self) -> str:
        """Return the ``<robot>`` element, in the document order it was read in if any."""
        robot = self.robot
        pad = INDENT
        order = robot.extras.order if robot.extras is not None else None
        children = self.prologue()
        materials, links, joints = robot.materials, robot.links, robot.joints
        if order is not None:
            written = set()
            present = {id(item) for item in [*materials, *links, *joints,
                                             *self._all_extensions()]}
            for item in order:
                if id(item) in present:
                    written.add(id(item))
                    children.append(self._write_item(item, pad))
                elif not isinstance(item, (Material, Link, Joint, Extension)):
                    children.append(fragment(item, pad, self.declared))
            materials = [item for item in materials if id(item) not in written]
            links = [item for item in links if id(item) not in written]
            joints = [item for item in joints if id(item) not in written]
        else:
            written = set()
        children.extend(self.write_material(material, pad) for material in materials)
        for link in links:
            children.append(self.write_link(link, pad))
        owners: tuple[Link | Joint, ...] = (*robot.links, *robot.joints)
        for owner in owners:
            children.extend(self._write_item(block, pad, owner)
                            for block in owner.extensions if id(block) not in written)
            children.extend(_sensor_block(sensor, owner.name, pad) for sensor in owner.sensors)
        for joint in joints:
            children.append(self.write_joint(joint, pad))
        children.extend(self._write_item(block, pad) for block in robot.extensions
                        if id(block) not in written)
        attrs = self.robot_attrs()
        if robot.extras is not None:
            declared = {name for name, *_ in attrs}
            for prefix, uri in robot.extras.node.nsmap.items():
                name = f'xmlns:{prefix}' if prefix else 'xmlns'
                if name not in declared and prefix:
                    attrs.append((name, uri, uri, None))
        return element('', 'robot', attrs, robot.extras, children, restore_children=False)

    def _all_extensions(self) -> list[Extension]:
        robot = self.robot
        blocks = list(robot.extensions)
        owners: tuple[Link | Joint, ...] = (*robot.links, *robot.joints)
        for owner in owners:
            blocks.extend(owner.extensions)
        return blocks

    def _write_item(self, item: object, pad: str, owner: Link | Joint | None = None) -> str:
        extras = getattr(item, 'extras', None)
        if extras is not None and extras.state is not None and self.verbatim \
                and extras.state == state(item):  # type: ignore[arg-type]
            return verbatim(extras.node, pad, self.declared)
        if isinstance(item, Link):
            return self.write_link(item, pad)
        if isinstance(item, Joint):
            return self.write_joint(item, pad)
        if isinstance(item, Material):
            return self.write_material(item, pad)
        assert isinstance(item, Extension)
        if owner is None:
            owner = self._owner(item)
        if owner is not None and (item.tag == 'gazebo' or isinstance(owner, Link)):
            return fragment(item.with_reference(owner.name), pad, self.declared)
        return fragment(item.element, pad, self.declared)

    def _owner(self, block: Extension) -> Link | Joint | None:
        if self._owners is None:
            owners: tuple[Link | Joint, ...] = (*self.robot.links, *self.robot.joints)
            self._owners = {id(candidate): owner
                            for owner in owners
                            for candidate in owner.extensions}
        return self._owners.get(id(block))

    def write_material(self, material: Material, pad: str) -> str:
        """Return a ``<material>`` definition or reference."""
        inner = pad + INDENT
        extras = material.extras
        children, tags = [], []
        if material.rgba is not None:
            rgba = [('rgba', material.rgba, fmt_vec(material.rgba), None)]
            children.append(element(inner, 'color', rgba, _sub(extras, 'color'), []))
            tags.append('color')
        if material.texture is not None:
            texture = [('filename', material.texture, material.texture, None)]
            children.append(element(inner, 'texture', texture, _sub(extras, 'texture'), []))
            tags.append('texture')
        return element(pad, 'material', [('name', material.name, material.name, None)],
                       extras, children, tags)

    def write_link(self, link: Link, pad: str) -> str:
        """Return a ``<link>`` element."""
        inner = pad + INDENT
        children = []
        if link.inertial is not None:
            children.append(self.write_inertial(link.inertial, inner, link))
        for visual in link.visuals:
            children.append(self.write_visual(visual, inner))
        for collision in link.collisions:
            children.append(self.write_collision(collision, inner))
        if link.extras is None:
            return _wrap(pad, f'link name="{esc(link.name)}"', 'link', children)
        tags = ['inertial'] if link.inertial is not None else []
        tags += ['visual'] * len(link.visuals) + ['collision'] * len(link.collisions)
        return element(pad, 'link', [('name', link.name, link.name, None)], link.extras,
                       children, tags)

    def write_origin(self, origin: Origin, pad: str) -> str:
        """Return an ``<origin>`` element."""
        if origin.extras is not None:
            return element(pad, 'origin', [('xyz', origin.xyz, fmt_vec(origin.xyz), _ZERO3),
                                           ('rpy', origin.rpy, fmt_vec(origin.rpy), _ZERO3)],
                           origin.extras, [])
        text = origin.text
        if text is None:
            text = f'xyz="{fmt_vec(origin.xyz)}" rpy="{fmt_vec(origin.rpy)}"'
            set_origin_text(origin, text)
        return f'{pad}<origin {text}/>'

    def _placed(self, tag: str, shape: Visual | Collision, pad: str, extra: str) -> str:
        inner = pad + INDENT
        origin = self._optional_origin(shape.origin, inner)
        geometry = self.write_geometry(shape.geometry, inner)
        if shape.extras is None:
            name = '' if shape.name is None else f' name="{esc(shape.name)}"'
            return f'{pad}<{tag}{name}>\n{origin}{geometry}\n{extra}{pad}</{tag}>'
        children = [origin[:-1]] if origin else []
        children.append(geometry)
        if extra:
            children.append(extra[:-1])
        tags = (['origin'] if origin else []) + ['geometry'] + (['material'] if extra else [])
        attrs: list[Attr] = [] if shape.name is None else [('name', shape.name, shape.name,
                                                            None)]
        return element(pad, tag, attrs, shape.extras, children, tags)

    def write_visual(self, visual: Visual, pad: str) -> str:
        """Return a ``<visual>`` element."""
        extra = ''
        material = visual.material
        if material is not None:
            defined = self.robot._materials.get(material.name)
            if defined is not None and material is not defined and not material.is_reference:
                if material.source is None and material == defined:
                    material = defined  # built in Python as a copy: refer to it
            if material is defined:
                material = Material(material.name)
            extra = self.write_material(material, pad + INDENT) + '\n'
        return self._placed('visual', visual, pad, extra)

    def write_collision(self, collision: Collision, pad: str) -> str:
        """Return a ``<collision>`` element."""
        return self._placed('collision', collision, pad, '')

    def write_geometry(self, geometry: Geometry, pad: str) -> str:
        """Return a ``<geometry>`` element holding one shape."""
        inner = pad + INDENT
        if geometry.extras is None and type(geometry) is Box:
            return (f'{pad}<geometry>\n{inner}<box size="{fmt_vec(geometry.size)}"/>\n'
                    f'{pad}</geometry>')
        attrs: list[Attr]
        if isinstance(geometry, Box):
            tag, attrs = 'box', [('size', geometry.size, fmt_vec(geometry.size), None)]
        elif isinstance(geometry, Cylinder):
            tag, attrs = 'cylinder', [('radius', geometry.radius, fmt(geometry.radius), None),
                                      ('length', geometry.length, fmt(geometry.length), None)]
        elif isinstance(geometry, Sphere):
            tag, attrs = 'sphere', [('radius', geometry.radius, fmt(geometry.radius), None)]
        elif isinstance(geometry, Mesh):
            tag, attrs = 'mesh', [('filename', geometry.filename, geometry.filename, None)]
            if geometry.scale is not None:
                attrs.append(('scale', geometry.scale, fmt_vec(geometry.scale), _ONE3))
        else:
            raise ModelTypeError(f'cannot write geometry of type {type(geometry).__name__}')
        shape = element(inner, tag, attrs, geometry.extras, [])
        return element(pad, 'geometry', [], _sub(geometry.extras, 'geometry'), [shape])

    def write_joint(self, joint: Joint, pad: str) -> str:
        """Return a ``<joint>`` element."""
        inner = pad + INDENT
        origin = self._optional_origin(joint.origin, inner)
        if joint.extras is None:
            axis = '' if joint.axis is None else f'{inner}<axis xyz="{fmt_vec(joint.axis)}"/>\n'
            limit = joint.limit
            if (limit is not None and limit.extras is None and joint.calibration is None
                    and joint.dynamics is None):
                rest = (f'{inner}<limit lower="{fmt(limit.lower)}" upper="{fmt(limit.upper)}" '
                        f'effort="{fmt(limit.effort)}" velocity="{fmt(limit.velocity)}"/>\n')
                if joint.mimic is not None or joint.safety_controller is not None:
                    rest += ''.join(line + '\n' for line in self._joint_parts(joint, inner,
                                                                              after_limit=True))
            else:
                rest = ''.join(line + '\n' for line in self._joint_parts(joint, inner))
            return (f'{pad}<joint name="{esc(joint.name)}" type="{joint.type.value}">\n'
                    f'{origin}{inner}<parent link="{esc(joint.parent)}"/>\n'
                    f'{inner}<child link="{esc(joint.child)}"/>\n{axis}{rest}{pad}</joint>')
        extras = joint.extras
        children = [origin[:-1]] if origin else []
        for tag, link in (('parent', joint.parent), ('child', joint.child)):
            children.append(element(inner, tag, [('link', link, link, None)],
                                    _sub(extras, tag), []))
        if joint.axis is not None:
            axis_attrs: list[Attr] = [('xyz', joint.axis, fmt_vec(joint.axis), None)]
            children.append(element(inner, 'axis', axis_attrs, _sub(extras, 'axis'), []))
        tags = (['origin'] if origin else []) + ['parent', 'child']
        tags += ['axis'] if joint.axis is not None else []
        parts = self._joint_parts(joint, inner)
        children.extend(parts)
        tags += [part.split(None, 1)[0].lstrip('<') for part in parts]
        return element(pad, 'joint', [('name', joint.name, joint.name, None),
                                      ('type', joint.type, joint.type.value, None)],
                       extras, children, tags)

    def _joint_parts(self, joint: Joint, pad: str, after_limit: bool = False) -> list[str]:
        """Return calibration, dynamics, limit, mimic and safety_controller, as present."""
        parts = []
        calibration = joint.calibration
        if calibration is not None and not after_limit:
            attrs = [(name, value, fmt(value), None)
                     for name, value in (('rising', calibration.rising),
                                         ('falling', calibration.falling))
                     if value is not None]
            parts.append(element(pad, 'calibration', attrs, calibration.extras, []))
        dynamics = joint.dynamics
        if dynamics is not None and not after_limit:
            parts.append(element(pad, 'dynamics', [
                ('damping', dynamics.damping, fmt(dynamics.damping), 0.0),
                ('friction', dynamics.friction, fmt(dynamics.friction), 0.0)],
                dynamics.extras, []))
        limit = joint.limit
        if limit is not None and not after_limit:
            parts.append(element(pad, 'limit', [
                ('lower', limit.lower, fmt(limit.lower), 0.0),
                ('upper', limit.upper, fmt(limit.upper), 0.0),
                ('effort', limit.effort, fmt(limit.effort), None),
                ('velocity', limit.velocity, fmt(limit.velocity), None)],
                limit.extras, []))
        mimic = joint.mimic
        if mimic is not None:
            parts.append(element(pad, 'mimic', [
                ('joint', mimic.joint, mimic.joint, None),
                ('multiplier', mimic.multiplier, fmt(mimic.multiplier), 1.0),
                ('offset', mimic.offset, fmt(mimic.offset), 0.0)], mimic.extras, []))
        safety = joint.safety_controller
        if safety is not None:
            parts.append(element(pad, 'safety_controller', [
                ('soft_lower_limit', safety.soft_lower_limit,
                 fmt(safety.soft_lower_limit), 0.0),
                ('soft_upper_limit', safety.soft_upper_limit,
                 fmt(safety.soft_upper_limit), 0.0),
                ('k_position', safety.k_position, fmt(safety.k_position), 0.0),
                ('k_velocity', safety.k_velocity, fmt(safety.k_velocity), None)],
                safety.extras, []))
        return parts


def write_urdf(robot: Robot, path: str | PathLike[str] | None = None) -> str:
    """Return the URDF text of ``robot``; also write it to ``path`` when given."""
    text = UrdfWriter(robot).document()
    if path is not None:
        write_text(path, text)
    return text
