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

"""Engine pre-flight (check --engines): compared with libsdformat's conversion and MuJoCo."""

from __future__ import annotations

import os
from pathlib import Path
import re
import subprocess

from click.testing import CliRunner
from helpers import (
    build_sdf_checker, check_urdf_verdict, CORPUS, corpus_cases, FIXTURES, parse_xml,
    require_module)
from lxml import etree
import pytest
from registry_robots import absolute_meshes, robot_id, robots, search_paths

from urdfgenpy_ros import ParseError, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.formats.sdf_conversion import sdformat_conversion
from urdfgenpy_ros.model.findings import Findings
from urdfgenpy_ros.validation.mujoco_preflight import _by_rules
from urdfgenpy_ros.validation.preflight import preflight

PREFLIGHT = FIXTURES / 'preflight'


@pytest.fixture(scope='session')
def convert_urdf(tmp_path_factory: pytest.TempPathFactory):
    """Build the libsdformat checker; return a runner printing its conversion of a URDF."""
    binary = build_sdf_checker(tmp_path_factory.mktemp('converter'))

    def run(path: Path) -> tuple[int, str, str]:
        result = subprocess.run([str(binary), '--sdf', str(path)], capture_output=True,
                                text=True, timeout=60)
        return result.returncode, result.stdout, result.stderr
    return run


def _sdf_links(sdf: str) -> dict[str, list[str]]:
    """Return each link of the converted model with its collisions' and visuals' names."""
    model = parse_xml(sdf.encode()).find('model')
    return {link.get('name'): [item.get('name') for item in link
                               if item.tag in ('collision', 'visual')]
            for link in model.iter('link')}


def _compare_with_sdformat(robot: Robot, path: Path, convert_urdf) -> None:
    """Our model of the conversion names exactly the links libsdformat keeps."""
    conversion = sdformat_conversion(robot)
    names = {link.name for link in robot.links}
    kept = names - set(conversion.lumped) - conversion.dropped - {'world'}
    code, sdf, errors = convert_urdf(path)
    if not kept:
        assert code != 0 and 'at least one link' in errors
        return
    assert code == 0, errors
    theirs = _sdf_links(sdf)
    assert set(theirs) == kept
    for name, (into, _) in conversion.lumped.items():  # renamed into the parent
        link = robot.get_link(name)
        if link.collisions or link.visuals:
            assert any(item.startswith(f'{into}_fixed_joint_lump__')
                       for item in theirs[into]), (name, theirs[into])
    # and check reports every lumped link (G601) and every link it leaves out (G602)
    findings = preflight(robot, ['gazebo'])
    lumped = {f.element for f in findings if f.code == 'G601'}
    assert lumped == {f'link {name!r}' for name in conversion.lumped}
    said = set(re.findall(r"'([^']*)'", ' '.join(f'{f.element} {f.message}'
                                                 for f in findings if f.code == 'G602')))
    assert conversion.dropped <= said


@pytest.mark.parametrize('name', ['lumping', 'massless_root', 'world_root'])
@pytest.mark.engine
def test_sdformat_rules_match_libsdformat_on_fixtures(name: str, convert_urdf) -> None:
    path = PREFLIGHT / f'{name}.urdf'
    _compare_with_sdformat(Robot.from_urdf(path), path, convert_urdf)


def test_fixture_conversion_is_what_the_rules_say() -> None:
    conversion = sdformat_conversion(Robot.from_urdf(PREFLIGHT / 'lumping.urdf'))
    assert {name: into for name, (into, _) in conversion.lumped.items()} == {
        'plate': 'base', 'bracket': 'base', 'lidar_frame': 'lidar'}
    assert conversion.dropped == {'upper_arm', 'camera', 'wheel_mount', 'wheel', 'antenna'}


def _readable(path: Path, tmp_path: Path) -> tuple[Robot | None, Path]:
    """Return the robot and a URDF file of it (a Xacro .urdf expanded, as check reads it)."""
    try:
        robot = load(path)
    except ParseError:
        return None, path
    if any(warning.code == 'X101' for warning in robot.read_warnings):
        path = tmp_path / path.name  # TurtleBot3's: libsdformat would read the Xacro as is
        robot.to_urdf(path)
        robot = Robot.from_urdf(path)
    return (robot if len(robot.roots) == 1 else None), path


def _corpus_urdfs() -> list[Path]:
    return sorted(CORPUS.rglob('*.urdf')) if CORPUS.is_dir() else []


def _all_urdfs() -> list:
    corpus = _corpus_urdfs()
    return [*[pytest.param(path, id=robot_id(path)) for path in robots()],
            *corpus_cases(corpus, [str(path.relative_to(CORPUS)) for path in corpus])]


