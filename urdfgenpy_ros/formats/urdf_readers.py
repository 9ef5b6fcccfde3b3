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
Readers compiled from the URDF declarations of :mod:`.urdf_schema`.

For each declared element with a model class this module generates one function that
reads a source node into its model object: attributes parsed, children dispatched by tag
(the first of each single kind; elements urdfdom drops are warned about and kept as
written), the object built without re-checking values the reader already parsed, and its
source location and by-value snapshot recorded. Every error is the reader's one-line
message at the file's line. :mod:`.urdf_read` calls them; nothing else does.
"""

from __future__ import annotations

from _thread import allocate_lock  # threading's lock, without loading threading
from collections.abc import Callable
import dataclasses
from typing import Any

from urdfgenpy_ros.formats.urdf_schema import (
    Attr, DEFAULT_CHILD, Element, ELEMENTS, FLOAT, GEOMETRY, MAY_BE_UNUSABLE, OF_CLASS,
    plan, raw_field, REQUIRED, TEXT, unusable, VEC3)
from urdfgenpy_ros.model.errors import SourceLocation
from urdfgenpy_ros.model.joint import JointType
from urdfgenpy_ros.model.lazy_lists import LazyList
from urdfgenpy_ros.model.preserved import Preserved

Reader = Callable[[Any, Any], Any]
_SHAPE_TAGS = GEOMETRY.children[0].tags
_EXPECTED = {'type': f'one of {", ".join(kind.value for kind in JointType)}',
             'filename': 'the mesh file, e.g. package://my_robot/meshes/part.stl'}


class _Code:
    """Python source being generated, with the constants it refers to (in ``names``)."""

    def __init__(self, names: dict[str, Any], cls: type) -> None:
        self.lines: list[str] = []
        self.names = names
        self.fields = {item.name: item for item in dataclasses.fields(cls)}
        self.have: set[str] = set()  # the fields held in locals ``f_<field>``

    def const(self, value: Any) -> str:
        """Return the name of a constant holding ``value`` in the generated namespace."""
        for name, known in self.names.items():
            if known is value:
                return name
        name = f'K{len(self.names)}'
        assert name not in self.names
        self.names[name] = value
        return name

    def add(self, indent: int, line: str) -> None:
        """Add one line of code."""
        self.lines.append('    ' * indent + line)

    def default(self, name: str) -> str:
        """Return the expression of a field's default value (None for a required field)."""
        item = self.fields[name]
        if item.default_factory is list:
            return '[]'
        if item.default_factory is not dataclasses.MISSING:
            return f'{self.const(item.default_factory)}()'
        return self.const(None if item.default is dataclasses.MISSING else item.default)


def _expected(attr: Attr) -> str:
    return attr.expected or _EXPECTED.get(attr.name) or (
        'a number' if attr.kind == FLOAT else f'{3 if attr.kind == VEC3 else 4} numbers')


def _attributes(code: _Code, element: Element, node: str, indent: int) -> None:
    """Emit the reading of ``element``'s attributes of ``node`` into locals ``f_<field>``."""
    code.add(indent, f'get = {node}.get')
    for attr in element.attrs:
        target = f'f_{attr.field}'
        code.add(indent, f't = get({attr.name!r})')
        empty = ' or not t' if attr.name == 'filename' and attr.default is REQUIRED else ''
        code.add(indent, f'if t is None{empty}:')
        if attr.default is REQUIRED:
            code.add(indent + 1, f'raise r.missing({node}, {attr.name!r}, '
                                 f'{_expected(attr)!r})')
        else:
            code.add(indent + 1, f'{target} = {code.const(attr.default)}')
        code.add(indent, 'else:')
        if attr.kind == TEXT:
            code.add(indent + 1, f'{target} = t')
        elif attr.kind == FLOAT:
            code.add(indent + 1, 'try:')
            code.add(indent + 2, f'{target} = float(t)')
            code.add(indent + 1, 'except ValueError:')
            code.add(indent + 2, f'raise r.not_number({node}, {attr.name!r}, t) from None')
        else:
            count = 3 if attr.kind == VEC3 else 4
            code.add(indent + 1, f'{target} = vectors.get(t)')  # the same text, the same tuple
            code.add(indent + 1, f'if {target} is None or len({target}) != {count}:')
            code.add(indent + 2, f'{target} = r.vector({node}, {attr.name!r}, t, {count})')
        code.have.add(attr.field)


