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
``check --fix`` on every fixture of the validation suite, judged by independent readers.

The fixed file passes check for the fixed codes; yourdfpy sees exactly the repaired fields
changed (their values computed here from the textbook formulas); the text diff has exactly
the repaired lines; check_urdf and MuJoCo accept what they refused for those codes.
"""

from __future__ import annotations

import difflib
import json
import math
from pathlib import Path
import re

from click.testing import CliRunner
from helpers import check_urdf_verdict, CORPUS, corpus_cases, load_yourdfpy, snapshot
import pytest
from test_validation import mujoco_accepts

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main
from validation_fixtures import broken, defect_line, DEFECTS

DEFAULTS = ['--limit-default', 'lower=-0.5,upper=0.5', '--limit-default',
            'effort=3,velocity=2']

# code: the fields yourdfpy must see changed, with their new values
CYLINDER_SIDE = 1.0 * (3 * 0.03 ** 2 + 0.2 ** 2) / 12  # arm: cylinder r 0.03, l 0.2, 1 kg
CYLINDER_AXIAL = 1.0 * 0.03 ** 2 / 2
TENSOR = [[CYLINDER_SIDE, 0, 0], [0, CYLINDER_SIDE, 0], [0, 0, CYLINDER_AXIAL]]
EXPECTED = {
    'J102': {('joint', 'wrist', 'axis'): [0.0, 1.0, 0.0]},
    'J104': {('joint', 'wrist', 'limit', 'lower'): -1.0,
             ('joint', 'wrist', 'limit', 'upper'): 1.0},
    'J103': {('joint', 'wrist', 'limit', 'effort'): 3.0,
             ('joint', 'wrist', 'limit', 'velocity'): 2.0,
             ('joint', 'wrist', 'limit', 'lower'): -0.5,
             ('joint', 'wrist', 'limit', 'upper'): 0.5},
    'J106': {('joint', 'wrist', 'limit', 'velocity'): 2.0},
    'I202': {('link', 'arm', 'inertial', 'inertia'): TENSOR},
    'I203': {('link', 'arm', 'inertial', 'inertia'): TENSOR},
}
FIXED = {*EXPECTED, 'I205'}


def _model(path: Path) -> dict:
    """Return yourdfpy's model as {(kind, name, field...): value}."""
    robot = snapshot(load_yourdfpy(path))
    flat: dict = {}

    def walk(prefix: tuple, value) -> None:
        if isinstance(value, dict):
            for key, item in value.items():
                walk((*prefix, key), item)
        else:
            flat[prefix] = value
    for kind in ('link', 'joint'):
        for item in robot[f'{kind}s']:
            for key, value in item.items():
                walk((kind, item['name'], key), value)
    return flat


def _changed(before: dict, after: dict) -> dict:
    return {key: after.get(key) for key in before.keys() | after.keys()
            if before.get(key) != after.get(key)}


def _close(value, expected) -> bool:
    if isinstance(expected, list):
        return len(value) == len(expected) and all(map(_close, value, expected))
    return math.isclose(value, expected, rel_tol=1e-12, abs_tol=1e-15)


def _diff(old: str, new: str) -> tuple[list[int], list[str]]:
    """Return the removed line numbers (1-based, of ``old``) and the added lines."""
    removed, added = [], []
    matcher = difflib.SequenceMatcher(None, old.splitlines(), new.splitlines())
    for tag, a0, a1, b0, b1 in matcher.get_opcodes():
        if tag != 'equal':
            removed += range(a0 + 1, a1 + 1)
            added += new.splitlines()[b0:b1]
    return removed, added


