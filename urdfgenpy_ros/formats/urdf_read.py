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
URDF reader: the model of a file, keeping in place everything the model does not hold.

An element whose text the writer would reproduce exactly gets no ``extras``; any other
(unknown attributes or children, comments, numbers written differently, optional
attributes left out) keeps its source node, so that writing gives the file back.
"""

from __future__ import annotations

from collections.abc import Callable
from os import PathLike
from pathlib import Path
from typing import Any

from urdfgenpy_ros import checks
from urdfgenpy_ros.errors import ParseError, ReadWarning, SourceLocation
from urdfgenpy_ros.extensions import Extension
from urdfgenpy_ros.formats._parse import parse_xml, Source
from urdfgenpy_ros.formats._xml import fmt, fmt_vec
from urdfgenpy_ros.formats.state import state
from urdfgenpy_ros.geometry import Box, Cylinder, Geometry, IDENTITY, Mesh, Origin, Sphere
from urdfgenpy_ros.inertial import INERTIA_ATTRS, Inertial
from urdfgenpy_ros.joint import (
    Joint, JointCalibration, JointDynamics, JointLimit, JointMimic, JointType,
    SafetyController)
from urdfgenpy_ros.link import Collision, Link, Visual
from urdfgenpy_ros.material import Material
from urdfgenpy_ros.preserved import Preserved
from urdfgenpy_ros.robot import Robot


def _known(attributes: str, children: str = '') -> tuple[frozenset[str], frozenset[str]]:
    return frozenset(attributes.split()), frozenset(children.split())


# The order the writer puts known children in; a file in another order keeps its own.
_WRITTEN_ORDER = {tag: {child: rank for rank, child in enumerate(children.split())} for tag,
                  children in (('link', 'inertial visual collision'),
                               ('inertial', 'origin mass inertia'),
                               ('visual', 'origin geometry material'),
                               ('collision', 'origin geometry'),
                               ('material', 'color texture'),
                               ('joint', 'origin parent child axis calibration dynamics '
                                         'limit mimic safety_controller'))}


KNOWN = {
    'robot': _known('name', 'link joint material'),
    'link': _known('name', 'inertial visual collision'),
    'inertial': _known('', 'origin mass inertia'),
    'mass': _known('value'),
    'inertia': _known(' '.join(INERTIA_ATTRS)),
    'visual': _known('name', 'origin geometry material'),
    'collision': _known('name', 'origin geometry'),
    'origin': _known('xyz rpy'),
    'geometry': _known('', 'box cylinder sphere mesh'),
    'box': _known('size'),
    'cylinder': _known('radius length'),
    'sphere': _known('radius'),
    'mesh': _known('filename scale'),
    'material': _known('name', 'color texture'),
    'color': _known('rgba'),
    'texture': _known('filename'),
    'joint': _known('name type', 'origin parent child axis calibration dynamics limit '
                                 'mimic safety_controller'),
    'parent': _known('link'),
    'child': _known('link'),
    'axis': _known('xyz'),
    'calibration': _known('rising falling'),
    'dynamics': _known('damping friction'),
    'limit': _known('lower upper effort velocity'),
    'mimic': _known('joint multiplier offset'),
    'safety_controller': _known('soft_lower_limit soft_upper_limit k_position k_velocity'),
}
EXTENSION_TAGS = frozenset(('gazebo', 'transmission', 'ros2_control'))
_TYPES = ', '.join(kind.value for kind in JointType)
_SHAPES = 'box, cylinder, sphere or mesh'


class _Reader:
    """Read one document; ``plain`` tracks whether the element at hand is canonical."""

    def __init__(self, source: Source, warnings: list[ReadWarning]) -> None:
        self.source = source
        self.file = source.file
        self.warnings = warnings
        self.plain = True

    # ---- attributes ---------------------------------------------------------------

    def fail(self, node: Any, message: str, code: str = 'P002',
             attribute: str | None = None) -> ParseError:
        """Return a ParseError at ``node`` (or at one of its attributes)."""
        return ParseError(message, self.source.at(node, attribute), code)

    def where(self, node: Any) -> SourceLocation:
        """Return the location of ``node`` (file and line)."""
        return SourceLocation(self.file, node.sourceline)

    def text(self, node: Any, name: str, expected: str) -> str:
        """Return a required attribute's text."""
        value = node.get(name)
        if value is None:
            raise self.fail(node, f'{_describe(node)}: missing {name!r} ({expected})')
        return value

    def number(self, node: Any, name: str, default: float | None = None) -> float:
        """Return a float attribute; None default means required."""
        text = node.get(name)
        if text is None:
            if default is None:
                raise self.fail(node, f'{_describe(node)}: missing {name!r} (a number)')
            self.plain = False
            return default
        try:
            value = float(text)
        except ValueError:
            raise self.fail(node, f'{_describe(node)}: {name} {text!r} is not a number '
                                  '(write e.g. 0.5 or 1e-3)', 'P003', name) from None
        if self.plain and fmt(value) != text:
            self.plain = False
        return value

    def numbers(self, node: Any, name: str, count: int,
                default: tuple[float, ...] | None = None) -> tuple[float, ...]:
        """Return a space-separated vector attribute of ``count`` floats."""
        text = node.get(name)
        if text is None:
            if default is None:
                raise self.fail(node, f'{_describe(node)}: missing {name!r} '
                                      f'({count} numbers)')
            self.plain = False
            return default
        parts = text.split()
        try:
            values = tuple(float(part) for part in parts)
        except ValueError:
            values = ()
        if len(values) != count or len(parts) != count:
            raise self.fail(node, f'{_describe(node)}: {name} {text!r} must be {count} '
                                  'numbers separated by spaces', 'P003', name)
        if self.plain and fmt_vec(values) != text:
            self.plain = False
        return values

    def keep(self, node: Any, tag: str,
             nested: dict[str, Preserved] | None = None) -> Preserved | None:
        """Return what must be kept of ``node``, or None when the writer reproduces it."""
        attributes, children = KNOWN[tag]
        if self.plain and not nested:
            if node.text is not None and not node.text.isspace():
                self.plain = False
            elif len(node) and not _in_written_order(node, tag, children):
                self.plain = False
            elif not _attributes_in_written_order(node, tag):
                self.plain = False
            else:
                return None
        return Preserved(node, attributes, children, nested)

    def plain_child(self, node: Any, tag: str, nested: dict[str, Preserved]) -> None:
        """Record a child without a model object of its own (``<mass>`` ...)."""
        kept = self.keep(node, tag)
        if kept is not None:
            nested[tag] = kept

    # ---- elements -----------------------------------------------------------------

    def origin(self, node: Any) -> Origin:
        """Read an ``<origin>``."""
        self.plain = True
        xyz = self.numbers(node, 'xyz', 3, (0.0, 0.0, 0.0))
        rpy = self.numbers(node, 'rpy', 3, (0.0, 0.0, 0.0))
        return Origin(xyz, rpy, source=self.where(node), extras=self.keep(node, 'origin'))

    def material(self, node: Any) -> Material:
        """Read a ``<material>`` definition or reference."""
        self.plain = True
        name = self.text(node, 'name', 'the material name')
        rgba: Any = None
        texture: str | None = None
        nested: dict[str, Any] = {}
        for child in node:
            if child.tag == 'color' and rgba is None:
                rgba = self.numbers(child, 'rgba', 4)
                self.plain_child(child, 'color', nested)
            elif child.tag == 'texture' and texture is None:
                texture = child.get('filename', '')
                self.plain_child(child, 'texture', nested)
        return Material(name, rgba, texture, source=self.where(node),
                        extras=self.keep(node, 'material', nested))

    def geometry(self, node: Any) -> Geometry:
        """Read a ``<geometry>`` and its one shape."""
        shapes = [child for child in node if isinstance(child.tag, str)]
        if not shapes:
            raise self.fail(node, f'<geometry> has no shape (use {_SHAPES})', 'P006')
        shape = shapes[0]
        reader = _SHAPE_READERS.get(shape.tag)
        if reader is None:
            raise self.fail(shape, f'unknown geometry <{shape.tag}> (URDF has {_SHAPES})',
                            'P006')
        self.plain = True
        wrapper: dict[str, Preserved] = {}
        self.plain_child(node, 'geometry', wrapper)
        self.plain = not wrapper
        return reader(self, shape, wrapper)

    def _box(self, node: Any, wrapper: dict[str, Preserved]) -> Box:
        size = self.numbers(node, 'size', 3)
        return Box(*size, source=self.where(node), extras=self.keep(node, 'box', wrapper))

    def _cylinder(self, node: Any, wrapper: dict[str, Preserved]) -> Cylinder:
        radius, length = self.number(node, 'radius'), self.number(node, 'length')
        return Cylinder(radius, length, source=self.where(node),
                        extras=self.keep(node, 'cylinder', wrapper))

    def _sphere(self, node: Any, wrapper: dict[str, Preserved]) -> Sphere:
        return Sphere(self.number(node, 'radius'), source=self.where(node),
                      extras=self.keep(node, 'sphere', wrapper))

    def _mesh(self, node: Any, wrapper: dict[str, Preserved]) -> Mesh:
        filename = node.get('filename')
        if not filename:
            raise self.fail(node, "<mesh>: missing 'filename' (the mesh file, e.g. "
                                  'package://my_robot/meshes/part.stl)')
        scale: Any = self.numbers(node, 'scale', 3) if node.get('scale') is not None else None
        return Mesh(filename, scale, source=self.where(node),
                    extras=self.keep(node, 'mesh', wrapper))

    def _placed(self, node: Any, tag: str) -> tuple[Origin, Geometry, Material | None]:
        origin, geometry, material = IDENTITY, None, None
        for child in node:
            if child.tag == 'origin' and origin is IDENTITY:
                origin = self.origin(child)
            elif child.tag == 'geometry' and geometry is None:
                geometry = self.geometry(child)
            elif child.tag == 'material' and tag == 'visual' and material is None:
                material = self.material(child)
        if geometry is None:
            raise self.fail(node, f'<{tag}>: missing <geometry> (give a {_SHAPES})')
        return origin, geometry, material

    def visual(self, node: Any) -> Visual:
        """Read a ``<visual>``."""
        origin, geometry, material = self._placed(node, 'visual')
        self.plain = True
        return Visual(geometry, origin=origin, material=material, name=node.get('name'),
                      source=self.where(node), extras=self.keep(node, 'visual'))

    def collision(self, node: Any) -> Collision:
        """Read a ``<collision>``."""
        origin, geometry, _ = self._placed(node, 'collision')
        self.plain = True
        return Collision(geometry, origin=origin, name=node.get('name'),
                         source=self.where(node), extras=self.keep(node, 'collision'))

    def inertial(self, node: Any) -> Inertial:
        """Read an ``<inertial>``."""
        origin, mass, tensor = IDENTITY, None, None
        nested: dict[str, Preserved] = {}
        for child in node:
            if child.tag == 'origin' and origin is IDENTITY:
                origin = self.origin(child)
        self.plain = True
        for child in node:
            if child.tag == 'mass' and mass is None:
                mass = self.number(child, 'value')
                self.plain_child(child, 'mass', nested)
            elif child.tag == 'inertia' and tensor is None:
                tensor = [self.number(child, name) for name in INERTIA_ATTRS]
                self.plain_child(child, 'inertia', nested)
        if mass is None:
            raise self.fail(node, '<inertial>: missing <mass value=...> (the mass in kg)')
        if tensor is None:
            raise self.fail(node, '<inertial>: missing <inertia ixx=... izz=...> (the '
                                  'tensor about the centre of mass)')
        return Inertial(mass, *tensor, origin=origin, source=self.where(node),
                        extras=self.keep(node, 'inertial', nested))

    def link(self, node: Any) -> Link:
        """Read a ``<link>``."""
        name = self.text(node, 'name', 'the link name')
        link = Link(name, source=self.where(node))
        for child in node:
            tag = child.tag
            if tag == 'visual':
                link.visuals.append(self.visual(child))
            elif tag == 'collision':
                link.collisions.append(self.collision(child))
            elif tag == 'inertial' and link.inertial is None:
                link.inertial = self.inertial(child)
        self.plain = True
        link.extras = self.keep(node, 'link')
        return link

    def joint(self, node: Any) -> Joint:
        """Read a ``<joint>``."""
        name = self.text(node, 'name', 'the joint name')
        kind = self.text(node, 'type', f'one of {_TYPES}')
        if kind not in _JOINT_TYPES:
            raise self.fail(node, f'joint {name!r}: unknown type {kind!r} (use one of '
                                  f'{_TYPES})', 'P004', 'type')
        parts: dict[str, Any] = {}
        ends: dict[str, str] = {}
        origin = IDENTITY
        for child in node:
            tag = child.tag
            if tag in ('parent', 'child') and tag not in ends:
                ends[tag] = self.text(child, 'link', f'the {tag} link name')
            elif tag == 'origin' and origin is IDENTITY:
                origin = self.origin(child)
            elif tag in _JOINT_PARTS and tag not in parts:
                self.plain = True
                parts[tag] = _JOINT_PARTS[tag](self, child)
        for tag in ('parent', 'child'):
            if tag not in ends:
                raise self.fail(node, f'joint {name!r}: missing <{tag} link=...> (the '
                                      f'{tag} link)')
        self.plain = True
        nested: dict[str, Preserved] = {}
        axis = None
        for child in node:
            if child.tag in ('parent', 'child'):
                self.plain_child(child, child.tag, nested)
            elif child.tag == 'axis' and axis is None:
                axis = self.numbers(child, 'xyz', 3, (1.0, 0.0, 0.0))
                self.plain_child(child, 'axis', nested)
        return Joint(name, kind, ends['parent'], ends['child'], origin=origin, axis=axis,
                     limit=parts.get('limit'), dynamics=parts.get('dynamics'),
                     mimic=parts.get('mimic'),
                     safety_controller=parts.get('safety_controller'),
                     calibration=parts.get('calibration'), source=self.where(node),
                     extras=self.keep(node, 'joint', nested))

    def _limit(self, node: Any) -> JointLimit:
        lower, upper = self.number(node, 'lower', 0.0), self.number(node, 'upper', 0.0)
        effort, velocity = self.number(node, 'effort'), self.number(node, 'velocity')
        return JointLimit(lower, upper, effort=effort, velocity=velocity,
                          source=self.where(node), extras=self.keep(node, 'limit'))

    def _dynamics(self, node: Any) -> JointDynamics:
        damping, friction = self.number(node, 'damping', 0.0), self.number(node, 'friction',
                                                                           0.0)
        return JointDynamics(damping, friction, source=self.where(node),
                             extras=self.keep(node, 'dynamics'))

    def _mimic(self, node: Any) -> JointMimic:
        leader = self.text(node, 'joint', 'the name of the joint to follow')
        multiplier, offset = self.number(node, 'multiplier', 1.0), self.number(node, 'offset',
                                                                               0.0)
        return JointMimic(leader, multiplier, offset, source=self.where(node),
                          extras=self.keep(node, 'mimic'))

    def _safety(self, node: Any) -> SafetyController:
        values = [self.number(node, 'soft_lower_limit', 0.0),
                  self.number(node, 'soft_upper_limit', 0.0),
                  self.number(node, 'k_position', 0.0), self.number(node, 'k_velocity')]
        return SafetyController(*values, source=self.where(node),
                                extras=self.keep(node, 'safety_controller'))

    def _calibration(self, node: Any) -> JointCalibration:
        rising = self.number(node, 'rising') if node.get('rising') is not None else None
        falling = self.number(node, 'falling') if node.get('falling') is not None else None
        return JointCalibration(rising, falling, source=self.where(node),
                                extras=self.keep(node, 'calibration'))

    # ---- the robot ----------------------------------------------------------------

    def robot(self, root: Any) -> Robot:
        """Read the ``<robot>`` element and everything in it."""
        root = self._robot_element(root)
        name = root.get('name')
        if not name:
            raise self.fail(root, "<robot>: missing 'name' (give the robot a name)")
        robot = Robot(name)
        robot.source = self.where(root)
        order: list[Any] = []
        joints: list[Joint] = []
        seen: dict[tuple[str, str], int] = {}
        for node in root:
            tag = node.tag
            if tag in ('link', 'joint', 'material'):
                item = getattr(self, tag)(node)
                first = seen.setdefault((tag, item.name), node.sourceline)
                if first != node.sourceline:
                    raise self.fail(node, f'{tag} {item.name!r} is defined twice (first at '
                                          f'line {first}): rename or remove one', 'P007',
                                    'name')
                if tag == 'link':
                    robot.add_link(item)
                elif tag == 'joint':
                    joints.append(item)
                else:
                    robot.add_material(item)
                order.append(item)
            elif tag in EXTENSION_TAGS:
                block = Extension(node, self.where(node))
                order.append(block)
                self._attach(robot, block, joints)
            else:
                order.append(node)
        for joint in joints:
            robot.add_joint(joint)
        _share_materials(robot)
        for item, node in zip(order, root):  # to write unedited elements verbatim
            if isinstance(item, (Link, Joint)) and item.extras is None:
                item.extras = Preserved(node, *KNOWN[node.tag])
            if isinstance(item, (Link, Joint, Material)) and item.extras is not None:
                item.extras.state = state(item)
        self.plain = True
        robot.extras = Preserved(root, *KNOWN['robot'])
        robot.extras.order = order
        robot.extras.outside = (list(root.itersiblings(preceding=True))[::-1],
                                list(root.itersiblings()))
        return robot

    def _attach(self, robot: Robot, block: Extension, joints: list[Joint]) -> None:
        reference = block.reference if block.tag == 'gazebo' else None
        if reference is not None and robot.has_link(reference):
            robot.get_link(reference).extensions.append(block)
            return
        owner = next((joint for joint in joints if joint.name == reference), None)
        if reference is not None and owner is not None:
            owner.extensions.append(block)
        else:
            robot.extensions.append(block)

    def _robot_element(self, root: Any) -> Any:
        if isinstance(root.tag, str) and root.tag.startswith('{'):
            namespace = root.tag[1:].split('}')[0]
            for node in root.iter():
                if isinstance(node.tag, str) and node.tag.startswith(f'{{{namespace}}}'):
                    node.tag = node.tag.split('}', 1)[1]
            self.warnings.append(ReadWarning(self.source.at(root), 'P104',
                                             f'default namespace {namespace!r} on <robot> '
                                             'ignored (URDF elements have no namespace)'))
        if root.tag == 'robot':
            return root
        inner = root.find('robot')
        if inner is None:
            raise self.fail(root, f'no <robot> element (the root is <{root.tag}>: a URDF '
                                  'starts with <robot name=...>)', 'P005')
        self.warnings.append(ReadWarning(self.source.at(root), 'P101',
                                         f'<robot> is wrapped in <{root.tag}>; read the '
                                         'inner <robot> (remove the wrapper: urdfdom '
                                         'refuses it)'))
        return inner


