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
DH tables in YAML or CSV (format in docs/dh_guide.md); angles in degrees on request.

YAML: ``convention``, optional ``degrees``, ``base`` and ``tool`` (``xyz``, ``rpy``), and
``rows`` of mappings. CSV: ``# convention: ...`` and ``# degrees: ...`` comment lines, then
a header row naming the columns.
"""

from __future__ import annotations

from collections.abc import Callable
import csv
import io
import math
from os import PathLike
from pathlib import Path
from typing import Any, TypeVar

from urdfgenpy_ros.model.dh_row import DHConvention, DHRow
from urdfgenpy_ros.model.dh_skeleton import Table
from urdfgenpy_ros.model.errors import (MissingDependencyError, ModelError, ParseError,
                                        SourceLocation)
from urdfgenpy_ros.model.geometry import Origin

Built = TypeVar('Built')
"""What ``cls`` builds: a ``dh.DHTable`` or a ``dh_skeleton.TableRows``."""


COLUMNS = ('joint', 'a', 'alpha', 'd', 'theta_offset', 'type', 'lower', 'upper', 'effort',
           'velocity')
_ANGLES = ('alpha', 'theta_offset')


def _yaml() -> Any:
    try:
        import yaml
    except ImportError:
        raise MissingDependencyError('yaml', 'yaml', 'Reading DH tables in YAML') from None
    return yaml


def _row(values: dict[str, Any], degrees: bool, where: SourceLocation) -> DHRow:
    unknown = set(values) - set(COLUMNS)
    if unknown:
        names = ', '.join(sorted(map(str, unknown)))
        raise ParseError(f'DH row: unknown column(s) {names} (columns are '
                         f'{", ".join(COLUMNS)})', where, 'D001')
    if 'joint' not in values:
        raise ParseError("DH row: missing 'joint' (a number or a name)", where, 'D001')
    kind = str(values.get('type') or 'revolute')
    numbers: dict[str, float | None] = {}
    for column in ('a', 'alpha', 'd', 'theta_offset', 'lower', 'upper', 'effort', 'velocity'):
        raw = values.get(column)
        if raw is None or raw == '':
            numbers[column] = None
            continue
        try:
            numbers[column] = float(raw)
        except (TypeError, ValueError):
            raise ParseError(f'DH row {values["joint"]}: {column} {raw!r} is not a number',
                             where, 'D002') from None
    angular_limits = kind != 'prismatic'
    for column in (*_ANGLES, *(('lower', 'upper') if angular_limits else ())):
        if degrees and numbers[column] is not None:
            numbers[column] = math.radians(numbers[column])  # type: ignore[arg-type]
    joint = values['joint']
    joint = int(joint) if isinstance(joint, int) or str(joint).isdigit() else str(joint)
    free = kind == 'continuous'  # without effort and velocity: no <limit>, as in URDF
    try:
        return DHRow(joint, numbers['a'] or 0.0, numbers['alpha'] or 0.0, numbers['d'] or 0.0,
                     numbers['theta_offset'] or 0.0, kind, lower=numbers['lower'],
                     upper=numbers['upper'],
                     effort=numbers['effort'] if free or numbers['effort'] is not None
                     else 100.0,
                     velocity=numbers['velocity'] if free or numbers['velocity'] is not None
                     else 2.0)
    except ValueError as error:
        raise ParseError(str(error), where, 'D002') from None


def _origin(data: Any, degrees: bool, where: SourceLocation) -> Origin:
    if data is None:
        return Origin()
    try:
        xyz = tuple(float(v) for v in data.get('xyz', (0, 0, 0)))
        rpy = tuple(float(v) for v in data.get('rpy', (0, 0, 0)))
    except (AttributeError, TypeError, ValueError):
        raise ParseError('base/tool must be {xyz: [x, y, z], rpy: [r, p, y]}', where,
                         'D002') from None
    if degrees:
        rpy = tuple(math.radians(v) for v in rpy)
    return Origin(xyz, rpy)


def _convention(value: Any, where: SourceLocation) -> DHConvention:
    try:
        return DHConvention(str(value).strip().lower())
    except ValueError:
        raise ParseError(f"convention {value!r} is neither 'standard' nor 'modified'", where,
                         'D003') from None


def read_table(path: str | PathLike[str], cls: Callable[..., Built]) -> Built:
    """
    Read a DH table (a ``cls``) from a .yaml/.yml or .csv file.

    :raises ParseError: naming the file, the line where known, and the fix.
    """
    file = Path(path)
    text = file.read_text(encoding='utf-8')
    if file.suffix.lower() in ('.yaml', '.yml'):
        return _read_yaml(text, str(path), cls)
    if file.suffix.lower() == '.csv':
        return _read_csv(text, str(path), cls)
    raise ParseError(f'unknown DH table suffix {file.suffix!r} (use .yaml, .yml or .csv)',
                     SourceLocation(str(path)), 'D001')


def _read_yaml(text: str, file: str, cls: Callable[..., Built]) -> Built:
    yaml = _yaml()
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as error:
        mark = getattr(error, 'problem_mark', None)
        where = SourceLocation(file, mark.line + 1, mark.column + 1) if mark else \
            SourceLocation(file)
        raise ParseError(f'YAML syntax: {getattr(error, "problem", error)}', where,
                         'D001') from None
    where = SourceLocation(file, 1, 1)
    if not isinstance(data, dict) or 'rows' not in data or 'convention' not in data:
        raise ParseError("a DH table needs 'convention' and 'rows'", where, 'D001')
    if not isinstance(data['rows'], list):
        raise ParseError("'rows' is a list of rows (- {joint: 1, a: 0.0, ...})", where, 'D001')
    degrees = bool(data.get('degrees', False))
    rows = []
    lines = text.splitlines()
    for index, values in enumerate(data['rows']):
        line = _yaml_row_line(lines, index)
        if not isinstance(values, dict):
            raise ParseError('each DH row is a mapping {joint: ..., a: ..., ...}',
                             SourceLocation(file, line, 1), 'D001')
        rows.append(_row(values, degrees, SourceLocation(file, line, 1)))
    return cls(_convention(data['convention'], where), rows,
               base=_origin(data.get('base'), degrees, where),
               tool=_origin(data.get('tool'), degrees, where))


def _yaml_row_line(lines: list[str], index: int) -> int:
    """Return the line of the ``index``-th item under ``rows:`` (best effort)."""
    seen = -1
    inside = False
    for number, line in enumerate(lines, start=1):
        if line.startswith('rows:'):
            inside = True
        elif inside and line.lstrip().startswith('- '):
            seen += 1
            if seen == index:
                return number
    return 1


def _read_csv(text: str, file: str, cls: Callable[..., Built]) -> Built:
    settings: dict[str, str] = {}
    body = []
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if stripped.startswith('#'):
            key, _, value = stripped[1:].partition(':')
            settings[key.strip().lower()] = value.strip()
        elif stripped:
            body.append((number, line))
    if not body:
        raise ParseError('no header row (joint,a,alpha,d,theta_offset,type,...)',
                         SourceLocation(file, 1, 1), 'D001')
    header_line, header = body[0]
    columns = [column.strip() for column in next(csv.reader([header]))]
    degrees = settings.get('degrees', 'false').lower() in ('1', 'true', 'yes')
    rows = []
    for number, line in body[1:]:
        cells = [cell.strip() for cell in next(csv.reader(io.StringIO(line)))]
        where = SourceLocation(file, number, 1)
        if len(cells) != len(columns):
            raise ParseError(f'{len(cells)} cells for {len(columns)} columns', where, 'D001')
        rows.append(_row(dict(zip(columns, cells)), degrees, where))
    where = SourceLocation(file, 1, 1)
    return cls(_convention(settings.get('convention', ''), where), rows)


def write_table(table: Table, path: str | PathLike[str], degrees: bool = False) -> None:
    """Write ``table`` as YAML or CSV by suffix; angles in degrees when asked."""
    def angle(value: float) -> float:
        return math.degrees(value) if degrees else value

    rows = []
    for row in table.rows:
        limits: tuple[float | None, ...] = (row.lower, row.upper)
        if row.turns:
            limits = tuple(None if v is None else angle(v) for v in limits)
        rows.append({'joint': row.joint, 'a': row.a, 'alpha': angle(row.alpha), 'd': row.d,
                     'theta_offset': angle(row.theta_offset), 'type': row.joint_type,
                     'lower': limits[0], 'upper': limits[1], 'effort': row.effort,
                     'velocity': row.velocity})
    file = Path(path)
    if file.suffix.lower() == '.csv':
        if not (table.base.is_identity and table.tool.is_identity):
            raise ModelError(f'{file}: this table has a base or tool transform, which CSV '
                             'cannot hold: write .yaml')
        buffer = io.StringIO()
        buffer.write(f'# convention: {table.convention.value}\n# degrees: '
                     f'{str(degrees).lower()}\n')
        writer = csv.DictWriter(buffer, fieldnames=COLUMNS, lineterminator='\n')
        writer.writeheader()
        writer.writerows(rows)
        file.write_text(buffer.getvalue(), encoding='utf-8')
        return
    data = {'convention': table.convention.value, 'degrees': degrees,
            'base': {'xyz': list(table.base.xyz), 'rpy': [angle(v) for v in table.base.rpy]},
            'tool': {'xyz': list(table.tool.xyz), 'rpy': [angle(v) for v in table.tool.rpy]},
            'rows': rows}
    file.write_text(_yaml().safe_dump(data, sort_keys=False), encoding='utf-8')
