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
URDF reader: the model of a file, following the declarations of :mod:`.urdf_schema`.

Every element read keeps its source node and a by-value snapshot of the fields it gave
(:class:`~urdfgenpy_ros.model.preserved.Preserved`), and the robot the file's text
(:class:`~urdfgenpy_ros.model.preserved.SourceDocument`), so that writers can copy whatever
nobody edited and keep everything the model does not hold.
"""

from __future__ import annotations

import codecs
import re
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.formats._parse import parse_xml, Source
from urdfgenpy_ros.formats.urdf_comments import read_directives
from urdfgenpy_ros.formats.urdf_readers import READERS
from urdfgenpy_ros.formats.urdf_schema import GEOMETRY, record, unusable
from urdfgenpy_ros.model import checks
from urdfgenpy_ros.model import robot_class
from urdfgenpy_ros.model.errors import ParseError, ReadWarning, SourceLocation
from urdfgenpy_ros.model.extensions import Extension
from urdfgenpy_ros.model.geometry import quaternion_rpy
from urdfgenpy_ros.model.joint import Joint, JointType
from urdfgenpy_ros.model.link import Link
from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.model.preserved import SourceDocument

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

EXTENSION_TAGS = frozenset(('gazebo', 'transmission', 'ros2_control'))
_TYPES = ', '.join(kind.value for kind in JointType)
_SHAPES = 'box, cylinder, sphere, capsule or mesh'
_SHAPE_TAGS = GEOMETRY.children[0].tags
_ENCODING = re.compile(rb'\s*<\?xml\b[^>]*?\bencoding\s*=\s*["\']([^"\']*)')


class _Reader:
    """Read one document into the model."""

    def __init__(self, source: Source, warnings: list[ReadWarning]) -> None:
        self.source = source
        self.file = source.file
        self.warnings = warnings
        self.materials: dict[str, Material] = {}  # robot-level materials read so far
        self.unresolved = False  # a visual refers to a material not (yet) defined
        self.vectors: dict[str, tuple[float, ...]] = {}  # vectors read, by their text

    def fail(self, node: Any, message: str, code: str = 'P002',
             attribute: str | None = None) -> ParseError:
        """Return a ParseError at ``node`` (or at one of its attributes)."""
        return ParseError(message, self.source.at(node, attribute), code)

    def where(self, node: Any) -> SourceLocation:
        """Return the location of ``node`` (file and line)."""
        return SourceLocation(self.file, node.sourceline)

    # ---- what the compiled readers (formats/urdf_readers.py) call -----------------

    def missing(self, node: Any, name: str, expected: str) -> ParseError:
        """Return the error of a required attribute the file leaves out."""
        return self.fail(node, f'{_describe(node)}: missing {name!r} ({expected})')

    def not_number(self, node: Any, name: str, text: str) -> ParseError:
        """Return the error of a number attribute that does not read as one."""
        return self.fail(node, f'{_describe(node)}: {name} {text!r} is not a number (write '
                               'e.g. 0.5 or 1e-3)', 'P003', name)

    def vector(self, node: Any, name: str, text: str, count: int) -> tuple[float, ...]:
        """Return the ``count`` numbers of a vector attribute (kept: texts repeat)."""
        parts = text.split()
        try:
            values = tuple(map(float, parts))
        except ValueError:
            values = ()
        if len(values) != count:
            raise self.fail(node, f'{_describe(node)}: {name} {text!r} must be {count} '
                                  'numbers separated by spaces', 'P003', name)
        self.vectors[text] = values
        return values

    def quaternion(self, node: Any, quat: tuple[float, ...]) -> tuple[float, float, float]:
        """Return the rpy of an origin's ``quat_xyzw``; refuse rpy given beside it."""
        if node.get('rpy') is not None:
            raise self.fail(node, '<origin> has both rpy and quat_xyzw (urdfdom 6 refuses '
                                  'it): keep one of them', 'P009', 'quat_xyzw')
        return quaternion_rpy(quat)

    def bad_type(self, node: Any, name: str, kind: str) -> ParseError:
        """Return the error of an unknown joint type."""
        return self.fail(node, f'joint {name!r}: unknown type {kind!r} (use one of '
                               f'{_TYPES})', 'P004', 'type')

    def ignored(self, tag: str, node: Any, child: Any) -> None:
        """Warn about a child urdfdom drops: it is kept as written."""
        name = node.get('name')
        owner = f'{tag} {name!r}' if name else f'<{tag}>'
        self.warnings.append(ReadWarning(
            self.source.at(child), 'P106' if child.tag == 'inertial' else 'P107',
            f'{owner}: ignored, as urdfdom does: {unusable(tag, child)}'))

    def shape(self, node: Any) -> Any:
        """Return the shape of a ``<geometry>``: its first element, which must be one."""
        for child in node:
            if isinstance(child.tag, str):
                if child.tag not in _SHAPE_TAGS:
                    raise self.fail(child, f'unknown geometry <{child.tag}> (URDF has '
                                           f'{_SHAPES})', 'P006')
                return child
        raise self.fail(node, f'<geometry> has no shape (use {_SHAPES})', 'P006')

    def shared(self, material: Material, node: Any) -> Material:
        """
        Return the robot-level material a plain reference (``<material name="x"/>``) names.

        A reference to a material defined further down is resolved when the robot is
        read (:func:`_share_materials`).
        """
        if len(node.attrib) != 1 or len(node):
            return material
        defined = self.materials.get(material.name)
        if defined is None:
            self.unresolved = True
            return material
        return defined

    # ---- the robot ----------------------------------------------------------------

    def robot(self, root: Any, cls: type[RobotModel]) -> RobotModel:
        """Read the ``<robot>`` element and everything in it."""
        root = self._robot_element(root)
        name = root.get('name')
        if not name:
            raise self.fail(root, "<robot>: missing 'name' (give the robot a name)")
        robot = cls(name)
        robot.source = self.where(root)
        robot.urdf_version = root.get('version')
        order: list[Any] = []
        joints: list[Joint] = []
        blocks: list[Extension] = []
        seen: dict[tuple[str, str], int] = {}
        for node in root:
            tag = node.tag
            if tag in ('link', 'joint', 'material'):
                item = READERS[tag](self, node)
                key = (tag, item.name)
                if key in seen:  # on another line, or on the same one (a one-line file)
                    raise self.fail(node, f'{tag} {item.name!r} is defined twice (first at '
                                          f'line {seen[key]}): rename or remove one', 'P007',
                                    'name')
                seen[key] = node.sourceline
                if tag == 'link':
                    robot.add_link(item)
                elif tag == 'joint':
                    joints.append(item)
                else:
                    robot.add_material(item)
                    self.materials[item.name] = item
                order.append(item)
            elif tag in EXTENSION_TAGS:
                block = Extension(node, self.where(node))
                order.append(block)
                blocks.append(block)
            else:
                order.append(node)
        for joint in joints:
            robot.add_joint(joint)
        for block in blocks:  # once every link is read: a block may come before its link
            self._attach(robot, block)
        if self.unresolved:
            for link in _share_materials(robot):
                record(link)
        text, bom = source_text(self.source.data)
        robot.extras = SourceDocument(
            root, order, text, bom=bom,
            mended=any(warning.code == 'P102' for warning in self.warnings),
            blocks={block.element: etree.tostring(block.element, with_tail=False)
                    for block in blocks}, directives=read_directives(root, text))
        return robot

    @staticmethod
    def _attach(robot: RobotModel, block: Extension) -> None:
        """Give a block to the link or joint its ``reference`` names, else to the robot."""
        reference = block.reference if block.tag == 'gazebo' else None
        if reference is not None and robot.has_link(reference):
            robot.get_link(reference).extensions.append(block)
        elif reference is not None and robot.has_joint(reference):
            robot.get_joint(reference).extensions.append(block)
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


