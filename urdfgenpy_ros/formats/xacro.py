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
Xacro writer: the URDF with masses as properties and solid inertias as macros.

The macros repeat the arithmetic of :mod:`urdfgenpy_ros.model.inertial` operation for
operation, so the real ``xacro`` expands them to exactly the floats ``to_urdf()`` writes.
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import partial
from os import PathLike
from pathlib import Path
import re
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.formats._xml import esc, tag_end, write_text
from urdfgenpy_ros.formats.urdf import UrdfWriter
from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.extensions import Extension
from urdfgenpy_ros.model.floats import fmt, fmt_vec
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.link import Link

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.model.material import Material

XACRO_NS = 'http://www.ros.org/wiki/xacro'
_EXPR = '\x00'  # stands for '$' in expressions we mean; every other '$' is escaped
ZERO = "'0 0 0'"  # a Python string literal inside an xacro expression

_TUBE = '(mass * length / (length + 4.0 * radius / 3.0))'
_CAPS = f'(mass - {_TUBE})'
_CAPSULE_SIDE = (f'{_TUBE} * (3.0 * radius * radius + length * length) / 12.0 + {_CAPS} * '
                 '(2.0 * radius * radius / 5.0 + length * length / 4.0 + '
                 '3.0 * length * radius / 8.0)')
_MACROS = {
    'box': ('mass x y z', ('mass * (y * y + z * z) / 12.0', 'mass * (x * x + z * z) / 12.0',
                           'mass * (x * x + y * y) / 12.0')),
    'cylinder': ('mass radius length',
                 ('mass * (3.0 * radius * radius + length * length) / 12.0',
                  'mass * (3.0 * radius * radius + length * length) / 12.0',
                  'mass * radius * radius / 2.0')),
    'sphere': ('mass radius', ('2.0 * mass * radius * radius / 5.0',) * 3),
    # inertial.capsule_tensor, operation for operation: the tube's and the caps' masses
    'capsule': ('mass radius length', (
        _CAPSULE_SIDE, _CAPSULE_SIDE,
        f'{_TUBE} * radius * radius / 2.0 + {_CAPS} * 2.0 * radius * radius / 5.0')),
}


def _macro(kind: str, pad: str, unit: str) -> str:
    params, (ixx, iyy, izz) = _MACROS[kind]
    inner = pad + unit
    body = pad + unit * 2
    e = _EXPR
    return '\n'.join([
        f'<xacro:macro name="{kind}_inertial" params="{params} '
        "xyz:='' rpy:=''\">",
        f'{inner}<inertial>',
        f'{body}<xacro:if value="{e}{{bool(xyz or rpy)}}">'
        f'<origin xyz="{e}{{xyz or {ZERO}}}" rpy="{e}{{rpy or {ZERO}}}"/></xacro:if>',
        f'{body}<mass value="{e}{{mass}}"/>',
        f'{body}<inertia ixx="{e}{{{ixx}}}" ixy="0" ixz="0" iyy="{e}{{{iyy}}}" iyz="0" '
        f'izz="{e}{{{izz}}}"/>',
        f'{inner}</inertial>',
        f'{pad}</xacro:macro>'])


def _identifier(name: str, taken: set[str]) -> str:
    base = re.sub(r'\W', '_', name)
    if not base or base[0].isdigit():
        base = f'_{base}'
    candidate, number = f'{base}_mass', 2
    while candidate in taken:
        candidate, number = f'{base}_mass_{number}', number + 1
    taken.add(candidate)
    return candidate