def _share_materials(robot: Robot) -> None:
    """Point plain references (``<material name="x"/>``) at the robot-level material."""
    for link in robot.links:
        for visual in link.visuals:
            material = visual.material
            if material is not None and material.is_reference and material.extras is None:
                visual.material = robot._materials.get(material.name, material)


def _attributes_in_written_order(node: Any, tag: str) -> bool:
    """Return whether every attribute is known and in the order the writer uses."""
    ranks = _ATTRIBUTE_ORDER[tag]
    last = -1
    for name in node.attrib:
        rank = ranks.get(name, -1)
        if rank <= last:
            return False
        last = rank
    return True


def _in_written_order(node: Any, tag: str, children: frozenset[str]) -> bool:
    """Return whether every child is known and in the order the writer uses."""
    ranks = _WRITTEN_ORDER.get(tag, {})
    last = -1
    for child in node:
        if not isinstance(child.tag, str) or child.tag not in children:
            return False
        rank = ranks.get(child.tag, last)
        if rank < last:
            return False
        last = rank
    return True


def _describe(node: Any) -> str:
    name = node.get('name') if node.tag in ('link', 'joint', 'material', 'robot') else None
    return f'<{node.tag} name="{name}">' if name else f'<{node.tag}>'


_JOINT_TYPES = frozenset(kind.value for kind in JointType)
_ATTRIBUTE_ORDER = {tag: {name: rank for rank, name in enumerate(names.split())}
                    for tag, names in (
                        ('origin', 'xyz rpy'), ('box', 'size'), ('cylinder', 'radius length'),
                        ('sphere', 'radius'), ('mesh', 'filename scale'), ('mass', 'value'),
                        ('inertia', ' '.join(INERTIA_ATTRS)), ('link', 'name'),
                        ('joint', 'name type'), ('visual', 'name'), ('collision', 'name'),
                        ('material', 'name'), ('color', 'rgba'), ('texture', 'filename'),
                        ('parent', 'link'), ('child', 'link'), ('axis', 'xyz'),
                        ('inertial', ''), ('geometry', ''),
                        ('limit', 'lower upper effort velocity'),
                        ('calibration', 'rising falling'), ('dynamics', 'damping friction'),
                        ('mimic', 'joint multiplier offset'),
                        ('safety_controller',
                         'soft_lower_limit soft_upper_limit k_position k_velocity'))}
_SHAPE_READERS: dict[str, Callable[..., Geometry]] = {
    'box': _Reader._box, 'cylinder': _Reader._cylinder, 'sphere': _Reader._sphere,
    'mesh': _Reader._mesh}
_JOINT_PARTS: dict[str, Callable[..., Any]] = {
    'limit': _Reader._limit, 'dynamics': _Reader._dynamics, 'mimic': _Reader._mimic,
    'safety_controller': _Reader._safety, 'calibration': _Reader._calibration}


def read_urdf_bytes(data: bytes, file: str | None = None) -> Robot:
    """
    Return the robot described by URDF ``data`` (``file`` names it in messages).

    :raises ParseError: when the text is not a readable URDF (one line, with location).
    """
    root, source, warnings = parse_xml(data, file)
    reader = _Reader(source, warnings)
    with checks.unchecked():
        robot = reader.robot(root)
    robot.read_warnings = warnings
    return robot


def read_urdf(path: str | PathLike[str]) -> Robot:
    """Return the robot described by the URDF file at ``path``."""
    file = Path(path)
    return read_urdf_bytes(file.read_bytes(), str(path))
