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

The macros repeat the arithmetic of :mod:`urdfgenpy_ros.inertial` operation for
operation, so the real ``xacro`` expands them to exactly the floats ``to_urdf()`` writes.
"""

from __future__ import annotations

from collections.abc import Sequence
from os import PathLike
import re
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.extensions import Extension
from urdfgenpy_ros.floats import fmt, fmt_vec
from urdfgenpy_ros.formats._xml import esc, write_text
from urdfgenpy_ros.formats.urdf import UrdfWriter
from urdfgenpy_ros.inertial import Inertial
from urdfgenpy_ros.link import Link

if TYPE_CHECKING:
    from urdfgenpy_ros.robot import Robot

XACRO_NS = 'http://www.ros.org/wiki/xacro'
_EXPR = '\x00'  # stands for '$' in expressions we mean; every other '$' is escaped
ZERO = "'0 0 0'"  # a Python string literal inside an xacro expression

_MACROS = {
    'box': ('mass x y z', ('mass * (y * y + z * z) / 12.0', 'mass * (x * x + z * z) / 12.0',
                           'mass * (x * x + y * y) / 12.0')),
    'cylinder': ('mass radius length',
                 ('mass * (3.0 * radius * radius + length * length) / 12.0',
                  'mass * (3.0 * radius * radius + length * length) / 12.0',
                  'mass * radius * radius / 2.0')),
    'sphere': ('mass radius', ('2.0 * mass * radius * radius / 5.0',) * 3),
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

    def __init__(self, robot: Robot, includes: Sequence[str] = (), materials: bool = True,
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
                mass = self.robot.get_link(link_name).inertial.mass  # type: ignore[union-attr]
                lines.append(f'<xacro:property name="{prop}" value="{fmt(mass)}"/>')
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


def write_xacro(robot: Robot, path: str | PathLike[str] | None = None, *,
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
