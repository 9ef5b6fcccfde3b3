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

"""The urdfgenpy command line."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import (
    assert_check_urdf_accepts, CORPUS, corpus_file, FIXTURES, load_yourdfpy, snapshot,
    xacro_expand)
from urdfgenpy_ros.cli import main


def test_example_prints_the_tree_and_writes_urdf_and_xacro(tmp_path: Path) -> None:
    result = CliRunner().invoke(main, ['example', '--output-dir', str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert 'pan_joint [revolute] → pan_link' in result.output
    urdf, xacro = tmp_path / 'ptu.urdf', tmp_path / 'ptu.urdf.xacro'
    assert_check_urdf_accepts(urdf)
    expanded = tmp_path / 'expanded.urdf'
    expanded.write_text(xacro_expand(xacro))
    assert snapshot(load_yourdfpy(expanded)) == snapshot(load_yourdfpy(urdf))


def test_example_keeps_an_edited_file_without_force(tmp_path: Path) -> None:
    arguments = ['example', '--output-dir', str(tmp_path)]
    assert CliRunner().invoke(main, arguments).exit_code == 0
    assert CliRunner().invoke(main, arguments).exit_code == 0  # as written: written again
    urdf = tmp_path / 'ptu.urdf'
    urdf.write_text(urdf.read_text().replace('name="ptu"', 'name="mine"'))
    result = CliRunner().invoke(main, arguments)
    assert result.exit_code == 2 and result.stderr.count('\n') == 1
    assert 'ptu.urdf exists and differs from the example' in result.stderr
    assert 'name="mine"' in urdf.read_text()
    assert CliRunner().invoke(main, [*arguments, '--force']).exit_code == 0
    assert 'name="ptu"' in urdf.read_text()
    assert_check_urdf_accepts(urdf)


def test_unwritable_output_is_one_line_and_exit_2(tmp_path: Path) -> None:
    blocker = tmp_path / 'file'
    blocker.write_text('x')
    result = CliRunner().invoke(main, ['example', '-o', str(blocker / 'sub')])
    assert result.exit_code == 2
    assert result.stdout == ''
    assert result.stderr.count('\n') == 1 and result.stderr.startswith('urdfgenpy: ')
    assert 'file/sub: Not a directory' in result.stderr


def test_tree_of_a_xacro_with_arguments_and_package_path() -> None:
    arm = FIXTURES / 'packages/fixture_description/urdf/arm.urdf.xacro'
    result = CliRunner().invoke(main, ['tree', str(arm), 'dof:=6', 'gripper:=true',
                                       '--package-path', str(FIXTURES / 'packages')])
    assert result.exit_code == 0, result.output
    assert result.stdout.startswith('robot fixture_arm: 8 links, 7 joints')
    assert 'gripper_mount [fixed] → gripper (mesh)' in result.stdout


def test_broken_file_is_one_line_exit_2_and_verbose_shows_the_traceback() -> None:
    path = FIXTURES / 'broken/bracket_in_rpy.urdf'
    result = CliRunner().invoke(main, ['tree', str(path)])
    assert result.exit_code == 2
    assert result.stderr == (f"urdfgenpy: {path}:9:27: error P003 <origin>: rpy '0 0 1 }}' "
                             'must be 3 numbers separated by spaces\n')
    verbose = CliRunner().invoke(main, ['--verbose', 'tree', str(path)])
    assert verbose.exit_code == 2 and 'Traceback' in verbose.stderr


def test_convert_urdf_to_xacro_and_back_keeps_the_model(tmp_path: Path) -> None:
    source = FIXTURES / 'packages/fixture_description/urdf/every_element.urdf'
    xacro, back = tmp_path / 'every.urdf.xacro', tmp_path / 'every.urdf'
    assert CliRunner().invoke(main, ['convert', str(source), str(xacro)]).exit_code == 0
    result = CliRunner().invoke(main, ['convert', str(xacro), str(back)])
    assert result.exit_code == 0, result.output
    assert snapshot(load_yourdfpy(back)) == snapshot(load_yourdfpy(source))
    refused = CliRunner().invoke(main, ['convert', str(source), str(back)])
    assert refused.exit_code == 2 and 'pass --force' in refused.stderr
    assert snapshot(load_yourdfpy(back)) == snapshot(load_yourdfpy(source))


def test_warnings_go_to_stderr() -> None:
    result = CliRunner().invoke(main, ['tree', str(FIXTURES / 'robots/misspelt_declaration.urdf')])
    assert result.exit_code == 0
    assert 'warning P102' in result.stderr and 'warning' not in result.stdout


def test_check_exit_codes_and_summary(tmp_path: Path) -> None:
    from validation_fixtures import broken, VALID
    valid, bad = tmp_path / 'valid.urdf', tmp_path / 'bad.urdf'
    valid.write_text(VALID)
    bad.write_text(broken('J104'))
    clean = CliRunner().invoke(main, ['check', str(valid)])
    assert (clean.exit_code, clean.stdout) == (0, '')
    failed = CliRunner().invoke(main, ['check', str(valid), str(bad)])
    assert failed.exit_code == 1
    assert failed.stdout.count('\n') == 1 and ' error J104 ' in failed.stdout
    assert failed.stderr == '2 file(s): 1 error(s), 0 warning(s), 0 unreadable\n'
    unreadable = CliRunner().invoke(main, ['check', str(valid),
                                           str(FIXTURES / 'broken/bracket_in_rpy.urdf')])
    assert unreadable.exit_code == 2 and 'error P003' in unreadable.stdout


def test_check_strict_and_json(tmp_path: Path) -> None:
    import json
    from validation_fixtures import broken
    warned = tmp_path / 'warned.urdf'
    warned.write_text(broken('J102'))
    assert CliRunner().invoke(main, ['check', str(warned)]).exit_code == 0
    assert CliRunner().invoke(main, ['check', '--strict', str(warned)]).exit_code == 1
    result = CliRunner().invoke(main, ['check', '--format', 'json', str(warned)])
    report = json.loads(result.stdout)
    assert report['warnings'] == 1 and report['files'][0]['findings'][0]['code'] == 'J102'


def test_check_xacro_with_arguments() -> None:
    result = CliRunner().invoke(main, ['check', str(
        FIXTURES / 'packages/fixture_description/urdf/arm.urdf.xacro'), 'dof:=4',
        'gripper:=true', '-p', str(FIXTURES / 'packages')])
    assert result.exit_code == 0, result.output


def test_check_corpus_xacro_with_arguments() -> None:
    ur = corpus_file('ur_description/urdf/ur.urdf.xacro')
    result = CliRunner().invoke(main, ['check', '--no-meshes', str(ur), 'name:=ur',
                                       'ur_type:=ur5e', '-p', str(CORPUS)])
    assert result.exit_code == 0, result.output


def test_meshlab_figures_pasted_as_printed_negative_numbers_included() -> None:
    rows = ['8171479.5', '-1091.582153', '858.932007', '-1091.582153', '6636559.0',
            '29447.435547', '858.932007', '29447.435547', '2481984.75']
    figures = ['inertia', '--meshlab', '--mass', '0.0105', '--volume', '15253.618164']
    pasted = CliRunner().invoke(main, [*figures, '--tensor', *rows])
    quoted = CliRunner().invoke(main, [*figures, '--tensor', ' '.join(rows)])
    assert pasted.exit_code == 0, pasted.output
    assert pasted.stdout == quoted.stdout
    # Gazebo's inertia tutorial prints these for the same figures (16 decimals).
    for name, printed in (('ixx', '0.0000056249300217'), ('ixy', '-0.0000000007514029')):
        value = float(pasted.stdout.split(f'{name}="')[1].split('"')[0])
        assert f'{value:.16f}' == printed


def test_a_file_nothing_reads_names_what_can_be_read(tmp_path: Path) -> None:
    mesh = tmp_path / 'part.STL'
    mesh.write_text('solid part\nendsolid part\n')
    result = CliRunner().invoke(main, ['tree', str(mesh)])
    assert result.exit_code == 2 and result.output.count('\n') == 1, result.output
    assert "unknown suffix '.stl' (urdfgenpy reads .urdf, .xacro and .urdf.xacro" \
        in result.output and '.sdf' not in result.output