def _children(code: _Code, element: Element, indent: int) -> None:
    """Emit the loop over the children of ``node``, filling ``f_<field>`` locals."""
    slots = list(element.children)
    for number, child in enumerate(slots):
        if child.many:
            code.add(indent, f'f_{child.field} = []')
            code.have.add(str(child.field))
            continue
        code.add(indent, f's{number} = False')
        if child.field is not None:
            code.add(indent, f'f_{child.field} = {code.const(DEFAULT_CHILD.get(child.field))}')
            code.have.add(child.field)
            continue
        inline = ELEMENTS[child.tags[0]]
        names = [attr.field for attr in inline.attrs] + [
            str(inner.field) for inner in inline.children]
        for name in names:  # the class's default while the child is absent
            code.add(indent, f'f_{name} = {code.default(name)}')
            code.have.add(name)
    code.add(indent, 'for child in node:')
    code.add(indent + 1, 'tag = child.tag')
    keyword = 'if'
    for number, child in enumerate(slots):
        for tag in child.tags:
            code.add(indent + 1, f'{keyword} tag == {tag!r}:')
            keyword = 'elif'
            body = indent + 2
            if (element.tag, tag) in MAY_BE_UNUSABLE:
                code.add(body, f'if {code.const(unusable)}({element.tag!r}, child) is not None:')
                code.add(body + 1, f'r.ignored({element.tag!r}, node, child)')
                code.add(body + 1, 'continue')
            if child.many:
                code.add(body, f'f_{child.field}.append(R_{tag}(r, child))')
                continue
            code.add(body, f'if s{number}:')
            code.add(body + 1, 'continue')
            code.add(body, f's{number} = True')
            if child.field is not None:
                read = f'R_{tag}(r, child)'
                if tag == 'material':
                    read = f'r.shared({read}, child)'
                code.add(body, f'f_{child.field} = {read}')
                continue
            inline = ELEMENTS[tag]
            if inline.attrs:
                _attributes(code, inline, 'child', body)
            if inline.children:  # <geometry>: its first element is the shape
                shape = inline.children[0]
                code.add(body, 'shape = r.shape(child)')
                code.add(body, f'f_{shape.field} = SHAPES[shape.tag](r, shape)')
    for number, child in enumerate(slots):
        if child.missing:
            owner = ("f'joint {node.get(\"name\")!r}'" if element.tag == 'joint'
                     else repr(f'<{element.tag}>'))
            code.add(indent, f'if not s{number}:')
            code.add(indent + 1, f"raise r.fail(node, {owner} + ': ' + {child.missing!r})")


def _build(code: _Code, element: Element, indent: int) -> None:
    """Emit the construction of the model object ``o`` with source and snapshot."""
    cls = element.cls
    assert cls is not None
    fields, nested, lists = plan(cls)
    parts = [f'f_{name}' for name in fields]
    parts += [f'(None if f_{name} is None else f_{name}.extras.snapshot)' for name in nested]
    parts += [f'tuple([part.extras.snapshot for part in f_{name}])' for name in lists]
    code.add(indent, 'ex = new(Preserved)')  # Preserved(node, snapshot), without its __init__
    code.add(indent, 'ex.node = node')
    code.add(indent, f'ex.snapshot = ({", ".join(parts)},)')
    code.add(indent, 'where = tnew(SL, (r.file, node.sourceline, None, None, ()))')
    if element.make is not None:
        given = ', '.join(f'f_{attr.field}' for attr in element.attrs)
        code.add(indent, f'return {code.const(element.make)}({given}, source=where, extras=ex)')
        return
    code.add(indent, f'o = new({code.const(cls)})')
    frozen = cls.__dataclass_params__.frozen  # type: ignore[attr-defined]
    for item in dataclasses.fields(cls):
        name = item.name
        if name == 'source':
            value = 'where'
        elif name == 'extras':
            value = 'ex'
        elif name in code.have:
            value = f'f_{name}'
        else:
            value = code.default(name)
        if frozen:
            code.add(indent, f'{code.const(getattr(cls, name).__set__)}(o, {value})')
        elif isinstance(cls.__dict__.get(name), LazyList):  # the list is made on first use
            code.add(indent, f'o.{name}_if_any = None')
        else:  # a new object is in no robot: its bare slot, no edit counted
            code.add(indent, f'o.{raw_field(cls, name)} = {value}')
    code.add(indent, 'return o')


def _compile(element: Element, namespace: dict[str, Any]) -> Reader:
    assert element.cls is not None
    code = _Code(namespace, element.cls)
    code.add(0, 'def read(r, node):')
    code.add(1, 'vectors = r.vectors')
    _attributes(code, element, 'node', 1)
    if element.tag == 'origin':  # a quaternion (URDF 1.1) gives the rotation
        code.add(1, 'if f_quat_xyzw is not None:')
        code.add(2, 'f_rpy = r.quaternion(node, f_quat_xyzw)')
    if element.tag == 'joint':
        code.add(1, 'kind = TYPES.get(f_type)')
        code.add(1, 'if kind is None:')
        code.add(2, 'raise r.bad_type(node, f_name, f_type)')
        code.add(1, 'f_type = kind')
    if element.children:
        _children(code, element, 1)
    _build(code, element, 1)
    exec(compile('\n'.join(code.lines), f'<read {element.tag}>', 'exec'),  # noqa: S102
         namespace)
    return namespace.pop('read')


def _compile_all() -> dict[str, Reader]:
    """
    Return the readers by tag, each compiled on its first call (start-up).

    Until then a tag's reader is a stub that compiles it, puts it in its place (in the
    returned dict, the generated code's ``R_<tag>`` and ``SHAPES``) and calls it: a file
    without meshes, materials or mimics never compiles their readers.
    """
    namespace: dict[str, Any] = {
        'Preserved': Preserved, 'SL': SourceLocation, 'tnew': tuple.__new__,
        'new': object.__new__, 'TYPES': {kind.value: kind for kind in JointType}}
    readers: dict[str, Reader] = {}
    lock = allocate_lock()  # threads reading at once compile each reader once

    def stub(element: Element) -> Reader:
        def first_call(r: Any, node: Any) -> Any:
            with lock:
                reader = readers[element.tag]
                if reader is first_call:
                    reader = _compile(element, namespace)
                    readers[element.tag] = namespace[f'R_{element.tag}'] = reader
                    if element.tag in namespace['SHAPES']:
                        namespace['SHAPES'][element.tag] = reader
            return reader(r, node)
        return first_call

    readers.update({element.tag: stub(element) for element in OF_CLASS.values()})
    namespace.update({f'R_{tag}': reader for tag, reader in readers.items()})
    namespace['SHAPES'] = {tag: readers[tag] for tag in _SHAPE_TAGS}
    return readers


READERS: dict[str, Reader] = _compile_all()
"""The reader of each element with a model class, by tag: ``READERS[tag](reader, node)``."""