@pytest.mark.parametrize('key', DEFECTS)
def test_fix_every_validation_fixture(key: str, tmp_path: Path) -> None:
    text = broken(key)
    path = tmp_path / f'{key}.urdf'
    path.write_text(text)
    before = {f.code for f in Robot.from_urdf(path).validate()}
    result = CliRunner().invoke(main, ['check', '--fix', *DEFAULTS, str(path)])
    after_text = path.read_text()
    after = {f.code for f in Robot.from_urdf(path).validate()}
    if key not in FIXED:
        assert after_text == text, 'a finding with no single right answer was changed'
        assert after == before and f' {key} ' in result.stdout
        assert ': fixed ' not in result.stdout
        return
    assert f'fixed {key} ' in result.stdout and key not in after
    assert after == before - {key}
    errors = [f for f in Robot.from_urdf(path).validate() if f.severity == 'error']
    assert result.exit_code == (1 if errors else 0)
    removed, added = _diff(text, after_text)
    changes = _changed(_original(tmp_path, text), _model(path))
    if key == 'I205':
        assert removed == []
        assert [line.strip() for line in added] == [
            '<link name="base_footprint"/>', '<joint name="base_footprint_joint" type="fixed">',
            '<parent link="base_footprint"/>', '<child link="base_link"/>', '</joint>']
        assert {key[1] for key in changes} == {'base_footprint', 'base_footprint_joint'}
        assert changes[('joint', 'base_footprint_joint', 'type')] == 'fixed'
        assert changes[('joint', 'base_footprint_joint', 'parent')] == 'base_footprint'
        assert changes[('joint', 'base_footprint_joint', 'child')] == 'base_link'
        assert changes.get(('link', 'base_footprint', 'inertial')) is None
        return
    assert len(added) == 1 and len(removed) <= 1
    if key != 'J103':
        assert removed == [defect_line(text)]
    expected = EXPECTED[key]
    assert set(changes) == set(expected)
    for field, value in expected.items():
        assert _close(changes[field], value), (field, changes[field])
    if key in ('I202', 'I203'):  # MuJoCo refused the model; it takes the fixed one
        assert not mujoco_accepts(_original_path(tmp_path, text)) and mujoco_accepts(path)
    assert check_urdf_verdict(path)


def _original_path(tmp_path: Path, text: str) -> Path:
    original = tmp_path / 'original' / 'robot.urdf'
    original.parent.mkdir(exist_ok=True)
    original.write_text(text)
    return original


def _original(tmp_path: Path, text: str) -> dict:
    return _model(_original_path(tmp_path, text))


@pytest.mark.parametrize('key', ['J103', 'J106'])
def test_limits_are_only_filled_in_from_defaults_the_user_gives(key: str,
                                                                tmp_path: Path) -> None:
    path = tmp_path / f'{key}.urdf'
    path.write_text(broken(key))
    result = CliRunner().invoke(main, ['check', '--fix', str(path)])
    assert path.read_text() == broken(key) and ': fixed ' not in result.stdout
    assert f"{path}: {key} not fixed for joint 'wrist': --limit-default has no " in (
        result.stdout)  # without any: what to give
    partial = ['--limit-default', 'effort=3,velocity=2'] if key == 'J103' else [
        '--limit-default', 'effort=3']
    result = CliRunner().invoke(main, ['check', '--fix', *partial, str(path)])
    assert path.read_text() == broken(key)  # J103 needs all four, J106 the zero one
    lines = result.stdout.splitlines()
    missing = ('lower, upper (', 'lower=...,upper=...)') if key == 'J103' else (
        'positive velocity (', 'velocity=...)')
    (line,) = [line for line in lines if ' not fixed ' in line]
    assert line.startswith(f"{path}: {key} not fixed for joint 'wrist': --limit-default has "
                           f'no {missing[0]}') and line.endswith(missing[1])
    assert lines.index(line) > lines.index(next(x for x in lines if f' {key} ' in x))


def test_limit_defaults_repair_what_they_can_and_name_what_is_missing(tmp_path: Path) -> None:
    # two joints: one lacks its <limit> (J103), the other has a zero velocity (J106)
    text = broken('J103').replace('</robot>', (
        '  <link name="tool"/>\n  <joint name="tool_joint" type="prismatic">\n'
        '    <parent link="arm"/>\n    <child link="tool"/>\n'
        '    <limit lower="0" upper="0.1" effort="1" velocity="0"/>\n  </joint>\n</robot>'))
    path = tmp_path / 'two.urdf'
    path.write_text(text)
    result = CliRunner().invoke(main, ['check', '--fix', '--limit-default', 'velocity=2',
                                       str(path)])
    assert "fixed J106 joint 'tool_joint': <limit> velocity 2 " in result.stdout
    joints = {joint.name: joint for joint in load_yourdfpy(path).joints}
    assert joints['tool_joint'].limit.velocity == 2.0 and joints['wrist'].limit is None
    assert f"{path}: J103 not fixed for joint 'wrist': --limit-default has no lower, upper, " \
        'effort (' in result.stdout


