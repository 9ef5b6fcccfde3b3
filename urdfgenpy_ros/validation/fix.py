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
Repair what has one right answer (``urdfgenpy check --fix``), in the model.

The robot is edited in place; written back by the lossless writer, only the repaired
elements' lines change. Fixed: a non-unit axis (J102, normalised), lower > upper (J104,
swapped), a non-physical tensor (I202, I203: replaced by the tensor of
the link's first collision, else visual, box, cylinder, sphere, capsule or closed mesh with
the link's mass), an
inertia on the root (I205: a massless root link above it), and, only with the defaults the
user gives, a missing ``<limit>`` (J103) or a zero effort or velocity (J106);
``missing_defaults`` says which values those still lack. Everything else (a zero axis, a
missing mimic target, ...) has no single right answer and stays.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
import math
from os import PathLike
import re
from typing import TYPE_CHECKING

from urdfgenpy_ros.model.codes import FIXABLE
from urdfgenpy_ros.model.errors import SourceLocation, ValidationError
from urdfgenpy_ros.model.floats import fmt, fmt_vec
from urdfgenpy_ros.model.geometry import Mesh
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.joint import Joint, JointLimit, JointType
from urdfgenpy_ros.model.link import Link
from urdfgenpy_ros.model.transforms import from_xyz_rpy

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.validation.fix_tensor import TensorSources

LIMIT_FIELDS = ('lower', 'upper', 'effort', 'velocity')
_OWNER = re.compile(r"^/robot/(link|joint)\[@name='(.*?)'\]")


@dataclass(frozen=True)
class Repair:
    """One repair: the finding's code, element and location, and what was done."""

    code: str
    element: str
    location: SourceLocation
    message: str

    def __str__(self) -> str:
        """Return ``file:line:col: fixed CODE element: what was done``."""
        return f'{self.location}: fixed {self.code} {self.element}: {self.message}'

    def as_dict(self) -> dict[str, object]:
        """Return the repair as plain data (for JSON output)."""
        return {'code': self.code, 'element': self.element, 'file': self.location.file,
                'line': self.location.line, 'column': self.location.column,
                'message': self.message}


@dataclass
class _Context:
    """What the repairs are given: the limit defaults, and where the meshes are."""

    defaults: dict[str, float]
    sources: TensorSources


def fix(robot: RobotModel, findings: list[ValidationError],
        limit_defaults: dict[str, float] | None = None,
        search_paths: Sequence[str | PathLike[str]] = ()) -> list[Repair]:
    """
    Repair the fixable ``findings`` of ``robot`` in place; return what was done.

    ``limit_defaults`` (``lower upper effort velocity``) allow J103 (all four needed) and
    J106 (the zero one needed); ``search_paths`` find the package of a mesh a tensor is
    taken from. Findings suppressed by the caller are not passed in, so they are not
    touched.
    """
    from urdfgenpy_ros.validation.fix_tensor import TensorSources  # meshes: when fixing
    context = _Context(dict(limit_defaults or {}), TensorSources.of(robot, search_paths))
    repairs: list[Repair] = []
    done: set[tuple[str, str]] = set()
    for finding in findings:
        if finding.code not in FIXABLE:
            continue
        owner = _owner(robot, finding)
        if owner is None or (finding.code, finding.element) in done:
            continue
        message = _REPAIRS[finding.code](robot, owner, context)
        if message is not None:
            done.add((finding.code, finding.element))
            repairs.append(Repair(finding.code, finding.element, finding.location, message))
    return repairs


def _owner(robot: RobotModel, finding: ValidationError) -> Link | Joint | None:
    match = _OWNER.match(finding.location.path or '')
    if match is None:
        return None
    kind, name = match.groups()
    if kind == 'link':
        return robot.get_link(name) if robot.has_link(name) else None
    return robot.get_joint(name) if robot.has_joint(name) else None


def _axis(robot: RobotModel, joint: Link | Joint, context: _Context) -> str | None:
    assert isinstance(joint, Joint)
    axis = joint.axis
    norm = math.sqrt(sum(value * value for value in axis)) if axis else 0.0
    if axis is None or not (norm > 0.0 and math.isfinite(norm)):
        return None
    joint.axis = (axis[0] / norm, axis[1] / norm, axis[2] / norm)
    return f'axis {fmt_vec(axis)} normalised to {fmt_vec(joint.axis)}'


def _swap(robot: RobotModel, joint: Link | Joint, context: _Context) -> str | None:
    assert isinstance(joint, Joint)
    limit = joint.limit
    if limit is None or not limit.lower > limit.upper:
        return None
    limit.lower, limit.upper = limit.upper, limit.lower
    return f'<limit> lower and upper swapped: [{fmt(limit.lower)}, {fmt(limit.upper)}]'


def _add_limit(robot: RobotModel, joint: Link | Joint, context: _Context) -> str | None:
    assert isinstance(joint, Joint)
    defaults = context.defaults
    if joint.limit is not None or not all(name in defaults for name in LIMIT_FIELDS):
        return None
    joint.limit = JointLimit(defaults['lower'], defaults['upper'],
                             effort=defaults['effort'], velocity=defaults['velocity'])
    return 'added <limit ' + ' '.join(f'{name}="{fmt(defaults[name])}"'
                                      for name in LIMIT_FIELDS) + '/> from the defaults given'


def _zero_limit(robot: RobotModel, joint: Link | Joint, context: _Context) -> str | None:
    assert isinstance(joint, Joint)
    limit, defaults = joint.limit, context.defaults
    if limit is None or not joint.type.is_movable:
        return None
    changed = []
    for name in ('effort', 'velocity'):
        if getattr(limit, name) == 0.0 and defaults.get(name, 0.0) > 0.0:
            setattr(limit, name, defaults[name])
            changed.append(f'{name} {fmt(defaults[name])}')
    return f'<limit> {" and ".join(changed)} from the defaults given' if changed else None


def _tensor(robot: RobotModel, link: Link | Joint, context: _Context) -> str | None:
    assert isinstance(link, Link)
    inertial = link.inertial
    if inertial is None or not inertial.mass > 0.0:
        return None
    found = context.sources.solid(link)
    if isinstance(found, str):
        return None
    kind, item, solid = found
    values = _rounded(_turned(solid, item.origin.rpy, inertial.origin.rpy))
    inertial.ixx, inertial.ixy, inertial.ixz = values[0], values[1], values[2]
    inertial.iyy, inertial.iyz, inertial.izz = values[3], values[4], values[5]
    turn = from_xyz_rpy(item.origin.xyz, item.origin.rpy)
    centre = tuple(sum(turn[i][j] * solid.origin.xyz[j] for j in range(3)) + turn[i][3]
                   for i in range(3))  # the solid's centre, in the link's frame
    offset = math.dist(centre, inertial.origin.xyz)
    note = (f"; its centre of mass is {offset:.3g} m from the shape's centre"
            if offset > 1e-9 else '')
    what = (f'{kind} mesh {item.geometry.filename!r}' if isinstance(item.geometry, Mesh)
            else f'{kind} {type(item.geometry).__name__.lower()}')
    return (f'inertia replaced by that of its {what} with mass {fmt(inertial.mass)} '
            f'(a solid of uniform density: check it){note}')


def _turned(solid: Inertial, shape_rpy: tuple[float, float, float],
            frame_rpy: tuple[float, float, float]) -> tuple[float, ...]:
    """Return the solid's tensor, turned from the shape's frame into the inertial's."""
    values = (solid.ixx, solid.ixy, solid.ixz, solid.iyy, solid.iyz, solid.izz)
    if shape_rpy == frame_rpy:
        return values
    zero = (0.0, 0.0, 0.0)
    shape = from_xyz_rpy(zero, shape_rpy)
    frame = from_xyz_rpy(zero, frame_rpy)
    turn = [[sum(frame[k][i] * shape[k][j] for k in range(3)) for j in range(3)]
            for i in range(3)]  # frame^T shape
    tensor = solid.tensor
    out = [[sum(turn[i][k] * tensor[k][m] * turn[j][m] for k in range(3) for m in range(3))
            for j in range(3)] for i in range(3)]
    return out[0][0], out[0][1], out[0][2], out[1][1], out[1][2], out[2][2]


def _rounded(values: tuple[float, ...]) -> tuple[float, ...]:
    """Write as 0 a value below 1e-15 of the largest moment: a turn's rounding, not data."""
    floor = 1e-15 * max(abs(value) for value in values)
    return tuple(0.0 if abs(value) < floor else value for value in values)


def _new_root(robot: RobotModel, link: Link | Joint, context: _Context) -> str | None:
    assert isinstance(link, Link)
    if len(robot.roots) != 1 or robot.roots[0] is not link:
        return None
    name = 'base_footprint' if not robot.has_link('base_footprint') else f'{link.name}_root'
    joint = f'{name}_joint'
    if robot.has_link(name) or robot.has_joint(joint):
        return None
    robot.add_link(Link(name))
    robot.add_joint(Joint(joint, JointType.FIXED, name, link.name))
    return (f'added a massless root link {name!r} and fixed joint {joint!r} above it '
            '(KDL ignores the inertia of a root link)')


def missing_defaults(robot: RobotModel, findings: list[ValidationError],
                     limit_defaults: dict[str, float] | None = None,
                     search_paths: Sequence[str | PathLike[str]] = ()) -> list[str]:
    """
    Return, after ``fix``, why J103 and J106 findings are still there: the values missing.

    One sentence per code and set of missing values, naming the joints, e.g. ``J103 not
    fixed for joint 'wrist': --limit-default has no lower, upper (...)``, and one per I202
    and I203 whose link has no shape a tensor can be taken from (meshes found through
    ``search_paths``). Empty when every such finding was repaired.
    """
    defaults = dict(limit_defaults or {})
    missing: dict[tuple[str, tuple[str, ...]], list[str]] = {}
    for finding in findings:
        joint = _owner(robot, finding) if finding.code in ('J103', 'J106') else None
        if not isinstance(joint, Joint):
            continue
        if finding.code == 'J103' and joint.limit is None:
            lacking = tuple(name for name in LIMIT_FIELDS if name not in defaults)
        elif finding.code == 'J106' and joint.limit is not None:
            lacking = tuple(name for name in ('effort', 'velocity')
                            if getattr(joint.limit, name) == 0.0
                            and not defaults.get(name, 0.0) > 0.0)
        else:
            continue
        names = missing.setdefault((finding.code, lacking), [])
        if lacking and joint.name not in names:
            names.append(joint.name)
    lines = []
    for (code, lacking), joints in missing.items():
        if not joints:
            continue
        why = ('a missing <limit> is added only with all four values'
               if code == 'J103' else 'a zero effort or velocity is replaced by a positive '
               'value')
        example = ','.join(f'{name}=...' for name in lacking)
        lines.append(f'{code} not fixed for joint {", ".join(map(repr, joints))}: '
                     f'--limit-default has no {"positive " if code == "J106" else ""}'
                     f'{", ".join(lacking)} ({why}: add --limit-default {example})')
    return lines + _shapeless(robot, findings, search_paths)


def _shapeless(robot: RobotModel, findings: list[ValidationError],
               search_paths: Sequence[str | PathLike[str]]) -> list[str]:
    """Return why I202/I203 findings stay: no shape, or no mesh, to take a tensor from."""
    links: dict[tuple[str, str], list[str]] = {}
    sources = None
    for finding in findings:
        link = _owner(robot, finding) if finding.code in ('I202', 'I203') else None
        if not isinstance(link, Link) or link.inertial is None:
            continue
        reason = ''
        if link.inertial.mass > 0.0:
            from urdfgenpy_ros.validation.fix_tensor import TensorSources
            sources = sources or TensorSources.of(robot, search_paths)
            found = sources.solid(link)
            if not isinstance(found, str):
                continue
            reason = f' ({found})' if found else ''
        names = links.setdefault((finding.code, reason), [])
        if link.name not in names:
            names.append(link.name)
    return [f'{code} not fixed for link {", ".join(map(repr, names))}: no box, cylinder, sphere '
            f'or capsule, nor a closed mesh, with a positive mass to take a tensor from{reason} '
            '(give it an <inertia>: urdfgenpy inertia MESH --mass KG prints the one of its '
            'mesh)' for (code, reason), names in links.items()]


_REPAIRS = {'J102': _axis, 'J104': _swap, 'J103': _add_limit, 'J106': _zero_limit,
            'I202': _tensor, 'I203': _tensor, 'I205': _new_root}