@pytest.mark.parametrize('path', _all_urdfs())
@pytest.mark.engine
def test_sdformat_rules_match_libsdformat_on_real_robots(
        path: Path, convert_urdf, tmp_path: Path) -> None:
    robot, path = _readable(path, tmp_path)
    if robot is None:
        pytest.skip('not a single-root URDF we read as such')
    code, _, errors = convert_urdf(path)
    if code != 0 and 'at least one link' not in errors:
        pytest.skip(f'libsdformat refuses it: {errors.splitlines()[0] if errors else code}')
    _compare_with_sdformat(robot, path, convert_urdf)


def _mujoco_bodies(path: Path) -> set[str] | None:
    """Return the bodies MuJoCo makes of the original file (meshes by absolute path)."""
    mujoco = require_module('mujoco')
    try:
        root = parse_xml(absolute_meshes(path.read_text(), path.parent).encode())
        for mesh in list(root.iter('mesh')):  # meshes the corpus left out: drop them
            shape = mesh.getparent().getparent()
            if not Path(mesh.get('filename', '')).is_file() and shape is not None \
                    and shape.tag in ('visual', 'collision'):
                shape.getparent().remove(shape)
        model = mujoco.MjModel.from_xml_string(etree.tostring(root, encoding='unicode'))
    except Exception:  # noqa: B902 - a refusal: nothing to compare with
        return None
    return {model.body(index).name for index in range(model.nbody)}


@pytest.mark.parametrize('path', _all_urdfs())
@pytest.mark.engine
def test_every_body_mujoco_merges_is_reported(path: Path, tmp_path: Path) -> None:
    robot, path = _readable(path, tmp_path)
    if robot is None:
        pytest.skip('not a single-root URDF we read as such')
    bodies = _mujoco_bodies(path)
    if bodies is None:
        pytest.skip('MuJoCo refuses the original')
    merged = {link.name for link in robot.links} - bodies
    packages = [CORPUS, *search_paths()] if CORPUS.is_dir() else search_paths()
    findings = preflight(robot, ['mujoco'], packages)
    assert not [f for f in findings if f.code == 'M505'], findings
    assert {f.element for f in findings if f.code == 'M501'} == {
        f'link {name!r}' for name in merged}
    by_rules = Findings(robot)  # and the rules used without MuJoCo say the same
    _by_rules(robot, by_rules)
    assert {f.element for f in by_rules.items if f.code == 'M501'} == {
        f'link {name!r}' for name in merged}


def _write_l_shape(path: Path) -> None:
    """Write a closed L-shaped prism (not convex) as OBJ."""
    trimesh = require_module('trimesh')
    outline = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
    vertices = [(x * 0.1, y * 0.1, 0.0) for x, y in outline] + [
        (x * 0.1, y * 0.1, 0.1) for x, y in outline]
    cap = [(3, 4, 5), (3, 5, 0), (3, 0, 1), (3, 1, 2)]  # a fan from the reflex corner
    faces = [tuple(reversed(t)) for t in cap] + [tuple(i + 6 for i in t) for t in cap]
    for i in range(6):
        j = (i + 1) % 6
        faces += [(i, j, j + 6), (i, j + 6, i + 6)]
    mesh = trimesh.Trimesh(vertices, faces, process=True)
    mesh.fix_normals()
    assert mesh.is_watertight and not mesh.is_convex
    mesh.export(path)


INERTIAL = ('<inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" '
            'iyz="0" izz="0.01"/></inertial>')
_MUJOCO_ROBOT = """<?xml version="1.0"?>
<robot name="engines">
  <link name="base_link">
    {inertial}
  </link>
  <link name="box">
    <collision><geometry><box size="0.1 0.2 0.3"/></geometry></collision>
  </link>
  <link name="bent">
    {inertial}
    <collision><geometry><mesh filename="{l_shape}"/></geometry></collision>
  </link>
  <link name="cube">
    {inertial}
    <collision><geometry><mesh filename="{cube}"/></geometry></collision>
    <collision><geometry><mesh filename="{dae}"/></geometry></collision>
  </link>
  <joint name="box_joint" type="revolute">
    <parent link="base_link"/><child link="box"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <joint name="bent_joint" type="revolute">
    <parent link="base_link"/><child link="bent"/><axis xyz="0 0 1"/>
    <limit lower="0" upper="0" effort="1" velocity="1"/>
  </joint>
  <joint name="cube_joint" type="prismatic">
    <parent link="base_link"/><child link="cube"/><axis xyz="1 0 0"/>
    <limit lower="-0.5" upper="0.5" effort="1" velocity="1"/>
  </joint>
</robot>
"""


