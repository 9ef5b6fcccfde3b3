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


"""The declared table of formats: one row each, one front door, unknown suffixes refused."""

from __future__ import annotations

import inspect
from pathlib import Path

from click.testing import CliRunner
from helpers import require_module
import pytest

from urdfgenpy_ros.cli import main
from urdfgenpy_ros.formats import find_format, format_of, FORMATS, load, open_description, save
from urdfgenpy_ros.formats.table import readable_suffixes
from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.robot import Robot


def test_every_row_declares_suffixes_and_a_reader_or_writer() -> None:
    names = [row.name for row in FORMATS]
    assert names == sorted(set(names), key=names.index)  # unique
    assert {'urdf', 'xacro', 'sdf', 'dh', 'assembly', 'mjcf'} <= set(names)
    for row in FORMATS:
        assert row.suffixes and (row.reader or row.writer)
        assert row.reader or row.not_read  # a row nobody reads says why, once
    suffixes = [suffix for row in FORMATS for suffix in row.suffixes]
    assert len(suffixes) == len(set(suffixes))


@pytest.mark.parametrize(('name', 'expected'), [
    ('r.urdf', 'urdf'), ('r.urdf.xacro', 'xacro'), ('r.xacro', 'xacro'), ('r.sdf', 'sdf'),
    ('r.xml', 'mjcf'), ('r.MJCF', 'mjcf'), ('arm.assembly.yaml', 'assembly'),
    ('dh.yaml', 'dh'), ('dh.csv', 'dh'), ('r.stl', None)])
def test_a_suffix_names_one_row(name: str, expected: str | None) -> None:
    row = find_format(name)
    assert (row.name if row else None) == expected


def test_xml_means_mjcf_for_writing_and_is_refused_for_reading(tmp_path: Path,
                                                               ptu: Robot) -> None:
    mujoco = require_module('mujoco')
    with pytest.warns(UserWarning, match='M801'):
        ptu.save(tmp_path / 'ptu.xml')
    assert format_of('ptu.xml') == 'mjcf'
    assert mujoco.MjModel.from_xml_path(str(tmp_path / 'ptu.xml')).nbody == 5
    (tmp_path / 'ptu.urdf.xml').write_text(ptu.to_urdf())  # URDF named .xml: not Xacro
    with pytest.raises(UrdfgenpyError, match='reading MJCF is not supported.*rename it '
                                             '.urdf'):
        load(tmp_path / 'ptu.urdf.xml')


def test_save_refuses_options_its_writer_lacks(tmp_path: Path, ptu: Robot) -> None:
    with pytest.raises(UrdfgenpyError, match='takes no option fuse_fixed'):
        save(ptu, tmp_path / 'ptu.urdf', fuse_fixed=True)
    save(ptu, tmp_path / 'ptu.sdf', lump_fixed=True)
    assert '<sdf' in (tmp_path / 'ptu.sdf').read_text()


@pytest.mark.parametrize('name', ['robot.sdf', 'robot.xml', 'robot.obj'])
def test_every_front_end_refuses_a_suffix_it_cannot_read_in_one_line(
        tmp_path: Path, name: str, ptu: Robot) -> None:
    path = tmp_path / name
    path.write_text(ptu.to_urdf())
    for command in (['tree', str(path)], ['check', str(path)],
                    ['convert', str(path), str(tmp_path / 'out.urdf')]):
        result = CliRunner().invoke(main, command)
        assert result.exit_code == 2, (command, result.output)
        lines = result.output.splitlines()
        assert str(path) in lines[0] and 'Traceback' not in result.output
        assert len(lines) == 1 or command[0] == 'check' and lines[1].endswith('1 unreadable')
    with pytest.raises(UrdfgenpyError) as refused:  # the node and the scaffold
        open_description(str(path))
    assert '\n' not in str(refused.value) and name in str(refused.value)
    assembly = tmp_path / 'robot.assembly.yaml'
    assembly.write_text(f'name: r\nparts:\n  - file: {name}\n')
    with pytest.raises(UrdfgenpyError, match=name):
        load(assembly)


def test_the_readers_suffixes_come_from_the_table() -> None:
    assert set(readable_suffixes()) == {'.urdf.xacro', '.xacro', '.urdf', '.assembly.yaml',
                                        '.assembly.yml', '.yaml', '.yml', '.csv'}


def test_each_writers_keywords_are_its_declared_options() -> None:
    from urdfgenpy_ros.formats.mjcf import write_mjcf
    for row in FORMATS:
        if row.writer is None:
            continue
        writer = write_mjcf if row.name == 'mjcf' else row.writer  # its warning wrapper
        taken = list(inspect.signature(writer).parameters)[2:]  # after robot and path
        assert taken == list(row.keywords()), row.name
