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


"""A format added by a test (the toy below, in 36 lines) reaches convert, save and check."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from click.testing import CliRunner
from helpers import assert_check_urdf_accepts, load_yourdfpy
import pytest

from urdfgenpy_ros import Joint, JointLimit, Link, Robot, Severity, SourceLocation
from urdfgenpy_ros import ValidationError
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.formats import save
from urdfgenpy_ros.formats.options import Option
from urdfgenpy_ros.formats.prepare import tree_review
from urdfgenpy_ros.formats.table import Format, registered
from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.model.review import ReviewRecord

LIMIT = ('lower', 'upper', 'effort', 'velocity')


def _read(path: Path, mappings: Any, search_paths: Any) -> Robot:
    data = json.loads(path.read_text())
    robot = Robot(data['name'])
    for name in data['links']:
        robot.add_link(Link(name, source=SourceLocation(str(path), 1)))
    for name, kind, parent, child, limit in data['joints']:
        robot.add_joint(Joint(name, kind, parent, child, limit=limit and JointLimit(
            limit[0], limit[1], effort=limit[2], velocity=limit[3])))
    return robot


def _write(robot: Robot, path: Any, indent: int | None = None) -> str:
    joints = [(j.name, j.type.value, j.parent, j.child, j.limit and [
        getattr(j.limit, field) for field in LIMIT]) for j in robot.joints]
    text = json.dumps({'name': robot.name, 'links': [link.name for link in robot.links],
                       'joints': joints}, indent=indent)
    Path(path).write_text(text) if path is not None else None
    return text


def _prepare(robot: Robot, options: Any) -> ReviewRecord:
    found = tree_review(robot)  # long names are frowned on: check lists them, convert says
    found.findings += [ValidationError(
        'Y901', Severity.WARNING, f'link {link.name!r}', link.source or SourceLocation(),
        'a name over 8 characters', 'toy readers cut it') for link in robot.links
        if len(link.name) > 8]
    found.lines += [str(finding) for finding in found.findings]
    return found


TOY = Format('toy', ('.toy.json',), 'toy', _read, _write, (Option('indent'),),
             prepare=_prepare)


@pytest.fixture
def toy() -> Any:
    """Register the toy format for one test."""
    with registered(TOY) as row:
        yield row


def _run(*words: Any) -> Any:
    return CliRunner().invoke(main, [str(word) for word in words])


def test_convert_writes_and_reads_the_toy(tmp_path: Path, ptu: Robot, toy: Format) -> None:
    ptu.to_urdf(tmp_path / 'ptu.urdf')
    written = _run('convert', tmp_path / 'ptu.urdf', tmp_path / 'ptu.toy.json')
    assert written.exit_code == 0 and 'wrote' in written.stdout, written.output
    assert written.stderr.count('Y901') == 3  # its prepare's lines, said before writing
    back = _run('convert', tmp_path / 'ptu.toy.json', tmp_path / 'back.urdf')
    assert back.exit_code == 0, back.output
    assert_check_urdf_accepts(tmp_path / 'back.urdf')  # urdfdom judges what it wrote
    source, result = load_yourdfpy(tmp_path / 'ptu.urdf'), load_yourdfpy(tmp_path / 'back.urdf')
    assert [link.name for link in result.links] == [link.name for link in source.links]
    assert [(j.name, j.type, j.parent, j.child, j.limit and j.limit.upper)
            for j in result.joints] == [(j.name, j.type, j.parent, j.child,
                                         j.limit and j.limit.upper) for j in source.joints]


def test_save_takes_the_toy_option(tmp_path: Path, ptu: Robot, toy: Format) -> None:
    ptu.save(tmp_path / 'indented.toy.json', indent=2)  # its option, declared once
    text = (tmp_path / 'indented.toy.json').read_text()
    assert json.loads(text)['name'] == ptu.name and '\n  "links"' in text
    with pytest.raises(UrdfgenpyError, match='takes no option fuse_fixed'):
        save(ptu, tmp_path / 'x.toy.json', fuse_fixed=True)


def test_check_reports_what_the_toy_refuses(tmp_path: Path, ptu: Robot, toy: Format) -> None:
    ptu.save(tmp_path / 'ptu.toy.json')
    checked = _run('check', tmp_path / 'ptu.toy.json', '--format', 'json')
    assert checked.exit_code == 0, checked.output  # warnings
    found = json.loads(checked.stdout)['files'][0]['findings']
    assert [finding['element'] for finding in found if finding['code'] == 'Y901'] == [
        "link 'base_link'", "link 'base_plate'", "link 'tilt_link'"]


def test_without_the_toy_its_suffix_is_refused(tmp_path: Path, ptu: Robot) -> None:
    with pytest.raises(UrdfgenpyError, match='unknown suffix'):
        ptu.save(tmp_path / 'ptu.toy.json')


def test_a_row_whose_suffix_is_taken_is_refused() -> None:
    with pytest.raises(UrdfgenpyError, match="format 'toy': its suffix .xml already"):
        with registered(Format('toy', ('.xml',), 'toy', _read, None)):
            pass  # pragma: no cover
    with pytest.raises(UrdfgenpyError, match="format 'urdf': its name already"):
        with registered(Format('urdf', ('.other',), 'URDF again', _read, None)):
            pass  # pragma: no cover
