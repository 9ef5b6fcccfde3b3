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


"""``check --fix``'s write: the repaired robot over its URDF file, only its repairs changed."""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def repaired_text(robot: RobotModel, path: Path) -> tuple[str, str]:
    """Return the text of ``path`` and the text of ``robot`` written over it (both decoded)."""
    from urdfgenpy_ros.formats.urdf import urdf_file_bytes
    old = path.read_bytes().decode('utf-8', 'surrogateescape')  # other bytes stay
    # the writer copies all the repairs left alone from the file as it is
    new = urdf_file_bytes(robot, mend=False).decode('utf-8', 'surrogateescape')
    return old, new


def unified_diff(path: Path, old: str, new: str) -> str:
    """Return the unified diff from ``old`` to ``new``, both named by ``path``."""
    import difflib  # only for --fix --dry-run (start-up)
    return ''.join(difflib.unified_diff(
        old.splitlines(keepends=True), new.splitlines(keepends=True),
        f'a/{path.as_posix()}', f'b/{path.as_posix()}'))


def read_written(robot: RobotModel, path: Path, text: str) -> RobotModel:
    """Return the robot read back from ``text``, the file written at ``path``."""
    from urdfgenpy_ros.formats._xml import xml_bytes
    from urdfgenpy_ros.formats.urdf_read import read_urdf_bytes
    return read_urdf_bytes(xml_bytes(text, 'surrogateescape'), str(path), type(robot))


def replace_file(path: Path, text: str) -> None:
    """Write ``text`` over ``path`` atomically, keeping its permissions (and symlinks)."""
    path = path.resolve()
    mode = path.stat().st_mode
    import tempfile  # only for --fix (start-up)
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f'.{path.name}.')
    try:
        with os.fdopen(handle, 'wb') as stream:
            stream.write(text.encode('utf-8', 'surrogateescape'))
        os.chmod(temporary, mode & 0o7777)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
