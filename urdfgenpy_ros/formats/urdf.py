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

An element read from a file whose fields still equal its snapshot is written as it was
read. An edited one is written from its declaration in the layout of its source: the
whitespace around its children, its attribute order, unknown attributes and children,
comments, and the original text of every value that did not change all stay, so one edit
is one changed line. Elements built in Python are written in the file's indentation.
"""

from __future__ import annotations

from itertools import chain
from os import PathLike
import re
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.errors import ModelError, UrdfgenpyError
from urdfgenpy_ros.extensions import Extension
from urdfgenpy_ros.formats._xml import esc, fragment, write_text
from urdfgenpy_ros.formats.sdf import sensor_element
from urdfgenpy_ros.formats.start_tags import as_source, tag_end
from urdfgenpy_ros.formats.urdf_element import ElementWriter, prefixed
from urdfgenpy_ros.formats.urdf_schema import MATERIAL, OF_CLASS, values
from urdfgenpy_ros.joint import Joint
from urdfgenpy_ros.link import Link
from urdfgenpy_ros.material import Material
from urdfgenpy_ros.preserved import Layout
from urdfgenpy_ros.urdf_versions import needed_version, version_text
from urdfgenpy_ros.value_kinds import wrong_kind

if TYPE_CHECKING:
    from urdfgenpy_ros.robot import Robot

_ROBOT_NAME = re.compile(r'(\sname\s*=\s*)(["\'])(.*?)\2', re.DOTALL)
_ROBOT_VERSION = re.compile(r'(\sversion\s*=\s*)(["\'])(.*?)\2', re.DOTALL)


def _single_quotes(text: str) -> str:
    """Write attributes with single quotes, as a file that used them did."""
    def tag(match: Any) -> str:
        return re.sub(r'="([^"\']*)"', r"='\1'", match.group(0))
    return re.sub(r'<[^<>!?][^<>]*>', tag, text)


def _sensor_block(sensor: Any, reference: str) -> Any:
    """Return the ``<gazebo reference=...>`` element that carries a sensor in URDF."""
    block = Extension('<gazebo/>')
    block.reference = reference
    block.element.append(sensor_element(sensor))
    return block.element


# What writing a value of the wrong kind raises (a string for a number, say)
_UNWRITABLE = (TypeError, ValueError, AttributeError, KeyError)


class UrdfWriter(ElementWriter):
    """Turn a Robot into URDF text; the Xacro writer overrides a few hooks."""

    declaration = '<?xml version="1.0"?>'

    def __init__(self, robot: Robot) -> None:
        extras = robot.extras
        # and lxml's text of the tree, if working out the layout just made it
        self.layout, self._written = extras.writing() if extras is not None else (Layout(), None)
        super().__init__(robot, self.layout.unit, {
            prefix or '': uri for prefix, uri in extras.node.nsmap.items()
        } if extras is not None else {})
        self._owners: dict[int, Link | Joint] | None = None
        self.materials = robot.materials
        self.extensions = robot.extensions

    def document(self) -> str:
        """
        Return the whole file, with the comments a read file had around its root.

        :raises ModelError: naming the link or joint that holds a value set since that is
            not of its kind (``inertial.mass = 'abc'``), instead of the error deep inside.
        """
        try:
            return self._document()
        except UrdfgenpyError:
            raise  # already the model's own one-line error
        except _UNWRITABLE as error:
            raise self._unwritable(error) from error

    def _unwritable(self, error: Exception) -> ModelError:
        """
        Return the one-line error naming a value set on the model that is not of its kind.

        When every value is of its kind, the error is a bug of ours: it is raised again,
        with its traceback.
        """
        robot = self.robot
        items: list[Link | Joint] = [*robot.links, *robot.joints]
        for item in items:
            found = wrong_kind(item)
            if found is not None:
                kind = 'link' if isinstance(item, Link) else 'joint'
                return ModelError(f'{kind} {item.name!r}: cannot be written, a value set in it '
                                  f'is not of its kind: {found}: e.g. inertial.mass = 1.5, '
                                  'joint.origin = Origin((0, 0, 0.1))')
        raise error

    def _document(self) -> str:
        extras = self.robot.extras
        layout = self.layout
        before: list[str] = []
        after: list[str] = []
        declaration = self.declaration
        if extras is not None:
            declaration = layout.declaration
            before, after = ([self.source_text(node) for node in nodes]
                             for nodes in extras.outside)
        spaces = layout.between if len(layout.between) == len(before) else ['\n'] * len(before)
        # One join: the robot's text is most of the file, and each '+' would copy it again.
        parts = [declaration, layout.gap]  # no declaration: the white space the file began with
        for node, space in zip(before, spaces):
            parts += [node, space]
        parts.append(self.write_robot())
        for node in after:
            parts += ['\n', node]
        parts.append(layout.end)
        text = ''.join(parts)
        if layout.quote == "'":
            text = _single_quotes(text)
        if layout.newline != '\n':
            text = text.replace('\n', layout.newline)
        return text

    # ---- hooks ----------------------------------------------------------------------

    def robot_attrs(self) -> list[tuple[str, str]]:
        """Return the root element's attributes (name, text)."""
        robot = self.robot
        version = robot.urdf_version
        if version is None and robot.extras is None:  # built here: declare what it uses
            needed = needed_version(robot)
            version = None if needed == (1, 0) else version_text(needed)
        return [('name', robot.name)] if version is None else \
            [('name', robot.name), ('version', version)]

    def prologue(self) -> list[str]:
        """Return top-level elements written before everything else."""
        return []

    # ---- the robot ------------------------------------------------------------------

    def write_robot(self) -> str:
        """Return the ``<robot>`` element, in the document order it was read in if any."""
        robot = self.robot
        extras = robot.extras
        unit = self.unit
        fresh = '\n' + unit
        if extras is not None and self._untouched():
            head = extras.layout.head
            assert head is not None
            serialized = self._written or etree.tostring(extras.node, encoding='unicode',
                                                         with_tail=False)
            text = as_source(serialized, extras.node, extras)
            return head + text[tag_end(text, 0):] if len(extras.node) else head[:-1] + '/>'
        items = [(fresh, text) for text in self.prologue()]
        materials, links, joints = self.materials, robot.links, robot.joints
        written: set[int] = set()
        trailing = '\n'
        if extras is not None and extras.order is not None:
            present = {id(item) for item in [*materials, *links, *joints,
                                             *self._all_extensions()]}
            # an item replaced by a copy of itself (a renamed material) keeps the place
            # of the source node it came from
            read: list[Material | Link | Joint] = [*materials, *links, *joints]
            by_node = {id(item.extras.node): item for item in read if item.extras is not None}
            whitespace = extras.node.text or ''
            for item, node in zip(extras.order, extras.node):
                if id(item) not in present and isinstance(item, (Material, Link, Joint)):
                    item = by_node.get(id(node), item)
                if id(item) in present and id(item) not in written:
                    written.add(id(item))
                    items.append((whitespace, self.write_item(item, unit)))
                elif not isinstance(item, (Material, Link, Joint, Extension)):
                    items.append((whitespace, self.source_text(node)))
                whitespace = node.tail or ''
            trailing = whitespace if not whitespace.strip() else '\n'
        items += [(fresh, self.write_item(item, unit)) for item in materials
                  if id(item) not in written]
        items += [(fresh, self.object_text(item, unit)) for item in links
                  if id(item) not in written]
        owners: list[Link | Joint] = [*links, *joints]
        for owner in owners:
            items += [(fresh, self.write_item(block, unit, owner)) for block in owner.extensions
                      if id(block) not in written]
            items += [(fresh, self.write_extension(_sensor_block(sensor, owner.name), unit))
                      for sensor in owner.sensors]
        items += [(fresh, self.object_text(item, unit)) for item in joints
                  if id(item) not in written]
        items += [(fresh, self.write_item(block, unit)) for block in self.extensions
                  if id(block) not in written]
        opening = self._opening()
        if not items:
            return opening[:-1] + '/>'
        return ''.join([opening, *chain.from_iterable(items), trailing, '</robot>'])

    def _untouched(self) -> bool:
        """Return whether the robot holds exactly what was read: write the tree as it is."""
        robot = self.robot
        extras = robot.extras
        if extras is None or extras.order is None or extras.layout.head is None \
                or not self.verbatim or extras.node.get('name') != robot.name \
                or extras.node.get('version') != robot.urdf_version:
            return False
        blocks = self._all_extensions()
        items = [*self.materials, *robot.links, *robot.joints, *blocks]
        read = [item for item in extras.order if isinstance(item, (Material, Link, Joint,
                                                                   Extension))]
        if len(items) != len(read) or {id(item) for item in items} != {id(i) for i in read}:
            return False
        for item in read:
            if isinstance(item, Extension):
                if item.element.getparent() is not extras.node:  # a copy: write it itself
                    return False
                owner = self._owner(item)
                if owner is not None and item.tag == 'gazebo' and item.reference != owner.name:
                    return False
            elif item.extras is None or values(item) != item.extras.snapshot:
                return False
        if any(owner.sensors for owner in self._owners_of_blocks()):
            return False
        head = extras.layout.head
        return all(f'{key}=' in head for key, _ in self.robot_attrs()) and not self.prologue()

    def _opening(self) -> str:
        """Return the ``<robot ...>`` tag: as the file wrote it, with what changed."""
        extras = self.robot.extras
        attrs = self.robot_attrs()
        head = extras.layout.head if extras is not None else None
        if head is not None:
            name = self.robot.name
            if extras is not None and extras.node.get('name') != name:
                head = _ROBOT_NAME.sub(lambda m: f'{m.group(1)}{m.group(2)}{esc(name)}'
                                       f'{m.group(2)}', head, count=1)
            version = self.robot.urdf_version
            if extras is not None and version is not None and \
                    extras.node.get('version') not in (None, version):
                head = _ROBOT_VERSION.sub(lambda m: f'{m.group(1)}{m.group(2)}{esc(version)}'
                                          f'{m.group(2)}', head, count=1)
            for key, text in attrs:
                if f'{key}=' not in head:
                    head = f'{head[:-1]} {key}="{esc(text)}">'
            return head
        parts = ['<robot']
        parts += [f' {key}="{esc(text)}"' for key, text in attrs]
        taken = {key for key, _ in attrs}
        if extras is not None:
            node = extras.node
            parts += [f' {prefixed(node, key)}="{esc(text)}"' for key, text in
                      node.attrib.items() if key not in taken]
            for prefix, uri in node.nsmap.items():
                key = f'xmlns:{prefix}' if prefix else 'xmlns'
                if prefix and key not in taken:
                    parts.append(f' {key}="{esc(uri)}"')
        return ''.join(parts) + '>'

    def _owners_of_blocks(self) -> list[Link | Joint]:
        return [*self.robot.links, *self.robot.joints]

    def _all_extensions(self) -> list[Extension]:
        blocks = list(self.extensions)
        for owner in self._owners_of_blocks():
            blocks.extend(owner.extensions)
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
        if item.source is not None:
            return self.source_text(element)
        return self.write_extension(element, pad)

    def write_extension(self, element: Any, pad: str) -> str:
        """Return an XML block built in Python, indented like the file."""
        return fragment(element, pad, self.declared, self.unit)[len(pad):]

    def _owner(self, block: Extension) -> Link | Joint | None:
        if self._owners is None:
            self._owners = {id(candidate): owner for owner in self._owners_of_blocks()
                            for candidate in owner.extensions}
        return self._owners.get(id(block))

    def write_material(self, material: Material, pad: str) -> str:
        """Return a ``<material>`` definition or reference, indented by ``pad``."""
        return pad + self.write_object(MATERIAL, material, pad)


def write_urdf(robot: Robot, path: str | PathLike[str] | None = None) -> str:
    """Return the URDF text of ``robot``; also write it to ``path`` when given."""
    writer = UrdfWriter(robot)
    text = writer.document()
    if path is not None:
        write_text(path, text, bom=writer.layout.bom)
    return text