class XacroWriter(UrdfWriter):
    """
    Write the URDF body with xacro properties and inertia macros.

    ``includes`` are files to ``<xacro:include>`` first (``$(find ...)`` allowed);
    ``materials=False`` leaves the robot-level materials out (visuals still refer to
    them) and ``extensions`` replaces the robot-level blocks written.
    """

    verbatim = False  # masses become properties: every inertial is written anew

    def __init__(self, robot: RobotModel, includes: Sequence[str] = (), materials: bool = True,
                 extensions: list[Extension] | None = None) -> None:
        super().__init__(robot)
        self.includes = list(includes)
        if not materials:
            self.materials = []
        if extensions is not None:
            self.extensions = extensions
        taken: set[str] = set()
        self.mass_names = {link.name: _identifier(link.name, taken)
                           for link in robot.links if link.inertial is not None}
        self.kinds = sorted({link.inertial.solid[0] for link in robot.links
                             if link.inertial is not None and link.inertial.solid is not None
                             and _uses_macro(link.inertial)})

    def document(self) -> str:
        """Return the whole file, with ``$`` escaped wherever it is not ours."""
        text = super().document()
        text = text.replace('${', '$${').replace('$(', '$$(')
        return text.replace(_EXPR, '$')

    def robot_attrs(self) -> list[tuple[str, str]]:
        """Declare the xacro namespace on the root."""
        return super().robot_attrs() + [('xmlns:xacro', XACRO_NS)]

    def prologue(self) -> list[str]:
        """Return the includes, the mass properties and the inertia macros in use."""
        lines = [f'<xacro:include filename="{esc(name).replace("$", _EXPR)}"/>'
                 for name in self.includes]
        if self.mass_names:
            lines.append('<!-- Link masses in kg. -->')
            for link_name, prop in self.mass_names.items():
                link = self.robot.get_link(link_name)
                mass = link.inertial.mass  # type: ignore[union-attr]
                value = self.checked(link, partial(fmt, mass))
                lines.append(f'<xacro:property name="{prop}" value="{value}"/>')
        if self.kinds:
            lines.append('<!-- Inertia of solid bodies about their centre of mass. -->')
            lines.extend(_macro(kind, self.unit, self.unit) for kind in self.kinds)
        return lines

    def write_inertial(self, inertial: Inertial, pad: str | None, link: Link,
                       slot: Any = None) -> str:
        """Call an inertia macro where one applies; else write it with the mass property."""
        mass = f'{_EXPR}{{{self.mass_names[link.name]}}}'
        if not _uses_macro(inertial):
            text = super().write_inertial(inertial, pad, link, slot)
            return _MASS.sub(lambda match: f'{match.group(1)}{mass}{match.group(4)}', text,
                             count=1)
        kind, _, *dims = inertial.solid  # type: ignore[misc]
        names = _MACROS[kind][0].split()[1:]
        attrs = [('mass', mass)] + [(name, fmt(value)) for name, value in zip(names, dims)]
        if not inertial.origin.is_identity:
            attrs += [('xyz', fmt_vec(inertial.origin.xyz)), ('rpy', fmt_vec(inertial.origin.rpy))]
        text = ''.join(f' {name}="{value}"' for name, value in attrs)
        return f'<xacro:{kind}_inertial{text}/>'


_MASS = re.compile(r'(<mass\b[^>]*?\bvalue=(["\']))(.*?)(\2)')


def _uses_macro(inertial: Inertial | None) -> bool:
    return (inertial is not None and inertial.extras is None
            and inertial.origin.extras is None and inertial.matches_solid())


def write_xacro(robot: RobotModel, path: str | PathLike[str] | None = None, *,
                includes: Sequence[str] = (), materials: bool = True,
                extensions: list[Extension] | None = None) -> str:
    """
    Return the Xacro text of ``robot``; also write it to ``path`` when given.

    ``includes``, ``materials`` and ``extensions``: see :class:`XacroWriter`.
    """
    text = XacroWriter(robot, includes, materials, extensions).document()
    if path is not None:
        write_text(path, text)
    return text


# ---- reusable macros ------------------------------------------------------------------

PREFIX_MARK = 'urdfgenpyprefixmark'
"""Stands for ``${prefix}`` while the macro body is written (a valid name, no ``$``)."""


class _MacroBody(XacroWriter):
    """The Xacro writer for a robot whose names start with PREFIX_MARK."""

    def __init__(self, robot: RobotModel, extensions: list[Extension] | None) -> None:
        super().__init__(robot, materials=False, extensions=extensions)
        taken: set[str] = set()  # mass properties are named after the unprefixed links
        self.mass_names = {link.name: _identifier(link.name.replace(PREFIX_MARK, ''), taken)
                           for link in robot.links if link.inertial is not None}


_NAMESPACE = re.compile(r'xmlns(?::[\w.-]+)?\s*=\s*("[^"]*"|\'[^\']*\')')


def macro_name(robot: RobotModel) -> str:
    """Return the name of the robot's Xacro macro: its name as an identifier."""
    name = re.sub(r'\W', '_', robot.name)
    return name if name and not name[0].isdigit() else f'_{name}'


def with_prefix(text: str) -> str:
    """Return Xacro text written for a ``prefixed(PREFIX_MARK)`` robot with ``${prefix}``."""
    return _dollars(text).replace(PREFIX_MARK, '${prefix}')


