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

"""References and values: materials, mesh files, sizes, and numbers that are not finite."""

from __future__ import annotations

import math
import os
from pathlib import Path, PurePosixPath, PureWindowsPath
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.errors import PACKAGE_FOLDER
from urdfgenpy_ros.model.findings import Findings, joint_path, link_path
from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, Mesh, Sphere
from urdfgenpy_ros.model.link import Shape
from urdfgenpy_ros.resources import PackageResolver, ResourceError, uri_warning

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def check_references(robot: RobotModel, findings: Findings, resolver: PackageResolver | None,
                     base: Path | None) -> None:
    """
    Check materials, meshes (when a resolver is given), sizes and non-finite numbers.

    A visual's material that only names a material is defined when the robot has it, or
    when a visual read before it (links in file order, visuals in order) defines it inline
    with a colour or texture: urdfdom adds such a material to the robot's, if the name is
    new, when it reads that link, so a later name-only reference finds it and an earlier
    one does not.
    """
    defined = {material.name for material in robot.materials}
    inline = _inline_materials(robot)
    for link in robot.links:
        groups: tuple[tuple[str, list[Shape]], ...] = (
            ('visual', list(link.visuals)), ('collision', list(link.collisions)))
        for kind, shapes in groups:
            for number, shape in enumerate(shapes, start=1):
                where = f'{link_path(link.name)}/{kind}[{number}]'
                element = f'link {link.name!r}'
                _check_geometry(shape.geometry, element, where, findings,
                                'R304' if kind == 'collision' else 'R307')
                if isinstance(shape.geometry, Mesh):
                    _check_bare_path(shape.geometry, element, where, findings)
                if isinstance(shape.geometry, Mesh) and resolver is not None:
                    missing = 'R302' if kind == 'collision' else 'R306'
                    _check_mesh(shape.geometry, element, where, findings, resolver, base,
                                missing)
                material = getattr(shape, 'material', None)
                if material is None or material.name in defined:
                    continue
                if not material.is_reference:
                    defined.add(material.name)  # urdfdom: from here on, the robot's
                    continue
                later = inline.get(material.name)
                findings.add('R301', material, element, where + '/material',
                             f'material {material.name!r} is not defined' + (
                                 f' yet (link {later!r} defines it later: urdfdom reads '
                                 'links in file order)' if later else ''),
                             f'add <material name="{material.name}"><color rgba=.../>'
                             '</material> to the robot' + (
                                 ', or define it here, where it is first used'
                                 if later else ''), 'material')
    _check_finite(robot, findings)


def _inline_materials(robot: RobotModel) -> dict[str, str]:
    """Return each material a visual defines inline, with the first link defining it."""
    found: dict[str, str] = {}
    for link in robot.links:
        for visual in link.visuals:
            material = visual.material
            if material is not None and not material.is_reference:
                found.setdefault(material.name, link.name)
    return found


def _check_geometry(geometry: Any, element: str, where: str, findings: Findings,
                    code: str) -> None:
    """
    Report a zero or negative size: an error on a collision, a warning on a visual.

    A negative size is an error on a visual too: MuJoCo refuses it when it keeps visuals
    and RViz draws the shape inside out; a zero one only draws nothing.
    """
    sizes = {Box: ('length', 'width', 'height'), Cylinder: ('radius', 'length'),
             Sphere: ('radius',), Capsule: ('radius', 'length')}.get(type(geometry), ())
    for name in sizes:
        value = getattr(geometry, name)
        if math.isfinite(value) and value <= 0.0:
            negative = value < 0.0 and code == 'R307'
            findings.add('R304' if negative else code, geometry, element, f'{where}/geometry',
                         f'{type(geometry).__name__.lower()} {name} is {value:g}'
                         + (' on a visual' if negative else ''),
                         'sizes are positive lengths in metres' + (
                             ' (MuJoCo refuses a negative one when it keeps visuals, and RViz '
                             'draws the shape inside out)' if negative else
                             '' if code == 'R304' else ' (a zero-size visual draws nothing; '
                             'remove it if it is a placeholder)'))
    if isinstance(geometry, Mesh) and geometry.scale is not None and 0.0 in geometry.scale:
        findings.add(code, geometry, element, f'{where}/geometry',
                     f'mesh scale {geometry.scale} has a zero',
                     'a zero scale flattens the mesh: use 1 (or 0.001 for millimetres)',
                     'mesh')


