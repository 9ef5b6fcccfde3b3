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

"""The files ``check`` reads: a folder stands for every description file under it."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import click

from urdfgenpy_ros.model.errors import UrdfgenpyError

DESCRIPTION_SUFFIXES = ('.urdf', '.xacro')
"""What a folder given to ``check`` is searched for (``.urdf.xacro`` included)."""


def description_files(items: Sequence[str]) -> list[Path]:
    """
    Return the files ``items`` name, each folder replaced by the description files under it.

    Hidden folders are passed by, as linters do. An item that is no file but looks like a
    Xacro argument written with ``=`` gets the spelling with ``:=`` suggested.
    """
    files: list[Path] = []
    for item in items:
        path = Path(item)
        if path.is_dir():
            found = sorted(
                child for child in path.rglob('*')
                if child.suffix.lower() in DESCRIPTION_SUFFIXES and child.is_file()
                and not any(part.startswith('.') for part in child.relative_to(path).parts))
            if not found:
                raise UrdfgenpyError(f'{item}: a folder with no .urdf or .xacro file under it '
                                     '(give the description files or their folder)')
            files += found
        elif '=' in item and not path.exists():
            name, _, value = item.partition('=')
            raise click.BadParameter(f'{item!r} is not a file; a Xacro argument is written '
                                     f'name:=value ({name}:={value})',
                                     param_hint='FILE... [NAME:=VALUE]...')
        else:
            files.append(path)
    return files