def test_mujoco_changes_are_reported_as_mujoco_makes_them(tmp_path: Path) -> None:
    mujoco = require_module('mujoco')
    trimesh = require_module('trimesh')
    _write_l_shape(tmp_path / 'l_shape.obj')
    trimesh.creation.box((0.1, 0.1, 0.1)).export(tmp_path / 'cube.stl')
    (tmp_path / 'cube.dae').write_text('<COLLADA/>')
    text = _MUJOCO_ROBOT.format(l_shape='l_shape.obj', cube='cube.stl', dae='cube.dae',
                                inertial=INERTIAL)
    path = tmp_path / 'engines.urdf'
    path.write_text(text)
    found = {(f.code, f.element): f for f in preflight(Robot.from_urdf(path), ['mujoco'])}
    assert set(found) == {('M501', "link 'base_link'"), ('M502', "link 'box'"),
                          ('M503', "joint 'bent_joint'"), ('M504', "link 'bent'"),
                          ('M506', "link 'cube'")}
    # MuJoCo itself (without the .dae it cannot read): the box's mass is its geometry's
    model = mujoco.MjModel.from_xml_string(absolute_meshes(
        text.replace('<collision><geometry><mesh filename="cube.dae"/></geometry>'
                     '</collision>', ''), tmp_path))
    box = model.body('box')
    assert box.mass[0] == pytest.approx(1000 * 0.1 * 0.2 * 0.3)
    assert f'{box.mass[0]:.6g} kg' in found[('M502', "link 'box'")].message
    bent = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, 'bent_joint')
    assert not model.jnt_limited[bent]
    assert "link 'base_link'" not in {model.body(i).name for i in range(model.nbody)}
    assert found[('M501', "link 'base_link'")].location.line == 3
    by_rules = Findings(Robot.from_urdf(path))  # without MuJoCo: its rules
    _by_rules(by_rules.robot, by_rules)
    assert {(f.code, f.element) for f in by_rules.items} == {
        ('M501', "link 'base_link'"), ('M503', "joint 'bent_joint'")}


def test_cli_engines_option_and_exit_codes(tmp_path: Path) -> None:
    path = tmp_path / 'lumping.urdf'
    path.write_text((PREFLIGHT / 'lumping.urdf').read_text())
    plain = CliRunner().invoke(main, ['check', str(path)])
    engines = CliRunner().invoke(main, ['check', '--engines', 'gazebo', str(path)])
    assert ' G60' not in plain.stdout
    assert engines.stdout.count(' warning G601 ') == 3
    assert engines.stdout.count(' warning G602 ') == 3
    assert engines.exit_code == plain.exit_code  # warnings: the exit status stays
    assert CliRunner().invoke(main, ['check', '--strict', '--engines', 'gazebo',
                                     str(path)]).exit_code == 1
    bad = CliRunner().invoke(main, ['check', '--engines', 'bullet', str(path)])
    assert bad.exit_code == 2 and 'bullet: use mujoco, gazebo' in bad.output


def test_what_mujoco_prints_becomes_findings_and_leaves_no_log(
        tmp_path: Path, capfd, monkeypatch) -> None:
    require_module('mujoco')
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main
    inertial = ('<inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" '
                'iyz="0" izz="0.01"/></inertial>')
    path = tmp_path / 'ghost_mimic.urdf'
    path.write_text(
        f'<robot name="ghost_mimic"><link name="base_link"/><link name="a">{inertial}</link>'
        f'<link name="b">{inertial}</link><joint name="ja" type="revolute">'
        '<parent link="base_link"/><child link="a"/><axis xyz="0 0 1"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        '<joint name="jb" type="revolute"><parent link="a"/><child link="b"/>'
        '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>'
        '<mimic joint="ghost"/></joint></robot>')
    work = tmp_path / 'repository'
    work.mkdir()
    monkeypatch.chdir(work)
    result = CliRunner().invoke(main, ['check', '--engines', 'mujoco', str(path)])
    assert "M507 robot 'ghost_mimic': <mimic> on joint 'jb' ignored" in result.stdout
    assert 'WARNING' not in capfd.readouterr().err
    assert list(work.iterdir()) == []  # no MUJOCO_LOG.TXT


def test_relative_file_and_mesh_paths_reach_mujoco(tmp_path: Path, monkeypatch) -> None:
    mujoco = require_module('mujoco')
    trimesh = require_module('trimesh')
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main
    (tmp_path / 'robot').mkdir()
    trimesh.creation.box((0.1, 0.1, 0.1)).export(tmp_path / 'robot' / 'cube.stl')
    (tmp_path / 'robot' / 'cube.urdf').write_text(
        '<robot name="cube"><link name="base_link"><inertial><mass value="1"/><inertia '
        'ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial><collision>'
        '<geometry><mesh filename="cube.stl"/></geometry></collision></link></robot>')
    mujoco.MjModel.from_xml_path(str(tmp_path / 'robot' / 'cube.urdf'))  # MuJoCo reads it
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, ['check', '--engines', 'mujoco', 'robot/cube.urdf'])
    assert ' M505 ' not in result.output and ' M506 ' not in result.output, result.output