def macro_xacro(robot: RobotModel, *, includes: Sequence[str] = (), materials: bool = True,
                skip: Sequence[str] = (), calls: Sequence[str] = ()) -> str:
    """
    Return ``<name>.macro.xacro``: the robot as ``<xacro:macro params="prefix parent *origin">``.

    Every link, joint and reference gets ``${prefix}`` (as :meth:`Robot.prefixed` does);
    a non-empty ``parent`` adds the fixed joint ``${parent}_to_${prefix}<root>`` placed by
    the ``origin`` block, as :meth:`Robot.attach` names it. Robot-level materials stand
    outside the macro, so a file that includes it once can call it many times.

    ``includes`` are included first; ``materials=False`` leaves the materials out;
    robot-level blocks whose tag is in ``skip`` are left out and ``calls`` (Xacro lines,
    ``$`` as written) end the macro's body: the scaffolder puts those blocks in macros of
    their own files.
    """
    from urdfgenpy_ros.reshape.assembly import prefixed
    marked = prefixed(robot, PREFIX_MARK)
    blocks = [block for block in marked.extensions if block.tag not in skip]
    writer = _MacroBody(marked, blocks)
    text = writer.document().replace('\r\n', '\n')
    opening = re.search(r'<robot\b', text)
    assert opening is not None
    start = tag_end(text, opening.start())
    declared = ''.join(f' {match.group(0)}' for match in _NAMESPACE.finditer(
        text[opening.start():start]) if not match.group(0).startswith('xmlns:xacro='))
    end = text.rfind('</robot>')
    body = text[start:end].strip('\n') if end > start else ''
    unit = writer.unit
    body = '\n'.join(unit + line if line.strip() else line for line in body.split('\n'))
    body = body.replace(PREFIX_MARK, '${prefix}')  # the writer escaped every other '$'
    root = with_prefix(esc(marked.root.name))
    defined = [line for material in robot.materials
               for line in defined_once(writer, material, unit)] if materials else []
    e, inner, name = '$', unit * 2, macro_name(robot)
    mount = [f'{inner}<xacro:if value="{e}{{parent != \'\'}}">',
             f'{inner}{unit}<joint name="{e}{{parent}}_to_{root}" type="fixed">',
             f'{inner}{unit * 2}<parent link="{e}{{parent}}"/>',
             f'{inner}{unit * 2}<child link="{root}"/>',
             f'{inner}{unit * 2}<xacro:insert_block name="origin"/>',
             f'{inner}{unit}</joint>', f'{inner}</xacro:if>']
    lines = ['<?xml version="1.0"?>',
             f'<!-- {_comment(robot.name)} as a macro: include this file, then call '
             f'<xacro:{name} prefix="..." parent="..."><origin .../></xacro:{name}> -->',
             f'<robot xmlns:xacro="{XACRO_NS}"{declared}>',
             *(f'{unit}<xacro:include filename="{esc(file)}"/>' for file in includes),
             *defined, f'{unit}<xacro:macro name="{name}" params="prefix parent *origin">',
             *mount, *([body] if body else []), *(inner + call for call in calls),
             f'{unit}</xacro:macro>', '</robot>', '']
    return '\n'.join(lines)


def defined_once(writer: UrdfWriter, material: Material, unit: str) -> list[str]:
    """
    Return Xacro lines that define a robot-level material unless a file did so before.

    Two robots' files that both define, say, ``black`` can then be included in one robot
    (urdfdom refuses a material defined twice): the first file included defines it. The
    flag is a global Xacro property named after the material (hex: any name will do).
    """
    flag = f'urdfgenpy_material_{material.name.encode("utf-8").hex()}'
    return [f'{unit}<xacro:property name="{flag}" default="false"/>',
            f'{unit}<xacro:unless value="${{{flag}}}">',
            f'{unit * 2}<xacro:property name="{flag}" value="true" scope="global"/>',
            _dollars(writer.write_material(material, unit * 2)), f'{unit}</xacro:unless>']


def top_level_xacro(robot: RobotModel, includes: Sequence[str]) -> str:
    """Return a robot file that includes ``includes`` (the macro's last) and calls it once."""
    name = macro_name(robot)
    return '\n'.join([
        '<?xml version="1.0"?>',
        f'<robot name="{_dollars(esc(robot.name))}" xmlns:xacro="{XACRO_NS}">',
        '  <xacro:arg name="prefix" default=""/>',
        *(f'  <xacro:include filename="{esc(file)}"/>' for file in includes),
        f'  <xacro:{name} prefix="$(arg prefix)" parent="">',
        '    <origin xyz="0 0 0" rpy="0 0 0"/>',
        f'  </xacro:{name}>',
        '</robot>', ''])


def write_macro_xacro(robot: RobotModel, path: str | PathLike[str] | None = None) -> str:
    """
    Return the macro file's text (:func:`macro_xacro`).

    With ``path``, write the file that instantiates the macro there (its ``prefix``
    argument defaults to ''), and the macro beside it as ``<robot name>.macro.xacro``.
    """
    text = macro_xacro(robot)
    if path is not None:
        target = Path(path)
        macro_file = target.with_name(f'{robot.name}.macro.xacro')
        if macro_file.name == target.name:
            raise ModelError(f"{path}: that is the macro file's own name; give the top-level "
                             f'file another one, e.g. {robot.name}.urdf.xacro')
        write_text(macro_file, text)
        write_text(target, top_level_xacro(robot, [macro_file.name]))
    return text


def _dollars(text: str) -> str:
    return text.replace('${', '$${').replace('$(', '$$(')


def _comment(text: str) -> str:
    return text.replace('--', '- -')