def source_text(data: bytes) -> tuple[str, bool]:
    """
    Return the text of a file's ``data`` in the encoding it declares, and whether a BOM began it.

    The writer copies what nobody edited from this text, so it must be the file's own.
    """
    bom = data.startswith(codecs.BOM_UTF8)
    if bom:
        data = data[len(codecs.BOM_UTF8):]
    match = _ENCODING.match(data, 0, 4096)
    codec = 'utf-8'
    if match is not None:
        try:
            codec = codecs.lookup(match.group(1).decode('ascii', 'replace')).name
        except LookupError:
            pass
    try:
        return data.decode(codec), bom
    except (UnicodeDecodeError, LookupError):
        return data.decode('utf-8', 'replace'), bom


def _share_materials(robot: RobotModel) -> list[Link]:
    """Point plain references (``<material name="x"/>``) at the robot-level material."""
    changed: list[Link] = []
    for link in robot.links:
        for visual in link.visuals:
            material = visual.material
            if (material is not None and material.is_reference
                    and robot.has_material(material.name)
                    and material is not robot.get_material(material.name)):
                node = material.extras.node if material.extras is not None else None
                if node is None or (len(node.attrib) == 1 and not len(node)):
                    visual.material = robot.get_material(material.name)
                    if not changed or changed[-1] is not link:
                        changed.append(link)
    return changed


def _describe(node: Any) -> str:
    name = node.get('name') if node.tag in ('link', 'joint', 'material', 'robot') else None
    return f'<{node.tag} name="{name}">' if name else f'<{node.tag}>'


def read_urdf_bytes(data: bytes, file: str | None = None, cls: type[RobotModel] | None = None
                    ) -> RobotModel:
    """
    Return the robot described by URDF ``data`` (``file`` names it in messages).

    The robot is a ``cls`` (default: :func:`urdfgenpy_ros.model.robot_class`, ``Robot``).

    :raises ParseError: when the text is not a readable URDF (one line, with location).
    """
    root, source, warnings = parse_xml(data, file)
    reader = _Reader(source, warnings)
    with checks.unchecked():
        robot = reader.robot(root, cls or robot_class())
    robot.read_warnings = warnings
    return robot
