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
Fast writers for elements built in Python, generated from the URDF declarations.

For each declared element this module compiles one function that writes an object which
was not read from a file: the same output as the general writer's, without its loops
over the declaration. The general writer calls them, and :func:`write_new_robot` for a
robot that was not read from a file; nothing else does.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from typing import Any

from urdfgenpy_ros.formats._xml import esc
from urdfgenpy_ros.formats.urdf_schema import (
    Element, ELEMENTS, FLOAT, LENGTHS, OF_CLASS, raw_field, REQUIRED, TEXT)
from urdfgenpy_ros.model.joint import JointType

Writer = Callable[[Any, Any, str], str]
_LEAVES = ('origin',)  # one-line frozen children written in place, not by a call


def _attributes(element: Element, owner: str, lines: list[str], indent: str,
                target: str = 'a', cls: type | None = None) -> None:
    """
    Emit code setting ``target`` to the attributes of ``element`` (fields of ``owner``, a ``cls``).

    The usual case is one f-string: every attribute that defaults to None is None, the
    others are set, and names are plain strings that need no escaping. Anything else
    takes the attribute-by-attribute path, which writes what it finds.
    """
    attrs = element.attrs
    if not attrs:
        lines.append(f"{indent}{target} = ''")
        return
    tests, pieces, slow = [], [], []
    for number, attr in enumerate(attrs):
        var = f'v{number}'
        expression = _FIELD_EXPRESSIONS.get((element.tag, attr.field), '{owner}.{field}')
        plain = (element.tag, attr.field) not in _FIELD_EXPRESSIONS  # a field as the user set it
        lines.append(f'{indent}{var} = ' + expression.format(owner=owner, field=_field(
            cls, attr.field)))
        if attr.kind == TEXT:
            skip = f" and {var} != ''" if attr.default == '' else ''
            slow.append(f'if {var} is not None{skip}:')
            slow.append(f'    t = {var} if type({var}) is str else text({var})')
            slow.append("    if '&' in t or '<' in t or '>' in t or '\"' in t:")
            slow.append('        t = esc(t)')
            slow.append(f'    {target} += \' {attr.name}="\' + t + \'"\'')
        else:
            text = 'number' if attr.kind == FLOAT else 'vector'
            unless = f' and {owner}.{_field(cls, attr.unless)} is None' if attr.unless else ''
            slow.append(f'if {var} is not None{unless}:')
            if attr.kind != FLOAT and plain:  # axis = (0, 1): named by wrong_kind
                slow.append(f'    if len({var}) != {LENGTHS[attr.kind]}: '
                            "raise ValueError('a vector of another length')")
            slow.append(f'    {target} += \' {attr.name}="\' + (known({var}) or {text}({var})) + '
                        '\'"\'')
            if attr.default is REQUIRED and not attr.unless:  # inertial.mass = None
                slow.append(f"elif {var} is None: raise TypeError('{attr.field} is required')")
        if attr.default is None:  # usually left out: the one-string path while it is
            tests.append(f'{var} is None')
        elif attr.kind == TEXT:
            tests.append(f'type({var}) is str' + (f" and {var} != ''" if attr.default == ''
                                                  else ''))
            tests += [f'{char!r} not in {var}' for char in '&<>"']
            pieces.append(f' {attr.name}="{{{var}}}"')
        else:
            text = 'number' if attr.kind == FLOAT else 'vector'
            tests.append(f'{var} is not None')
            if attr.kind != FLOAT and plain:
                tests.append(f'len({var}) == {LENGTHS[attr.kind]}')
            pieces.append(f' {attr.name}="{{known({var}) or {text}({var})}}"')
    lines.append(f"{indent}if {' and '.join(tests)}:")
    lines.append(f"{indent}    {target} = f'{''.join(pieces)}'" if pieces else
                 f"{indent}    {target} = ''")
    lines.append(f'{indent}else:')
    lines.append(f"{indent}    {target} = ''")
    lines += [f'{indent}    {line}' for line in slow]


