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

"""Reading and writing robot descriptions, chosen by file suffix."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from os import PathLike
from pathlib import Path
from typing import TYPE_CHECKING

from urdfgenpy_ros.errors import ModelError

if TYPE_CHECKING:
    from urdfgenpy_ros.errors import ReadWarning
    from urdfgenpy_ros.formats.detect import XacroEvidence
    from urdfgenpy_ros.robot import Robot

WRITERS = {'.urdf': 'urdf', '.xacro': 'xacro', '.sdf': 'sdf'}
DH_SUFFIXES = ('.yaml', '.yml', '.csv')


def format_of(path: str | PathLike[str]) -> str:
    """Return ``urdf``, ``xacro`` or ``sdf`` for a file name; raise ValueError otherwise."""
    suffix = Path(path).suffix.lower()
    try:
        return WRITERS[suffix]
    except KeyError:
        known = ', '.join(WRITERS)
        raise ModelError(f'{path}: unknown suffix {suffix!r} (use one of {known}, '
                         'or .urdf.xacro)') from None


def load(path: str | PathLike[str], mappings: Mapping[str, str] | None = None,
         search_paths: Iterable[str | PathLike[str]] = ()) -> Robot:
    """
    Read a robot from ``path`` in the format its suffix names.

    ``mappings`` are Xacro arguments; ``search_paths`` folders holding ROS packages. An
    assembly file (``*.assembly.yaml``, or YAML with a top-level ``parts:``) gives the
    robot its parts make; any other .yaml, .yml or .csv file is a DH table and gives its
    skeleton. A ``.urdf`` file that is Xacro (TurtleBot3's are) is expanded with xacro, as
    ROS launch files do, and the robot gets a read warning (X101) saying so.
    """
    from urdfgenpy_ros.robot import Robot
    if Path(path).suffix.lower() in DH_SUFFIXES:
        from urdfgenpy_ros.assembly_file import is_assembly
        if is_assembly(path):  # *.assembly.yaml, or a YAML file with a top-level parts:
            return Robot.from_assembly(path, list(search_paths))
        from urdfgenpy_ros.dh import DHTable
        return DHTable.from_file(path).to_robot(Path(path).name.split('.')[0])
    if Path(path).suffix.lower() not in WRITERS:
        raise ModelError(f'{path}: unknown suffix {Path(path).suffix.lower()!r} (urdfgenpy '
                         'reads .urdf, .xacro and .urdf.xacro files, and DH tables and '
                         'assembly files in .yaml, .yml or .csv)')
    kind = format_of(path)
    if kind == 'sdf':
        raise ModelError(f'{path}: reading SDF is not supported (convert from URDF or Xacro)')
    if kind == 'urdf':
        from urdfgenpy_ros.formats.detect import xacro_evidence_in
        from urdfgenpy_ros.formats.urdf_read import read_urdf_bytes
        data = Path(path).read_bytes()
        evidence = xacro_evidence_in(data, str(path))
        if evidence is None:
            return read_urdf_bytes(data, str(path))
        if evidence.weak:  # only a $(...) in a mesh filename: read as urdfdom does, X104
            return Robot.from_urdf(path)
        robot = Robot.from_xacro(path, dict(mappings or {}), search_paths=list(search_paths))
        robot.read_warnings.insert(0, _read_as_xacro(evidence, mappings))
        return robot
    return Robot.from_xacro(path, dict(mappings or {}), search_paths=list(search_paths))


def _read_as_xacro(evidence: XacroEvidence, mappings: Mapping[str, str] | None) -> ReadWarning:
    from urdfgenpy_ros.errors import ReadWarning
    given = ' '.join(f'{name}:={value}' for name, value in (mappings or {}).items())
    return ReadWarning(evidence.location, 'X101', (
        f'the file is Xacro ({evidence.what}): expanded with xacro '
        f'({"arguments " + given if given else "no arguments"}); plain URDF tools cannot '
        'read it, so name it .urdf.xacro'))


def save(robot: Robot, path: str | PathLike[str]) -> None:
    """Write ``robot`` to ``path`` in the format its suffix names."""
    kind = format_of(path)
    if kind == 'urdf':
        robot.to_urdf(path)
    elif kind == 'xacro':
        robot.to_xacro(path)
    else:
        robot.to_sdf(path)