def test_dry_run_prints_the_diff_and_writes_nothing(tmp_path: Path) -> None:
    text = broken('J104')
    path, twin = tmp_path / 'arm.urdf', tmp_path / 'twin' / 'arm.urdf'
    path.write_text(text)
    twin.parent.mkdir()
    twin.write_text(text)
    inode = path.stat().st_ino
    preview = CliRunner().invoke(main, ['check', '--fix', '--dry-run', str(path)])
    assert path.read_text() == text and path.stat().st_ino == inode
    CliRunner().invoke(main, ['check', '--fix', str(twin)])
    expected = ''.join(difflib.unified_diff(text.splitlines(True),
                                            twin.read_text().splitlines(True),
                                            f'a/{path.as_posix()}', f'b/{path.as_posix()}'))
    assert preview.stdout == expected and expected.count('\n-  ') == 1
    assert preview.exit_code == 1  # nothing was written: the file still has the error
    assert 'error J104' in preview.stderr and '1 to fix' in preview.stderr
    assert f"{path}:{defect_line(text)}:5: to fix J104 joint 'wrist'" in preview.stderr
    assert CliRunner().invoke(main, ['check', '--dry-run', str(path)]).exit_code == 2


def test_a_clean_file_is_never_rewritten(tmp_path: Path) -> None:
    path = tmp_path / 'clean.urdf'
    path.write_text(broken('J101'))  # only a finding with no single right answer
    inode = path.stat().st_ino
    result = CliRunner().invoke(main, ['check', '--fix', str(path)])
    assert path.stat().st_ino == inode and path.read_text() == broken('J101')
    assert result.exit_code == 1 and ' error J101 ' in result.stdout