# How to read an attribute that is not a plain field: a box's size is its three lengths;
# a joint's type is a JointType, whose text is its value.
_FIELD_EXPRESSIONS = {('box', 'size'): '({owner}.length, {owner}.width, {owner}.height)',
                      ('joint', 'type'): 'TYPES.get(w := {owner}.{field}, w)'}


def _field(cls: type | None, name: str) -> str:
    """Return the attribute to read field ``name`` of a ``cls`` by: its bare slot if it has one."""
    return name if cls is None else raw_field(cls, name)


def _leaf(element: Element, owner: str, lines: list[str], indent: str, kids: str,
          cls: type | None = None) -> None:
    """Emit code that appends a one-line child element ``<tag .../>`` of ``owner`` to ``kids``."""
    _attributes(element, owner, lines, indent, 'c', cls)
    lines.append(f"{indent}{kids}.append(f'<{element.tag}{{c}}/>')")


def _body(element: Element, lines: list[str], indent: str, depth: int) -> None:
    """Emit code that writes ``element`` of ``item`` into ``t`` at indentation ``p{depth}``."""
    pad, inner = f'p{depth}', f'p{depth + 1}'
    cls = element.cls
    _attributes(element, 'item', lines, indent, 'a', cls)
    if not element.children:
        lines.append(f"{indent}t = f'<{element.tag}{{a}}/>'")
        return
    lines.append(f'{indent}{inner} = {pad} + unit')
    lines.append(f'{indent}k{depth} = []')
    kids = f'k{depth}'
    for child in element.children:
        tag = child.tags[0]
        if child.many:  # written by the writer of each part's class, unless read
            lines.append(f'{indent}for part in item.{_field(cls, str(child.field))}:')
            lines.append(f'{indent}    {kids}.append(obj(part, {inner}) if part.extras is not '
                         f'None else FRESH[type(part)](writer, part, {inner}))')
        elif child.field is None:
            inline = ELEMENTS[tag]
            body = indent
            if child.optional:
                test = ' or '.join(f'item.{_field(cls, attr.field)} is not None'
                                   for attr in inline.attrs)
                lines.append(f'{indent}if {test}:')
                body = indent + '    '
            if inline.children:  # <geometry>: a wrapper around the shape object
                shape = _field(cls, str(inline.children[0].field))
                lines.append(f'{body}part = item.{shape}')
                lines.append(f'{body}g = {inner} + unit')
                lines.append(f'{body}x = obj(part, g) if part.extras is not None else '
                             'FRESH[type(part)](writer, part, g)')
                lines.append(f"{body}{kids}.append(f'<{tag}>\\n{{g}}{{x}}\\n{{{inner}}}</{tag}>')")
            else:
                _leaf(inline, 'item', lines, body, kids, cls)
        else:
            lines.append(f'{indent}part = item.{_field(cls, child.field)}')
            if child.field == 'origin':  # left out while it neither moves nor turns
                lines.append(f'{indent}if part is not None:')
                lines.append(f'{indent}    if part.extras is not None:')
                lines.append(f'{indent}        {kids}.append(obj(part, {inner}))')
                lines.append(f'{indent}    elif part.xyz != ZERO or part.rpy != ZERO:')
                _leaf(ELEMENTS['origin'], 'part', lines, indent + '        ', kids)
                continue
            lines.append(f'{indent}if part is not None:')
            if child.field == 'inertial':  # a hook: the Xacro writer writes a macro call
                call = f'writer.write_inertial(part, {inner}, item, None)'
            elif child.field == 'material':
                call = f'writer.visual_material(part, {inner}, None)'
            else:
                call = (f'obj(part, {inner}) if part.extras is not None else '
                        f'FRESH[type(part)](writer, part, {inner})')
            lines.append(f'{indent}    {kids}.append({call})')
    lines.append(f'{indent}if {kids}:')
    lines.append(f"{indent}    s = '\\n' + {inner}")
    lines.append(f"{indent}    t = f'<{element.tag}{{a}}>{{s}}{{s.join({kids})}}\\n{{{pad}}}"
                 f"</{element.tag}>'")
    lines.append(f'{indent}else:')
    lines.append(f"{indent}    t = f'<{element.tag}{{a}}/>'")


