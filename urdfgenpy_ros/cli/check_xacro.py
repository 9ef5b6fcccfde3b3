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

"""``check --fix`` on a Xacro file: edit the values in the Xacro text, or say why not."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
import difflib
from os import PathLike
from pathlib import Path

import click

from urdfgenpy_ros.cli.check_reports import FileReport
from urdfgenpy_ros.formats.urdf_read import read_urdf_bytes
from urdfgenpy_ros.formats.xacro_map import XacroMap
from urdfgenpy_ros.formats.xacro_mapped import shown
from urdfgenpy_ros.formats.xacro_read import expand_xacro
from urdfgenpy_ros.model.errors import ParseError, Severity
from urdfgenpy_ros.resources import PackageResolver
from urdfgenpy_ros.robot import Robot
from urdfgenpy_ros.validation.checklist import Review
from urdfgenpy_ros.validation.xacro_fix import apply_fix, edited, plan_fix, XacroEdit


def fix_xacro(path: Path, robot: Robot, found: Review, mappings: Mapping[str, str],
              search_paths: Sequence[str | PathLike[str]], dry_run: bool,
              report: FileReport, replace: Callable[[Path, str], None]) -> bool:
    """
    Repair ``robot`` (read from Xacro ``path``) by editing its Xacro files; return if done.

    Each repair is tried alone on a copy: one that only changes values becomes edits of
    the Xacro text; one that adds or removes elements is refused (``report.refused``
    says which and why). The edits are kept only when the edited files expand, with the
    real xacro, to the repaired robot; otherwise nothing is written.
    """
    source_map = robot.source_map
    assert source_map is not None
    accepted, refused, edits = plan_fix(found, source_map)
    texts = edited(list(edits.values())) if accepted else None
    repairs = apply_fix(found, accepted) if texts is not None else []
    if texts is not None and not _expands_to(path, mappings, search_paths, texts, robot):
        refused += [(finding, 'the edited Xacro does not expand to the repaired robot')
                    for finding in accepted]
        texts, repairs = None, []
    if refused:
        said = '; '.join(f'{finding.code} {finding.element}: {why}' for finding, why in refused)
        report.refused = (f'{path}: not fixed: {said}: repair '
                          f'{"it" if len(refused) == 1 else "them"} by hand (the lines above '
                          f'say where), or {repaired_copy(path, refused)}')
    if texts is None:
        return False
    report.repairs = repairs
    lines: dict[tuple[str, int], list[XacroEdit]] = {}
    for edit in edits.values():
        lines.setdefault((edit.file, edit.line), []).append(edit)
    report.notes += [_note(same, str(path)) for same in lines.values()]
    for file, text in texts.items():
        if dry_run:
            old = Path(file).read_text(encoding='utf-8')
            name = shown(file, str(path))
            click.echo(''.join(difflib.unified_diff(
                old.splitlines(keepends=True), text.splitlines(keepends=True),
                f'a/{name}', f'b/{name}')), nl=False)
        else:
            replace(Path(file), text)
    return not dry_run


def _expands_to(path: Path, mappings: Mapping[str, str],
                search_paths: Sequence[str | PathLike[str]], texts: Mapping[str, str],
                robot: Robot) -> bool:
    """Return whether the real xacro expands the edited ``texts`` to ``robot``."""
    maps: list[XacroMap] = []
    try:
        text, _ = expand_xacro(path, mappings, PackageResolver(search_paths), maps=maps,
                               texts=texts)
        again = read_urdf_bytes(text.encode('utf-8'), f'{path} (expanded)')
    except ParseError:
        return False
    return again == robot


def _note(edits: list[XacroEdit], main: str) -> str:
    """Return the line that says what the edits of one line changed, and what else."""
    first = edits[0]
    changes = ', '.join(f'{edit.name}="{edit.old}" is now "{edit.new}"' for edit in edits)
    said = f'{shown(first.file, main)}:{first.line}:{first.column}: note: {changes}'
    if first.made == 0:
        return f'{said} (a property: every use of it changes)'
    if first.macro is not None:
        return (f'{said} (in the body of {first.macro}: every instance of the macro changes, '
                f'{first.made} in this robot)')
    return said


def repaired_copy(path: Path, findings: Sequence[object]) -> str:
    """
    Return how to write a repaired copy of ``path``, a Xacro file, for ``findings``.

    ``convert --fix`` repairs errors only; warnings are repaired by ``check --fix`` on
    the expanded URDF ``convert`` writes. ``findings`` may be (finding, why) pairs.
    """
    items = [item[0] if isinstance(item, tuple) else item for item in findings]
    if any(getattr(item, 'severity', None) is Severity.ERROR for item in items):
        return f'write a repaired copy with urdfgenpy convert {path} OUT.urdf --fix'
    return (f'write the expanded robot with urdfgenpy convert {path} OUT.urdf and repair '
            'that with urdfgenpy check --fix OUT.urdf')