def test_xacro_with_an_expression_to_edit_is_not_fixed_and_says_why(tmp_path: Path) -> None:
    text = broken('J104').replace('<robot name="fixture">', '<robot name="fixture" '
                                  'xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                                  '  <xacro:property name="reach" value="1"/>')
    text = text.replace('upper="-1"', 'upper="${-reach}"')
    for name in ('arm.urdf.xacro', 'arm.urdf'):  # a .urdf that is Xacro too (X101)
        path = tmp_path / name
        path.write_text(text)
        result = CliRunner().invoke(main, ['check', '--fix', str(path)])
        assert path.read_text() == text
        assert result.exit_code == 2 and ' error J104 ' in result.stdout
        lines = result.stdout.splitlines()
        (note,) = [line for line in lines if 'not fixed' in line]
        assert note.startswith(f"{path}: not fixed: J104 joint 'wrist': upper=")
        assert 'is an expression: repair it by hand' in note and note.count('by hand') == 1
        assert lines[-1] == note  # after the findings it refers to


def _assembly(tmp_path: Path) -> tuple[Path, dict[Path, bytes]]:
    """Write an assembly whose arm part has a J104; return it and every file's bytes."""
    (tmp_path / 'arm.urdf').write_text(broken('J104'))
    (tmp_path / 'base.urdf').write_text(
        '<?xml version="1.0"?>\n<robot name="base">\n  <link name="base"/>\n</robot>\n')
    path = tmp_path / 'rover.assembly.yaml'
    path.write_text('parts:\n  - file: base.urdf\n  - file: arm.urdf\n    at: base\n'
                    '    prefix: arm_\n')
    return path, {item: item.read_bytes() for item in tmp_path.iterdir()}


@pytest.mark.parametrize('dry_run', [[], ['--dry-run']])
def test_an_assembly_file_is_not_fixed_and_names_where_to_fix(dry_run: list[str],
                                                              tmp_path: Path) -> None:
    path, files = _assembly(tmp_path)
    result = CliRunner().invoke(main, ['check', '--fix', *dry_run, str(path)])
    assert {item: item.read_bytes() for item in tmp_path.iterdir()} == files
    assert result.exit_code == 2 and 'please report' not in result.output
    lines = (result.stderr if dry_run else result.stdout).splitlines()
    (finding,) = [line for line in lines if ' J104 ' in line]
    assert finding.startswith(f'{tmp_path / "arm.urdf"}:')  # where to fix it: the part
    (note,) = [line for line in lines if 'not fixed' in line]
    assert note.startswith(f'{path}: not fixed: it is an assembly file')
    assert lines.index(note) > lines.index(finding)  # after the finding it refers to
    assert not dry_run or result.stdout == ''  # no diff
    assert CliRunner().invoke(main, ['check', str(path)]).exit_code == 1  # without --fix
    report = json.loads(CliRunner().invoke(main, ['check', '--fix', '--format', 'json',
                                                  str(path)]).stdout)
    assert report['not_fixed'] == 1 and report['files'][0]['not_fixed'] == note


def test_a_dh_table_is_not_fixed(tmp_path: Path) -> None:
    path = tmp_path / 'arm.csv'
    text = ('# convention: standard\njoint,a,alpha,d,theta_offset,type,lower,upper\n'
            'shoulder,0,0,0.1,0,revolute,1,-1\n')
    path.write_text(text)
    result = CliRunner().invoke(main, ['check', '--fix', str(path)])
    assert result.exit_code == 2 and path.read_text() == text
    assert result.stdout.splitlines()[-1].startswith(f'{path}: not fixed: it is a DH table')


def test_the_fixed_file_keeps_crlf_and_comments(tmp_path: Path) -> None:
    text = broken('J102').replace('<joint name="wrist"', '<!-- the wrist -->\n  <joint '
                                  'name="wrist"')
    path = tmp_path / 'crlf.urdf'
    path.write_bytes(text.replace('\n', '\r\n').encode())
    CliRunner().invoke(main, ['check', '--fix', str(path)])
    fixed = path.read_bytes().decode()
    assert fixed == text.replace('<axis xyz="0 2 0"/>', '<axis xyz="0 1 0"/>').replace(
        '\n', '\r\n')


def test_tensor_of_a_turned_box_is_turned_into_the_inertial_frame(tmp_path: Path) -> None:
    cylinder = ('<collision>\n      <origin xyz="0 0 0.1"/>\n      <geometry>'
                '<cylinder radius="0.03" length="0.2"/>')
    turned_box = ('<collision>\n      <origin xyz="0 0 0.1" rpy="0 1.5707963267948966 0"/>'
                  '\n      <geometry><box size="0.3 0.1 0.05"/>')
    text = broken('I203').replace(cylinder, turned_box)
    path = tmp_path / 'box.urdf'
    path.write_text(text)
    CliRunner().invoke(main, ['check', '--fix', str(path)])
    inertia = load_yourdfpy(path).links[1].inertial.inertia
    # the box turned a quarter about y: its 0.3 m side along z, its 0.05 m side along x
    mass, (x, y, z) = 1.0, (0.05, 0.1, 0.3)  # extents along the link's axes
    expected = [mass * (y * y + z * z) / 12, mass * (x * x + z * z) / 12,
                mass * (x * x + y * y) / 12]  # textbook moments of a solid box
    assert [inertia[0][0], inertia[1][1], inertia[2][2]] == pytest.approx(expected, rel=1e-9)
    assert abs(inertia[0][2]) < 1e-15 and mujoco_accepts(path)


def test_a_quarter_turn_writes_its_off_diagonals_as_zero(tmp_path: Path) -> None:
    """A turn's rounding (about 1e-20 here) is written as 0, as the textbook tensor has it."""
    cylinder = ('<collision>\n      <origin xyz="0 0 0.1"/>\n      <geometry>'
                '<cylinder radius="0.03" length="0.2"/>')
    turned = ('<collision>\n      <origin xyz="0 0 0.1" rpy="1.5707963267948966 0 0"/>'
              '\n      <geometry><cylinder radius="0.03" length="0.2"/>')
    path = tmp_path / 'arm.urdf'
    path.write_text(broken('I203').replace(cylinder, turned))
    CliRunner().invoke(main, ['check', '--fix', str(path)])
    inertia = load_yourdfpy(path).links[1].inertial.inertia
    assert inertia[1][1] == pytest.approx(1.0 * 0.03 ** 2 / 2, rel=1e-9)  # axis along y now
    assert [inertia[0][1], inertia[0][2], inertia[1][2]] == [0.0, 0.0, 0.0]
    assert 'e-2' not in path.read_text()


def test_only_repaired_lines_change_where_the_writer_is_not_byte_exact(tmp_path: Path) -> None:
    # a misspelled declaration and blank lines at the end: the writer mends both, --fix not
    text = broken('J104').replace('<?xml version="1.0"?>', '<?xml verison="1.0"?>') + '\n\n'
    path = tmp_path / 'odd.urdf'
    path.write_text(text)
    assert Robot.from_urdf(path).to_urdf() != text
    CliRunner().invoke(main, ['check', '--fix', str(path)])
    removed, added = _diff(text, path.read_text())
    assert removed == [defect_line(text)] and len(added) == 1
    assert path.read_text().endswith('</robot>\n\n\n')


def _corpus_urdfs() -> list[Path]:
    return sorted(CORPUS.rglob('*.urdf')) if CORPUS.is_dir() else []


@pytest.mark.parametrize('path', corpus_cases(
    _corpus_urdfs(), [str(path.relative_to(CORPUS)) for path in _corpus_urdfs()]))
def test_fix_on_the_corpus_changes_only_the_repaired_lines(path: Path, tmp_path: Path) -> None:
    copy = tmp_path / path.name
    copy.write_bytes(path.read_bytes())
    result = CliRunner().invoke(main, ['check', '--fix', '--no-meshes', str(copy)])
    repaired = re.findall(r": fixed (\w+) (\w+) '([^']*)'", result.stdout)
    if not repaired:  # clean, unreadable or only what has no single right answer:
        assert copy.read_bytes() == path.read_bytes()  # the file is left as it was
        return
    original = path.read_bytes().decode()
    removed, added = _diff(original, copy.read_bytes().decode())
    changes = _changed(_model(path), _model(copy))  # as yourdfpy reads both
    allowed, limits = set(), 0
    for code, kind, name in repaired:
        assert code in ('I202', 'I203', 'I205', 'J104'), code  # others: the fixtures
        if code == 'J104':
            limits += 1
            allowed |= {('joint', name, 'limit', 'lower'), ('joint', name, 'limit', 'upper')}
        if code in ('I202', 'I203'):  # one <inertia> line
            limits += 1
            allowed.add(('link', name, 'inertial', 'inertia'))
    added_names = set(re.findall(r"added a massless root link '([^']*)' and fixed joint "
                                 r"'([^']*)'", result.stdout))
    new_items = {name for pair in added_names for name in pair}
    allowed |= {key for key in changes if key[1] in new_items}
    assert set(changes) == allowed
    assert len(removed) == limits and all(
        re.search('<(limit|inertia) ', original.splitlines()[n - 1]) for n in removed)
    assert len(added) == limits + 5 * sum(code == 'I205' for code, _, _ in repaired)
    assert not {code for code, _, _ in repaired} & {
        f.code for f in Robot.from_urdf(copy).validate(check_meshes=False)}


def test_fix_writes_through_a_symlink_and_keeps_the_mode(tmp_path: Path) -> None:
    target, link = tmp_path / 'real.urdf', tmp_path / 'link.urdf'
    target.write_text(broken('J104'))
    target.chmod(0o640)
    link.symlink_to(target)
    CliRunner().invoke(main, ['check', '--fix', str(link)])
    assert link.is_symlink() and 'lower="-1" upper="1" effort="5"' in target.read_text()
    assert target.stat().st_mode & 0o777 == 0o640
