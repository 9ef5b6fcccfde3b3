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
(:class:`~urdfgenpy_ros.preserved.Preserved`), so that writers can put back, in place,
whatever nobody edited and everything the model does not hold.
"""

from __future__ import annotations

from functools import partial
import re
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros import checks
from urdfgenpy_ros.errors import ParseError, ReadWarning, SourceLocation
from urdfgenpy_ros.extensions import Extension
from urdfgenpy_ros.formats._parse import parse_xml, PARSER, Source
from urdfgenpy_ros.formats.start_tags import (
    same_as_source, tag_end, unusual_start_tags)
from urdfgenpy_ros.formats.urdf_readers import READERS
from urdfgenpy_ros.formats.urdf_schema import GEOMETRY, record, unusable
from urdfgenpy_ros.geometry import quaternion_rpy
from urdfgenpy_ros.joint import Joint, JointType
from urdfgenpy_ros.link import Link
from urdfgenpy_ros.material import Material
from urdfgenpy_ros.model import robot_class
from urdfgenpy_ros.preserved import Details, DocumentPreserved, Layout

if TYPE_CHECKING:
    from urdfgenpy_ros.robot import Robot

EXTENSION_TAGS = frozenset(('gazebo', 'transmission', 'ros2_control'))
_TYPES = ', '.join(kind.value for kind in JointType)
_SHAPES = 'box, cylinder, sphere, capsule or mesh'
_SHAPE_TAGS = GEOMETRY.children[0].tags
_DECLARATION = re.compile(r'^\s*(<\?xml\b[^>]*\?>)')
_ENCODING = re.compile(rb'\s*<\?xml\b[^>]*?\bencoding\s*=\s*["\']([^"\']*)')


def _spaces_before(text: str, start: int, comments: int) -> list[str]:
    """
    Return the white space before each top-level node from ``start`` up to the root.

    ``comments`` comments or processing instructions come before the root; the list has
    one more entry, the white space before the root. [] if they are not where expected.
    """
    spaces, position = [], start
    for index in range(comments + 1):
        rest = text[position:position + 4096]
        space = rest[:len(rest) - len(rest.lstrip())]
        spaces.append(space.replace('\r\n', '\n'))
        position += len(space)
        if index == comments:
            break
        closing = '-->' if text.startswith('<!--', position) else \
            '?>' if text.startswith('<?', position) else None
        end = text.find(closing, position) if closing else -1
        if end < 0:
            return []
        position = end + len(closing or '')
    return spaces


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

    def robot(self, root: Any, cls: type[Robot]) -> Robot:
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
        robot.extras = DocumentPreserved(
            root, order, (list(root.itersiblings(preceding=True))[::-1],
                          list(root.itersiblings())),
            partial(_document_details, self.source.data,
                    any(warning.code == 'P102' for warning in self.warnings)))
        return robot

    @staticmethod
    def _attach(robot: Robot, block: Extension) -> None:
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


def _document_details(data: bytes, declaration_ignored: bool, root: Any) -> Details:
    """
    Return how the file of ``root`` is written, and what a writer keeps of its text.

    Worked out on the first write, not at read: reading need not pay for it. That is the
    layout; a function finding the start tags lxml would write otherwise; lxml's text
    of the tree now (None for a wrapped robot), which the first write would make again;
    and, when that text shows the tree is still as read, the file's own text of the root.
    """
    text = data.decode('utf-8', 'replace')
    bom = text.startswith('\ufeff')  # kept for the file, not in the text
    if bom:
        text = text[1:]
    top = root.getroottree().getroot()
    # a <robot> wrapped in another element takes no namespace from it, or its tag won't do
    head, start = _opening_tag(text, root) if top is root or not top.nsmap else (None, None)
    if top is not root:
        start = None  # the start tags are compared from the wrapper's
    layout = _layout(data, text, root, head, declaration_ignored)._replace(bom=bom)
    tags = partial(unusual_start_tags, top, text, layout.newline)
    if start is None:
        return layout, tags, None, None
    written = etree.tostring(top, encoding='unicode', with_tail=False)
    if same_as_source(written, text, start):
        return layout, None, written, None
    return layout, tags, written, _as_read(data, text, start, written, root, layout.newline)


def _as_read(data: bytes, text: str, start: int, written: str, root: Any,
             newline: str) -> tuple[str, str] | None:
    """
    Return ``written`` and the file's text of the root if the tree is as read, else None.

    lxml's text of the tree is compared with its text of the file parsed again: one parse
    in C, where finding each unusual start tag costs Python time per tag (files that
    write ``<x />`` have hundreds). The file's line ends (``newline``) are returned as
    line feeds, which the writer turns back.
    """
    body = text.rstrip()
    encoding = _ENCODING.match(data)
    if root.getnext() is not None or not body.endswith('>') or '\ufffd' in text or (
            encoding is not None and encoding.group(1).lower() not in (b'utf-8', b'utf8')):
        return None  # something after the root, or text that is not plainly UTF-8
    try:
        fresh = etree.fromstring(data, PARSER)
    except etree.XMLSyntaxError:
        return None  # the reader had to mend it
    if etree.tostring(fresh, encoding='unicode', with_tail=False) != written:
        return None
    source = body[start:]
    return written, source if newline == '\n' else source.replace(newline, '\n')


def _layout(data: bytes, text: str, root: Any, head: str | None,
            declaration_ignored: bool) -> Layout:
    """Return how the file is written: indentation, line ends, quotes, first lines."""
    ws = root.text or ''
    unit = ws.rsplit('\n', 1)[-1] if '\n' in ws else ''
    unit = unit if unit and not unit.strip() else '  '
    crlf = data.count(b'\r\n') if b'\r' in data else 0  # the ends most lines have
    newline = '\r\n' if 2 * crlf > data.count(b'\n') else '\n'
    quote = "'" if b"'" in data and data.count(b"='") > data.count(b'="') else '"'
    match = _DECLARATION.match(text, 0, 4096)
    if match is None and root.getparent() is None and text[:4096].lstrip().startswith('<'):
        declaration = ''  # the file has none: it gets none
    else:
        declaration = match.group(1) if match and not declaration_ignored \
            else '<?xml version="1.0"?>'
    body = text.rstrip()
    end = text[len(body):].replace('\r\n', '\n') if body.endswith('>') else '\n'
    gap = '\n' if declaration else ''
    between: tuple[str, ...] = ()
    # the white space around a declaration the writer mends (P102) stays as well
    start = match.end(1) if match is not None else 0 if not declaration else None
    if start is not None:
        spaces = _spaces_before(text, start, len(list(root.itersiblings(preceding=True))))
        if spaces:
            gap, between = spaces[0], tuple(spaces[1:])
    return Layout(unit, newline, quote, declaration, head, end, gap, between)


def _opening_tag(text: str, root: Any) -> tuple[str | None, int | None]:
    """
    Return the root's opening tag exactly as the file wrote it and where, if found.

    lxml's ``sourceline`` is the line a start tag ends on: look back from its end.
    """
    if root.sourceline is None:
        return None, None
    end = -1
    for _ in range(root.sourceline):
        end = text.find('\n', end + 1)
        if end < 0:
            end = len(text)
            break
    start = text.rfind('<robot', 0, end)
    if start < 0:
        return None, None
    head = text[start:tag_end(text, start)]
    return (None if head.endswith('/>') else head.replace('\r\n', '\n')), start


def _share_materials(robot: Robot) -> list[Link]:
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


def read_urdf_bytes(data: bytes, file: str | None = None, cls: type[Robot] | None = None
                    ) -> Robot:
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
