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
URDF writer, driven by the declarations of :mod:`.urdf_schema`.

A robot read from a file and not edited since is the file's text. An edited one is
written from the text too (:mod:`.urdf_splice`): every element nobody edited is copied as
it stands in the file; an edited one keeps its start tag, with only the values that
changed replaced in place, and its unedited children and the text between them.
Elements built in Python are written in the file's indentation and quotes.
"""

from __future__ import annotations

import codecs
from functools import partial
from itertools import chain
from os import PathLike
import re
from typing import Any, Callable, TYPE_CHECKING

from urdfgenpy_ros.formats._xml import fragment, robot_name, write_text, xml_bytes
from urdfgenpy_ros.formats.sdf import sensor_element
from urdfgenpy_ros.formats.urdf_edits import block_edited, is_as_read, owners_of_blocks
from urdfgenpy_ros.formats.urdf_element import ElementWriter
from urdfgenpy_ros.formats.urdf_fresh import write_new_robot
from urdfgenpy_ros.formats.urdf_schema import MATERIAL, OF_CLASS
from urdfgenpy_ros.formats.urdf_splice import in_quotes, prefixed, Splice
from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.extensions import Extension
from urdfgenpy_ros.model.joint import Joint
from urdfgenpy_ros.model.link import Link
from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.model.preserved import SourceDocument
from urdfgenpy_ros.model.urdf_versions import needed_version, version_text
from urdfgenpy_ros.model.value_kinds import wrong_kind

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

_DECLARATION = re.compile(r'\s*(<\?xml\b[^>]*\?>)')

# What writing a value of the wrong kind raises (a string for a number, say)
_UNWRITABLE = (TypeError, ValueError, AttributeError, KeyError)


def _sensor_block(sensor: Any, reference: str) -> Any:
    """Return the ``<gazebo reference=...>`` element that carries a sensor in URDF."""
    block = Extension('<gazebo/>')
    block.reference = reference
    block.element.append(sensor_element(sensor))
    return block.element


def _layout(document: SourceDocument | None) -> tuple[str, str, str]:
    """Return the file's line end, quote and indentation unit (a new file's if none)."""
    if document is None:
        return '\n', '"', '  '
    text = document.text
    known = document.memo.get('layout')  # (text, line end, quote): counted once per text
    if known is not None and known[0] is text:
        newline, quote = known[1], known[2]
    else:
        crlf = text.count('\r\n') if '\r' in text else 0  # the ends most lines have
        newline = '\r\n' if crlf and 2 * crlf > text.count('\n') else '\n'
        quote = "'" if "'" in text and text.count("='") > text.count('="') else '"'
        document.memo['layout'] = (text, newline, quote)
    space = document.node.text or ''
    unit = space.rsplit('\n', 1)[-1] if '\n' in space else ''
    return newline, quote, unit if unit and not unit.strip() else '  '


class UrdfWriter(ElementWriter):
    """Turn a Robot into URDF text; the Xacro writer overrides a few hooks."""

    declaration = '<?xml version="1.0"?>'

    def __init__(self, robot: RobotModel, *, mend: bool = True) -> None:
        document = robot.extras if isinstance(robot.extras, SourceDocument) else None
        self.mend = mend  # write a wrapped <robot> unwrapped, a malformed declaration mended
        self.document_record = document
        self.newline, quote, unit = _layout(document)
        self.bom = document is not None and document.bom
        super().__init__(robot, unit, {
            prefix or '': uri for prefix, uri in document.node.nsmap.items()
        } if document is not None else {}, quote)
        self._owners: dict[int, Link | Joint] | None = None
        self.materials = robot.materials
        self.extensions = robot.extensions

    def document(self) -> str:
        """
        Return the whole file, with the text a read file had around its root.

        :raises ModelError: naming the link or joint that holds a value set since that is
            not of its kind (``inertial.mass = 'abc'``), instead of the error deep inside.
        """
        if self.verbatim and self.document_record is not None and not self.prologue():
            text = as_read_text(self.robot, self.mend)
            if text is not None:
                return text
        return self.document_anew()

    def document_anew(self) -> str:
        """Return the whole file written from the model (a copy of the file's text not tried)."""
        document = self.document_record
        if document is None:
            return ''.join([self.declaration, '\n', self.write_robot(), '\n'])
        mend = self.mend
        splice = self.splice = Splice(document, self.newline, self.quote, self.declared)
        text = splice.text
        node = document.node
        span = splice.span(node)
        if span is not None and not mend:
            before, after = text[:span.start], text[span.end:]
        elif span is None or node.getparent() is not None:  # a wrapped <robot> is unwrapped
            match = _DECLARATION.match(text)
            before = (match.group(1) if match is not None and not document.mended
                      else self.declaration) + '\n'
            after = '\n'
        else:
            before, after = text[:span.start], text[span.end:].rstrip('\x00')
            if document.mended:  # the declaration the reader mended (P102)
                before = _DECLARATION.sub(self.declaration, before, count=1)
        written = ''.join([before, self.write_robot(), after])
        return written if self.newline == '\n' else written.replace('\n', self.newline)

    def checked(self, item: Any, write: Callable[[], str]) -> str:
        """
        Return ``write()``, the text of a top-level item, naming a value of a wrong kind.

        A value the user set that is not of its kind (``inertial.mass = 'abc'``) is one
        line naming the item and the value; any other error is a bug of ours and keeps
        its traceback.
        """
        try:
            return write()
        except _UNWRITABLE as error:
            found = wrong_kind(item) if isinstance(item, (Link, Joint, Material)) else None
            if found is None:
                raise
            kind = type(item).__name__.lower()
            raise ModelError(f'{kind} {item.name!r}: cannot be written, a value set in it '
                             f'is not of its kind: {found}: e.g. inertial.mass = 1.5, '
                             'joint.origin = Origin((0, 0, 0.1))') from error

    # ---- hooks ----------------------------------------------------------------------

    def robot_attrs(self) -> list[tuple[str, str]]:
        """Return the root element's attributes (name, text)."""
        robot = self.robot
        name = robot_name(robot.name)
        version = robot.urdf_version
        if version is None and robot.extras is None:  # built here: declare what it uses
            needed = needed_version(robot)
            version = None if needed == (1, 0) else version_text(needed)
        return [('name', name)] if version is None else [('name', name), ('version', version)]

    def prologue(self) -> list[str]:
        """Return top-level elements written before everything else."""
        return []

    # ---- the robot ------------------------------------------------------------------

    def write_robot(self) -> str:
        """Return the ``<robot>`` element, in the document order it was read in if any."""
        robot = self.robot
        document = self.document_record
        unit = self.unit
        fresh = '\n' + unit
        checked = self.checked
        if document is None:  # built in Python: no source order to keep, one pass
            return write_new_robot(self, _sensor_block)
        items = [(fresh, text) for text in self.prologue()]
        materials, links, joints = self.materials, robot.links, robot.joints
        written: set[int] = set()
        trailing = '\n'
        if document is not None:
            present = {id(item) for item in [*materials, *links, *joints,
                                             *self._all_extensions()]}
            # an item replaced by a copy of itself (a renamed material) keeps the place
            # of the source node it came from
            read: list[Material | Link | Joint] = [*materials, *links, *joints]
            by_node = {id(item.extras.node): item for item in read if item.extras is not None}
            whitespace = document.node.text or ''
            for item, node in zip(document.order, document.node):
                if id(item) not in present and isinstance(item, (Material, Link, Joint)):
                    item = by_node.get(id(node), item)
                if id(item) in present and id(item) not in written:
                    written.add(id(item))
                    items.append((whitespace, checked(item, partial(self.write_item, item, unit))))
                elif not isinstance(item, (Material, Link, Joint, Extension)):
                    items.append((whitespace, self.source_text(node)))
                whitespace = node.tail or ''
            trailing = whitespace if not whitespace.strip() else '\n'
        items += [(fresh, checked(item, partial(self.write_item, item, unit)))
                  for item in materials if id(item) not in written]
        items += [(fresh, checked(item, partial(self.object_text, item, unit)))
                  for item in links if id(item) not in written]
        owners: list[Link | Joint] = [*links, *joints]
        for owner in owners:  # most hold neither, and have no list made (lazy_lists)
            if owner.extensions_if_any:
                items += [(fresh, self.write_item(block, unit, owner))
                          for block in owner.extensions if id(block) not in written]
            if owner.sensors_if_any:
                items += [(fresh, self.write_extension(_sensor_block(sensor, owner.name), unit))
                          for sensor in owner.sensors]
        items += [(fresh, checked(item, partial(self.object_text, item, unit)))
                  for item in joints if id(item) not in written]
        items += [(fresh, self.write_item(block, unit)) for block in self.extensions
                  if id(block) not in written]
        name, attrs = self._opening()
        if not items:
            span = self.splice.span(document.node) if self.splice is not None and \
                document is not None else None
            if span is not None and self.splice is not None:
                return self.splice.empty(name, attrs, span)
            return f'<{name}{attrs}/>'
        return ''.join([f'<{name}{attrs}>', *chain.from_iterable(items), trailing,
                        f'</{name}>'])

    def _opening(self) -> tuple[str, str]:
        """Return the root's tag and attributes: as the file wrote them, with what changed."""
        attrs = self.robot_attrs()
        document = self.document_record
        splice = self.splice
        if document is None or splice is None:
            return 'robot', self.written(attrs)
        node = document.node
        robot = self.robot
        given = []
        for key, value in node.attrib.items():
            if key == 'name':
                given.append((key, robot.name))
            elif key == 'version':
                if robot.urdf_version is not None:
                    given.append((key, robot.urdf_version))
            else:
                given.append((prefixed(node, key), value))
        text = splice.attributes(node, given)
        added = [(key, value) for key, value in attrs if key not in node.attrib]
        if self.mend:
            for prefix, uri in node.nsmap.items():  # a wrapper's declarations come along
                if prefix:
                    added.append((f'xmlns:{prefix}', uri))
        text += splice.written([(key, value) for key, value in added
                                if f' {key}=' not in text and f'\n{key}=' not in text
                                and f'\t{key}=' not in text])
        span = splice.span(node)
        return ('robot' if span is None else span.name), text

    def _owners_of_blocks(self) -> list[Link | Joint]:
        return [*self.robot.links, *self.robot.joints]

    def _all_extensions(self) -> list[Extension]:
        blocks = list(self.extensions)
        for owner in self._owners_of_blocks():
            blocks.extend(owner.extensions_if_any or ())  # makes no empty list
        return blocks

    def write_item(self, item: object, pad: str, owner: Link | Joint | None = None) -> str:
        """Return a top-level element (link, joint, material or extension), unindented."""
        if isinstance(item, Link):
            return self.write_object(OF_CLASS[Link], item, pad)
        if isinstance(item, Joint):
            return self.write_object(OF_CLASS[Joint], item, pad)
        if isinstance(item, Material):
            return self.write_object(MATERIAL, item, pad)
        assert isinstance(item, Extension)
        if owner is None:
            owner = self._owner(item)
        element = item.element
        if owner is not None and (item.tag == 'gazebo' or isinstance(owner, Link)) \
                and item.reference != owner.name:
            element = item.with_reference(owner.name)
            element.tail = None
        elif self.splice is not None and self.document_record is not None and \
                not block_edited(self.document_record, item):
            return self.source_text(element, as_read=True)
        if item.source is not None:
            return self.source_text(element)
        return self.write_extension(element, pad)

    def write_extension(self, element: Any, pad: str) -> str:
        """Return an XML block built in Python, indented like the file."""
        return in_quotes(fragment(element, pad, self.declared, self.unit)[len(pad):],
                         self.quote)

    def _owner(self, block: Extension) -> Link | Joint | None:
        if self._owners is None:
            self._owners = owners_of_blocks(self.robot)
        return self._owners.get(id(block))

    def write_material(self, material: Material, pad: str) -> str:
        """Return a ``<material>`` definition or reference, indented by ``pad``."""
        return pad + self.write_object(MATERIAL, material, pad)


def urdf_file_bytes(robot: RobotModel, *, mend: bool = True) -> bytes:
    """
    Return the bytes of the URDF file of ``robot``: in its declared encoding, with its BOM.

    ``mend=False`` keeps what the reader mended as the file has it (a ``<robot>`` wrapped
    in another element, a malformed XML declaration): ``check --fix`` changes nothing
    but the repaired lines.
    """
    writer = UrdfWriter(robot, mend=mend)
    text = writer.document()
    data = xml_bytes(text)
    utf8 = data == text.encode('utf-8', 'surrogateescape')
    return codecs.BOM_UTF8 + data if writer.bom and utf8 else data


def as_read_text(robot: RobotModel, mend: bool = True) -> str | None:
    """
    Return the text of the file ``robot`` was read from if that is what writing it gives.

    That is while nothing was edited (:func:`.urdf_edits.is_as_read`) and, with ``mend``,
    the reader mended nothing around the root (a malformed declaration, a wrapper).
    """
    document = robot.extras
    if not isinstance(document, SourceDocument) or mend and (
            document.mended or document.node.getparent() is not None) \
            or not is_as_read(robot):
        return None
    return document.text.rstrip('\x00') if mend else document.text


def write_urdf(robot: RobotModel, path: str | PathLike[str] | None = None) -> str:
    """Return the URDF text of ``robot``; also write it to ``path`` when given."""
    text = as_read_text(robot)  # nothing edited: the file's text, no writer made
    if text is not None:
        bom = robot.extras is not None and robot.extras.bom
    else:
        writer = UrdfWriter(robot)
        text = writer.document_anew()
        bom = writer.bom
    if path is not None:
        write_text(path, text, bom=bom)
    return text
