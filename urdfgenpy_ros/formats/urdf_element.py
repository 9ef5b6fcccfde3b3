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
Write one URDF element from its declaration, in the layout of the node it was read from.

An object whose fields still equal its snapshot is its source text, copied. An edited one
is written anew around its source: its start tag with only the changed values replaced
in place, the whitespace between its children, unknown attributes and children, comments
and the original text of every value that did not change all stay. Objects built in
Python go through the compiled writers of :mod:`.urdf_fresh`, in the file's indentation.
"""

from __future__ import annotations

from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.formats._xml import esc, without_declared
from urdfgenpy_ros.formats.urdf_edits import is_edited
from urdfgenpy_ros.formats.urdf_fresh import FRESH
from urdfgenpy_ros.formats.urdf_schema import (
    Attr, Child, Element, ELEMENTS, FLOAT, INERTIAL, LENGTHS, MATERIAL, OF_CLASS, REQUIRED,
    slot_of, SLOTS, TEXT)
from urdfgenpy_ros.formats.urdf_splice import in_quotes, prefixed, Splice
from urdfgenpy_ros.model.floats import fmt, fmt_vec
from urdfgenpy_ros.model.geometry import (Box, Capsule, Cylinder, Mesh, Origin, quaternion_rpy,
                                          Sphere)
from urdfgenpy_ros.model.material import Material

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.model.inertial import Inertial
    from urdfgenpy_ros.model.link import Link

_LEAVES = frozenset((Origin, Box, Cylinder, Sphere, Capsule, Mesh))
_ATTRS = {tag: {attr.name: attr for attr in element.attrs} for tag, element in ELEMENTS.items()}


def _not_left_out(attr: Attr, value: Any) -> None:
    """Raise when a value a file must give is None (``inertial.mass = None``)."""
    if value is None and attr.default is REQUIRED and not attr.unless:
        raise TypeError(f'{attr.field} is None, and <{attr.name}> is required')


def _reads_as(kind: str, text: str, value: Any) -> bool:
    """Return whether the original attribute ``text`` still denotes ``value``."""
    if kind == TEXT:
        return text == str(value)
    try:
        if kind == FLOAT:
            return float(text) == value
        return tuple([float(part) for part in text.split()]) == tuple(value)
    except (TypeError, ValueError):
        return False


class ElementWriter:
    """Write model objects as URDF elements; :class:`~.urdf.UrdfWriter` adds the robot."""

    verbatim = True  # write unedited elements read from a file exactly as they were

    def __init__(self, robot: RobotModel, unit: str, declared: dict[str, str],
                 quote: str = '"') -> None:
        self.robot = robot
        self.unit = unit
        self.quote = quote  # the file's: attributes written anew take it
        self.declared = declared  # namespaces the root declares: not repeated inside
        self.splice: Splice | None = None  # the source text, when a write needs it
        self._numbers: dict[Any, str] = {}  # the text of numbers and vectors written
        self._leaves: dict[Any, str] = {}  # the text of origins and shapes, by value
        self.known_number = self._numbers.get

    def text(self, kind: str, value: Any) -> str:
        """Return the URDF text of a value: exact, shortest numbers."""
        if kind == TEXT:
            return str(value)
        if kind == FLOAT:
            return self.number(value)
        if len(value) != LENGTHS[kind]:  # axis = (0, 1): the user's, named by wrong_kind
            raise ValueError(f'{len(value)} numbers for a {kind}')
        return self.vector(value)

    def number(self, value: float) -> str:
        """Return the exact text of a float (cached: numbers repeat a lot)."""
        text = self._numbers.get(value)
        if text is None:
            text = self._numbers[value] = fmt(value)
        return text

    def vector(self, value: tuple[float, ...]) -> str:
        """Return the exact text of a vector, numbers separated by spaces."""
        text = self._numbers.get(value)
        if text is None:
            text = fmt_vec(value)
            if type(value) is tuple:
                self._numbers[value] = text
        return text

    def write_inertial(self, inertial: Inertial, pad: str | None, link: Link,
                       slot: Any = None) -> str:
        """Return the ``<inertial>`` element of ``link``."""
        if inertial.extras is None and slot is None and pad is not None and self.quote == '"':
            return FRESH[type(inertial)](self, inertial, pad)  # what write_object does then
        return self.write_object(INERTIAL, inertial, pad, slot)

    def source_text(self, node: Any, as_read: bool = False) -> str:
        """
        Return a node as the file wrote it, edits in place (see :class:`.urdf_splice.Splice`).

        ``as_read``: its snapshot says nobody edited it. A node the file did not have is
        written by lxml (namespaces the root declares aside).
        """
        if self.splice is not None:
            return self.splice.node_text(node, as_read)
        text = etree.tostring(node, encoding='unicode', with_tail=False)
        return in_quotes(without_declared(text, self.declared), self.quote)

    def written(self, given: list[tuple[str, str]]) -> str:
        """Return attributes (name, value) written anew, in the file's quotes."""
        if self.splice is not None:
            return self.splice.written(given)
        return in_quotes(''.join(f' {name}="{esc(value)}"' for name, value in given),
                         self.quote)

    # ---- any element, from its declaration -------------------------------------------

    def write_object(self, element: Element, item: Any, pad: str | None,
                     slot: Any = None) -> str:
        """
        Return the element of a model object, unindented; ``pad`` is its line's indent.

        ``slot`` is the source node at the place it is written, whose layout a new
        object of the same tag takes over.
        """
        extras = item.extras
        if extras is not None:
            if self.verbatim and not is_edited(item):
                return self.source_text(extras.node, as_read=True)
            node = extras.node
        elif slot is None or slot.tag != element.tag:
            if pad is not None:
                return in_quotes(FRESH[type(item)](self, item, pad), self.quote)
            node = None
        else:
            node = slot
        return self.write(element, item, node, pad)

    def object_text(self, item: Any, pad: str) -> str:
        """Return the element of a model object written where no source node stood."""
        if item.extras is not None:
            return self.write_object(OF_CLASS[type(item)], item, pad)
        kind = type(item)
        if kind in _LEAVES:  # frozen one-line elements: the same value, the same text
            text = self._leaves.get(item)
            if text is None:
                text = self._leaves[item] = in_quotes(FRESH[kind](self, item, pad), self.quote)
            return text
        text = FRESH[kind](self, item, pad)
        return text if self.quote == '"' else in_quotes(text, self.quote)  # a call less

    def write(self, element: Element, item: Any, node: Any, pad: str | None) -> str:
        """Return ``element`` with the fields of ``item``, laid out like ``node`` if any."""
        tag = element.tag
        if tag == 'origin':
            item = self.origin_form(item, node)
        attrs = self._attributes(element, item, node)
        if not element.children:
            if node is None or not len(node):
                return self._empty(tag, attrs, node)
            return self._merge(element, attrs, [], node, pad, pad)
        inner = self._inner(node, pad)
        children = self._children(element, item, node, inner)
        if node is None:
            texts = [text for _, group in children for text in group]
            if not texts:
                return f'<{tag}{attrs}/>'
            if pad is None or inner is None:
                return f'<{tag}{attrs}>{"".join(texts)}</{tag}>'
            space = '\n' + inner
            return f'<{tag}{attrs}>{"".join(space + text for text in texts)}\n{pad}</{tag}>'
        return self._merge(element, attrs, children, node, pad, inner)

    def origin_form(self, origin: Origin, node: Any) -> Origin:
        """
        Return ``origin`` with its rotation in the form its element was read in.

        An origin read as a quaternion stays one (its own quaternion, as written, while
        the rotation is the same), one read as rpy stays rpy; a new one keeps its form.
        """
        if node is None:
            return origin
        written = node.get('quat_xyzw')
        if written is not None and origin.quat_xyzw is None:
            try:
                quat = tuple(float(part) for part in written.split())
                if len(quat) == 4 and quaternion_rpy(quat) == origin.rpy:
                    return Origin(origin.xyz, quat_xyzw=quat)
            except ValueError:
                pass
            return origin.as_quaternion()
        if written is None and origin.quat_xyzw is not None and 'rpy' in node.attrib:
            return origin.as_rpy()
        return origin

    def _empty(self, tag: str, attrs: str, node: Any) -> str:
        """Return an element without content: ``<x/>``, or ``<x></x>``, ``<x />`` as written."""
        splice = self.splice
        if splice is not None and node is not None:
            return splice.empty(tag, attrs, splice.span(node))
        return f'<{tag}{attrs}/>'

    def _inner(self, node: Any, pad: str | None) -> str | None:
        """Return the indentation of children (None: written on one line)."""
        if node is not None and len(node):
            space = node.text or ''
            return space.rsplit('\n', 1)[1] if '\n' in space else None
        return None if pad is None else pad + self.unit

    def _attributes(self, element: Element, item: Any, node: Any) -> str:
        """Return the attributes of ``item``: in ``node``'s start tag as written, if any."""
        given = []
        if node is None:
            for attr in element.attrs:
                value = getattr(item, attr.field)
                if value is None or (value == '' and attr.default == '') or (
                        attr.unless and getattr(item, attr.unless) is not None):
                    _not_left_out(attr, value)
                    continue
                given.append((attr.name, self.text(attr.kind, value)))
            return self.written(given)
        declared = _ATTRS[element.tag]
        done = set()
        for name, original in node.attrib.items():
            known = declared.get(name)
            if known is None:
                given.append((prefixed(node, name), original))
                continue
            done.add(name)
            value = getattr(item, known.field)
            if value is None or (known.unless and getattr(item, known.unless) is not None):
                _not_left_out(known, value)
                continue
            if not _reads_as(known.kind, original, value):
                original = self.text(known.kind, value)
            given.append((name, original))
        for attr in element.attrs:
            if attr.name in done:
                continue
            value = getattr(item, attr.field)
            if value is None or (attr.default is not REQUIRED and value == attr.default) or (
                    attr.unless and getattr(item, attr.unless) is not None):
                _not_left_out(attr, value)
                continue
            given.append((attr.name, self.text(attr.kind, value)))
        if self.splice is not None:
            return self.splice.attributes(node, given)
        return self.written(given)

    def _children(self, element: Element, item: Any, node: Any,
                  pad: str | None) -> list[tuple[Child, list[str]]]:
        """Return the text of every known child, grouped by declaration, in order."""
        result = []
        slots = _first_slots(element, node) if node is not None else {}
        for child in element.children:
            if child.many:
                parts = getattr(item, str(child.field))
                result.append((child, [self.write_object(OF_CLASS[type(part)], part, pad)
                                       for part in parts]))
                continue
            slot = slots.get(child)
            if child.field is None:
                inline = ELEMENTS[child.tags[0]]
                if child.optional and all(getattr(item, attr.field) is None
                                          for attr in inline.attrs):
                    result.append((child, []))
                else:
                    result.append((child, [self.write(inline, item, slot, pad)]))
                continue
            part = getattr(item, child.field)
            if part is None or (child.field == 'origin' and slot is None
                                and part.extras is None and part.is_identity):
                result.append((child, []))
            elif child.field == 'inertial':
                result.append((child, [self.write_inertial(part, pad, item, slot)]))
            elif child.field == 'material':
                result.append((child, [self.visual_material(part, pad, slot)]))
            else:
                result.append((child, [self.write_object(OF_CLASS[type(part)], part, pad,
                                                         slot)]))
        return result

    def visual_material(self, material: Material, pad: str | None, slot: Any) -> str:
        """Return a visual's material: a reference to a robot-level one, or its own."""
        robot = self.robot
        if robot.has_material(material.name):
            defined = robot.get_material(material.name)
            if material is defined or (material.source is None and material == defined):
                reference = Material(material.name)
                node = slot if slot is not None and slot.tag == 'material' and \
                    not len(slot) else None
                return self.write(MATERIAL, reference, node, pad)
        return self.write_object(MATERIAL, material, pad, slot)

    def _merge(self, element: Element, attrs: str, children: list[tuple[Child, list[str]]],
               node: Any, pad: str | None, inner: str | None) -> str:
        """Return an edited element: known children in their source places, the rest kept."""
        tag = element.tag
        queues = dict(children)
        used = dict.fromkeys(queues, 0)
        items: list[tuple[str, str, Child | None]] = []
        space = node.text or ''
        seen: set[Child] = set()
        for sub in node:
            child = slot_of(tag, sub)
            declared = SLOTS[tag].get(sub.tag)
            if child is None and declared is not None and queues.get(declared):
                child = declared  # a value given since replaces the child urdfdom ignores
            if child is not None and not child.many:
                if child in seen:
                    child = None
                else:
                    seen.add(child)
            if child is None:
                items.append((space, self.source_text(sub), None))
            else:
                index = used[child]
                used[child] = index + 1
                texts = queues[child]
                if index < len(texts):
                    items.append((space, texts[index], child))
            space = sub.tail or ''
        trailing = space
        if not len(node):
            trailing = '' if pad is None or inner is None else '\n' + pad
        fresh = '' if inner is None else '\n' + inner
        rank = {child: number for number, (child, _) in enumerate(children)}
        for child, texts in children:
            for text in texts[used[child]:]:
                position = None
                for index in range(len(items) - 1, -1, -1):
                    known = items[index][2]
                    if known is not None and rank[known] <= rank[child]:
                        position = index + 1
                        break
                if position is None:
                    position = next((index for index, entry in enumerate(items)
                                     if entry[2] is not None), len(items))
                items.insert(position, (fresh, text, child))
        if not items and not trailing.strip():
            return self._empty(tag, attrs, node)
        body = ''.join(space + text for space, text, _ in items)
        return f'<{tag}{attrs}>{body}{trailing}</{tag}>'


def _first_slots(element: Element, node: Any) -> dict[Child, Any]:
    """Return the first source child that fills each single child declaration."""
    found: dict[Child, Any] = {}
    for sub in node:
        child = slot_of(element.tag, sub)
        if child is not None and not child.many and child not in found:
            found[child] = sub
    return found
