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
over the declaration. The general writer calls them; nothing else does.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from urdfgenpy_ros.formats._xml import esc
from urdfgenpy_ros.formats.urdf_schema import Element, ELEMENTS, FLOAT, OF_CLASS, TEXT

Writer = Callable[[Any, Any, str], str]


def _attributes(element: Element, owner: str, lines: list[str], indent: str) -> None:
    """Emit code that appends the attributes of ``element`` (fields of ``owner``) to ``a``."""
    for attr in element.attrs:
        lines.append(f'{indent}v = {owner}.{attr.field}')
        if attr.kind == TEXT:
            skip = " and v != ''" if attr.default == '' else ''
            lines.append(f'{indent}if v is not None{skip}:')
            lines.append(f'{indent}    a += \' {attr.name}="\' + esc(str(v)) + \'"\'')
        else:
            text = 'number(v)' if attr.kind == FLOAT else 'vector(v)'
            unless = f' and {owner}.{attr.unless} is None' if attr.unless else ''
            lines.append(f'{indent}if v is not None{unless}:')
            lines.append(f'{indent}    n = known(v)')
            lines.append(f'{indent}    a += \' {attr.name}="\' + (n or {text}) + \'"\'')


def _body(element: Element, lines: list[str], indent: str, depth: int) -> None:
    """Emit code that writes ``element`` of ``item`` into ``t`` at indentation ``p{depth}``."""
    pad, inner = f'p{depth}', f'p{depth + 1}'
    lines.append(f"{indent}a = ''")
    _attributes(element, 'item', lines, indent)
    if not element.children:
        lines.append(f"{indent}t = '<{element.tag}' + a + '/>'")
        return
    lines.append(f'{indent}{inner} = {pad} + unit')
    lines.append(f'{indent}k{depth} = []')
    kids = f'k{depth}'
    for child in element.children:
        tag = child.tags[0]
        if child.many:
            lines.append(f'{indent}for part in item.{child.field}:')
            lines.append(f'{indent}    {kids}.append(obj(part, {inner}))')
        elif child.field is None:
            inline = ELEMENTS[tag]
            body = indent
            if child.optional:
                test = ' or '.join(f'item.{attr.field} is not None' for attr in inline.attrs)
                lines.append(f'{indent}if {test}:')
                body = indent + '    '
            if inline.children:  # <geometry>: a wrapper around the shape object
                shape = inline.children[0].field
                lines.append(f"{body}{kids}.append('<{tag}>\\n' + {inner} + unit + "
                             f"obj(item.{shape}, {inner} + unit) + '\\n' + {inner} + "
                             f"'</{tag}>')")
            else:
                saved = len(lines)
                lines.append(f'{body}b = a')
                _attributes(inline, 'item', lines, body)
                lines[saved + 1:] = [line.replace(' a +=', ' c +=') for line in
                                     lines[saved + 1:]]
                lines[saved] = f"{body}c = ''"
                lines.append(f"{body}{kids}.append('<{tag}' + c + '/>')")
        else:
            lines.append(f'{indent}part = item.{child.field}')
            if child.field == 'origin':
                lines.append(f'{indent}if part is not None and (part.extras is not None or '
                             'not part.is_identity):')
            else:
                lines.append(f'{indent}if part is not None:')
            if child.field == 'inertial':
                call = f'writer.write_inertial(part, {inner}, item, None)'
            elif child.field == 'material':
                call = f'writer.visual_material(part, {inner}, None)'
            else:
                call = f'obj(part, {inner})'
            lines.append(f'{indent}    {kids}.append({call})')
    lines.append(f'{indent}if {kids}:')
    lines.append(f"{indent}    s = '\\n' + {inner}")
    lines.append(f"{indent}    t = '<{element.tag}' + a + '>' + s + s.join({kids}) + '\\n' + "
                 f"{pad} + '</{element.tag}>'")
    lines.append(f'{indent}else:')
    lines.append(f"{indent}    t = '<{element.tag}' + a + '/>'")


_BINDINGS = {'unit': 'writer.unit', 'number': 'writer.number', 'vector': 'writer.vector',
             'known': 'writer.known_number', 'obj': 'writer.object_text'}


def _compile(element: Element) -> Writer:
    body: list[str] = []
    _body(element, body, '    ', 0)
    used = '\n'.join(body)
    lines = ['def fresh(writer, item, p0):']
    lines += [f'    {name} = {value}' for name, value in _BINDINGS.items()
              if f'{name}(' in used or f'+ {name}' in used]  # only what the body uses
    lines += body
    lines.append('    return t')
    namespace: dict[str, Any] = {'esc': esc}
    exec(compile('\n'.join(lines), f'<fresh {element.tag}>', 'exec'), namespace)  # noqa: S102
    return namespace['fresh']


FRESH: dict[type, Writer] = {cls: _compile(element) for cls, element in OF_CLASS.items()}
"""The fast writer of each model class, for objects built in Python."""
