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
Reading and writing robot descriptions, chosen by file suffix.

The formats are the rows of :data:`urdfgenpy_ros.formats.table.FORMATS`; ``load`` and
``save`` are the one front door every front end goes through.
"""

from __future__ import annotations

from os import PathLike
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.formats.table import find_format, FORMATS, load, writer_for

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

WRITERS = {suffix: row.name for row in FORMATS if row.writer for suffix in row.suffixes}
"""Written suffix -> format name (derived from the table)."""
DH_SUFFIXES = next(row.suffixes for row in FORMATS if row.name == 'dh')

__all__ = ['DH_SUFFIXES', 'find_format', 'format_of', 'FORMATS', 'load', 'save', 'WRITERS']


def format_of(path: str | PathLike[str]) -> str:
    """
    Return the name of the format that writes ``path`` (``urdf``, ``xacro``, ``sdf``, ``mjcf``).

    :raises ModelError: one line, for a suffix no format writes.
    """
    return writer_for(path).name


def save(robot: RobotModel, path: str | PathLike[str], **options: Any) -> None:
    """
    Write ``robot`` to ``path`` in the format its suffix names, with the writer's options.

    :raises ModelError: for a suffix no format writes, or an option its writer lacks.
    """
    row = writer_for(path)
    unknown = sorted(set(options) - set(row.options))
    if unknown:
        from urdfgenpy_ros.errors import ModelError
        raise ModelError(f'{path}: {row.description} output takes no option '
                         f"{', '.join(unknown)} (it takes {', '.join(row.options) or 'none'})")
    assert row.writer is not None
    row.writer(robot, path, **options)