def _mujoco_refusal(path: Path) -> str | None:
    """Return why MuJoCo refuses the file where it is (None: it compiles it)."""
    mujoco = require_module('mujoco')
    try:
        mujoco.MjModel.from_xml_path(str(path))
    except ValueError as error:
        return str(error)
    return None


def _check_mujoco(path: Path, work: Path, monkeypatch) -> list[str]:
    """Run ``check --engines mujoco`` from ``work``; return its M505 lines."""
    monkeypatch.chdir(work)
    result = CliRunner().invoke(main, ['check', '--engines', 'mujoco', str(path)])
    assert result.exit_code in (0, 1), result.output
    return [line for line in result.stdout.splitlines() if ' M505 ' in line]


def test_a_file_mujoco_refuses_as_written_is_reported(tmp_path: Path, monkeypatch) -> None:
    # a <visual> with two <material>: check_urdf reads it, MuJoCo refuses the file
    path = tmp_path / 'repeated_material.urdf'
    text = (PREFLIGHT / 'repeated_material.urdf').read_text()
    path.write_text(text)
    refusal = _mujoco_refusal(path)
    assert refusal is not None and check_urdf_verdict(path)
    (said,) = _check_mujoco(path, tmp_path, monkeypatch)
    line = re.search(r'line (\d+)', refusal)  # where MuJoCo says, the <material>
    assert line and '<material name=' in text.splitlines()[int(line.group(1)) - 1]
    assert said.startswith(f'{path}:{line.group(1)}:') and "'repeated_material'" in said
    assert ' '.join(refusal.split()) in said
    assert sorted(item.name for item in tmp_path.iterdir()) == [path.name]  # no log
    # with one <material> MuJoCo compiles it, and nothing is said
    path.write_text(text.replace('      <material name="grey"/>\n', ''))
    assert _mujoco_refusal(path) is None
    assert _check_mujoco(path, tmp_path, monkeypatch) == []


def test_meshes_are_looked_up_as_mujoco_does_with_the_files_meshdir(
        tmp_path: Path, monkeypatch) -> None:
    trimesh = require_module('trimesh')
    (tmp_path / 'meshes').mkdir()
    trimesh.creation.box((0.1, 0.1, 0.3)).export(tmp_path / 'meshes' / 'arm.STL')
    text = (PREFLIGHT / 'meshdir_twice.urdf').read_text()
    path = tmp_path / 'meshdir_twice.urdf'
    path.write_text(text)
    refusal = _mujoco_refusal(path)
    assert refusal is not None and 'meshes/meshes/arm.STL' in refusal
    work = tmp_path / 'elsewhere'
    work.mkdir()
    (said,) = _check_mujoco(path, work, monkeypatch)
    assert 'meshes/meshes/arm.STL' in said and 'meshdir' in said
    assert list(work.iterdir()) == [] and 'MUJOCO_LOG.TXT' not in os.listdir(tmp_path)
    # written relative to the meshdir, or without it, MuJoCo finds the mesh
    for fixed in (text.replace('"meshes/arm.STL"', '"arm.STL"'),
                  re.sub(r'\s*<mujoco>.*</mujoco>', '', text, flags=re.S)):
        path.write_text(fixed)
        assert _mujoco_refusal(path) is None
        assert _check_mujoco(path, work, monkeypatch) == []


def test_package_meshes_reach_mujoco_reading_the_file_as_written(
        tmp_path: Path, monkeypatch) -> None:
    trimesh = require_module('trimesh')
    package = tmp_path / 'src' / 'arm_description'
    (package / 'meshes').mkdir(parents=True)
    (package / 'package.xml').write_text('<package><name>arm_description</name></package>')
    trimesh.creation.box((0.1, 0.1, 0.3)).export(package / 'meshes' / 'arm.STL')
    text = (PREFLIGHT / 'meshdir_twice.urdf').read_text()
    text = re.sub(r'\s*<mujoco>.*</mujoco>', '', text, flags=re.S).replace(
        '"meshes/arm.STL"', '"package://arm_description/meshes/arm.STL"')
    path = package / 'arm.urdf'
    path.write_text(text)
    assert _mujoco_refusal(path) is not None  # MuJoCo itself knows no package://
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, ['check', '--engines', 'mujoco', '--package-path',
                                       str(tmp_path / 'src'), str(path)])
    assert ' M505 ' not in result.output and ' M506 ' not in result.output, result.output