_BINDINGS = {'unit': 'writer.unit', 'number': 'writer.number', 'vector': 'writer.vector',
             'known': 'writer.known_number', 'obj': 'writer.object_text'}
_JOINT_TYPES: dict[Any, str] = {kind: kind.value for kind in JointType}


def _text(value: Any) -> str:
    """Return the text of a TEXT attribute that is not a ``str`` (a JointType, say)."""
    return _JOINT_TYPES[value] if type(value) is JointType else str(value)


def _compile(element: Element) -> Writer:
    body: list[str] = []
    _body(element, body, '    ', 0)
    used = '\n'.join(body)
    lines = ['def fresh(writer, item, p0):']
    lines += [f'    {name} = {value}' for name, value in _BINDINGS.items()
              if f'{name}(' in used or f'+ {name}' in used]  # only what the body uses
    lines += body
    lines.append('    return t')
    namespace: dict[str, Any] = {'esc': esc, 'text': _text, 'FRESH': FRESH,
                                 'ZERO': (0.0, 0.0, 0.0), 'TYPES': _JOINT_TYPES}
    exec(compile('\n'.join(lines), f'<fresh {element.tag}>', 'exec'), namespace)  # noqa: S102
    return namespace['fresh']


class _Writers(dict[type, Writer]):
    """Each class's writer, compiled when first asked for (a check that writes compiles none)."""

    def __missing__(self, cls: type) -> Writer:
        writer = self[cls] = _compile(OF_CLASS[cls])
        return writer


FRESH: dict[type, Writer] = _Writers()
"""The fast writer of each model class, for objects built in Python."""


def write_new_robot(writer: Any, sensor_block: Callable[[Any, str], Any]) -> str:
    """
    Return the ``<robot>`` element of a robot not read from a file, in one pass.

    The same text as the general writer's (:meth:`.UrdfWriter.write_robot`) for such a
    robot: materials, links, the blocks and sensors of links then joints, joints, the
    robot's blocks, each on a new line; ``sensor_block`` gives the ``<gazebo>`` element
    that carries a sensor. A link or joint that fails to write is written again through
    ``writer.checked``, which names a value of the wrong kind in one line (a bug of ours
    keeps its traceback).
    """
    robot = writer.robot
    unit = writer.unit
    fresh = '\n' + unit
    checked = writer.checked
    parts = ['']  # the start tag, once the rest is written
    append = parts.append
    for text in writer.prologue():
        append(fresh)
        append(text)
    for material in writer.materials:
        append(fresh)
        append(checked(material, partial(writer.write_item, material, unit)))
    links, joints = robot.links, robot.joints
    _write_each(writer, links, fresh, append)
    for owners in (links, joints):
        for owner in owners:  # most hold neither list (lazy_lists)
            if owner.extensions_if_any:
                for block in owner.extensions:
                    append(fresh)
                    append(writer.write_item(block, unit, owner))
            if owner.sensors_if_any:
                for sensor in owner.sensors:
                    append(fresh)
                    append(writer.write_extension(sensor_block(sensor, owner.name), unit))
    _write_each(writer, joints, fresh, append)
    for block in writer.extensions:
        append(fresh)
        append(writer.write_item(block, unit))
    name, attrs = writer._opening()
    if len(parts) == 1:
        return f'<{name}{attrs}/>'
    parts[0] = f'<{name}{attrs}>'
    append(f'\n</{name}>')
    return ''.join(parts)


def _write_each(writer: Any, items: list[Any], fresh: str, append: Callable[[str], None]) -> None:
    """Append each link or joint on a new line; one that fails is written again, checked."""
    unit = writer.unit
    text_of = writer.object_text
    for item in items:
        append(fresh)
        try:
            append(text_of(item, unit))
        except Exception:  # noqa: B902 - written again to name the value, or to re-raise
            append(writer.checked(item, partial(text_of, item, unit)))