def _check_bare_path(mesh: Mesh, element: str, where: str, findings: Findings) -> None:
    """Warn on a mesh named by a bare absolute path: a file of this machine only."""
    name = mesh.filename
    if '://' in name or not (PurePosixPath(name).is_absolute()
                             or PureWindowsPath(name).is_absolute()):
        return
    findings.add('R309', mesh, element, f'{where}/geometry/mesh',
                 f'{name!r} is a bare absolute path: it names a file of this machine only, '
                 'and is not a URI as ROS tools expect',
                 'write package://<package>/<path in the package>, or '
                 f'{Path(name).as_uri() if name.startswith("/") else "file:///" + name} '
                 'if it must stay absolute', 'mesh')


def _check_mesh(mesh: Mesh, element: str, where: str, findings: Findings,
                resolver: PackageResolver, base: Path | None, missing: str) -> None:
    try:
        path = resolver.resolve(mesh.filename, base)
    except ResourceError as error:
        message = str(error).split(' (', 1)[0]
        if 'not found' in message:
            code, hint = 'R303', ('source the workspace that holds it, or '
                                  f'{PACKAGE_FOLDER.text}')
        else:
            code, hint = missing, 'fix the file name or add the file'
        findings.add(code, mesh, element, f'{where}/geometry/mesh', message, hint, 'mesh')
        return
    warning = uri_warning(mesh.filename)
    if warning is not None:
        findings.add('R308', mesh, element, f'{where}/geometry/mesh', warning,
                     'use a path relative to the file, or package://', 'mesh')
    if not os.access(path, os.R_OK) or not path.is_file():
        findings.add(missing, mesh, element, f'{where}/geometry/mesh',
                     f'{mesh.filename!r} resolves to {path}, which is not a readable file',
                     'check the path and its permissions', 'mesh')


def _check_finite(robot: RobotModel, findings: Findings) -> None:
    for link in robot.links:
        parts: list[tuple[str, Any]] = []
        if link.inertial is not None:
            parts.append(('inertial', link.inertial))
        parts += [(f'visual[{n}]', v) for n, v in enumerate(link.visuals, start=1)]
        parts += [(f'collision[{n}]', c) for n, c in enumerate(link.collisions, start=1)]
        for name, part in parts:
            _report_non_finite(part, f'link {link.name!r}', f'{link_path(link.name)}/{name}',
                               findings)
    for joint in robot.joints:
        _report_non_finite(joint, f'joint {joint.name!r}', joint_path(joint.name), findings)


def _numbers(item: Any, prefix: str = '') -> list[tuple[str, float]]:
    """Return ``(field path, value)`` for every number inside a model element."""
    found = []
    for name in getattr(item, '__dataclass_fields__', {}):
        if name in ('source', 'extras', 'text', 'solid', 'extensions'):
            continue
        value = getattr(item, name)
        if isinstance(value, float):
            found.append((f'{prefix}{name}', value))
        elif isinstance(value, tuple) and value and isinstance(value[0], float):
            found += [(f'{prefix}{name}', number) for number in value]
        elif hasattr(value, '__dataclass_fields__'):
            found += _numbers(value, f'{prefix}{name}.')
    return found


def _report_non_finite(item: Any, element: str, where: str, findings: Findings) -> None:
    for field, value in _numbers(item):
        if not math.isfinite(value):
            part = field.split('.', 1)[0] if '.' in field else None
            findings.add('R305', item, element, f'{where}/{part}' if part else where,
                         f'{field} is {value}', 'write a finite number', part)
            return
