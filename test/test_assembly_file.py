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


"""Assembly files, ``urdfgenpy attach`` and the assembled robot in the other commands."""

from __future__ import annotations

from pathlib import Path

from assembly_parts import gripper, mobile_base
from click.testing import CliRunner
from helpers import FIXTURES, require_module
import pytest

from urdfgenpy_ros import Mesh, Origin, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.model.errors import ParseError
from urdfgenpy_ros.scaffold.render import render_package
from urdfgenpy_ros.scaffold.spec import PackageSpec

ARM = FIXTURES / 'packages/fixture_description/urdf/arm.urdf.xacro'
PACKAGES = FIXTURES / 'packages'


def _files(folder: Path) -> Path:
    """Write the rover, and an assembly of it with the fixture arm and the gripper."""
    mobile_base().to_urdf(folder / 'rover.urdf')
    path = folder / 'rover_arm.yaml'  # no .assembly suffix: found by its parts: key
    path.write_text(f"""\
# The rover with a 4-joint arm and a gripper.
name: rover_arm
parts:
  - file: rover.urdf
  - file: {ARM}
    args: {{dof: 4, gripper: false}}
    at: chassis
    prefix: arm_
    origin: {{xyz: [0.1, 0, 0.15], rpy: [0, 0, 1.5]}}
  - function: assembly_parts:gripper
    at: arm_segment_4
    prefix: gripper_
    origin: {{xyz: [0, 0, 0.25]}}
    joint_name: wrist_mount
""")
    return path


def _in_python(folder: Path) -> Robot:
    robot = Robot.from_urdf(folder / 'rover.urdf')
    robot.attach(Robot.from_xacro(ARM, {'dof': '4', 'gripper': 'false'},
                                  search_paths=[PACKAGES]),
                 'chassis', Origin((0.1, 0, 0.15), (0, 0, 1.5)), prefix='arm_')
    robot.attach(gripper(), 'arm_segment_4', Origin((0, 0, 0.25)), prefix='gripper_',
                 joint_name='wrist_mount')
    robot.name = 'rover_arm'
    return robot


def test_assembly_file_is_found_by_content_and_equals_python(tmp_path: Path) -> None:
    path = _files(tmp_path)
    robot = load(path, {}, [PACKAGES])
    assert robot.to_urdf() == _in_python(tmp_path).to_urdf()
    rover = tmp_path / 'rover.urdf'
    assert robot.included_files[:2] == [str(path.resolve()), str(rover.resolve())]
    assert str((PACKAGES / 'fixture_description/urdf/arm_parts.xacro').resolve()) in \
        robot.included_files
    assert str(Path(__file__).with_name('assembly_parts.py').resolve()) in robot.included_files
    table = tmp_path / 'arm.yaml'  # a DH table stays a DH table
    table.write_text('convention: standard\nrows:\n  - {joint: 1, a: 0, alpha: 0, d: 0.3}\n')
    assert load(table).joints[0].name == 'joint_1'


@pytest.mark.parametrize('text, where, words', [
    ('parts: []\n', ':1:1: error A001', "'parts': an assembly file is a mapping with a "),
    ('parts:\n  - file: rover.urdf\n    at: base_link\n', ':3:5: error A001',
     "'at': the first part is the base: it takes no 'at'"),
    ('parts:\n  - file: rover.urdf\n  - file: rover.urdf\n    prefix: b_\n',
     ':3:5: error A001', "'at': every part after the first needs the link it attaches to "
     '(at: base_link)'),
    ('parts:\n  - file: rover.urdf\n  - file: rover.urdf\n    at: chassis\n',
     ':3:5: error A001', "'prefix': cannot attach 'rover' to 'rover': 9 names taken"),
    ('parts:\n  - file: rover.urdf\n  - file: rover.urdf\n    at: chassis\n    prefix: b_\n'
     '    joint_name: mast_joint\n', ':6:5: error A001', "'joint_name': cannot attach 'rover' "
     "to 'rover': 1 name taken"),
    ('parts:\n  - file: rover.urdf\n  - file: rover.urdf\n    at: chasis\n    prefix: b_\n',
     ':4:5: error A001', "link 'chasis' is not in 'rover' (did you mean 'chassis'?)"),
    ('parts:\n  - file: nowhere.urdf\n', ':2:5: error A001',
     "'file': 'nowhere.urdf' resolves to"),
    ('parts:\n  - file: rover.urdf\n  - function: rover\n    at: chassis\n',
     ':3:5: error A001', "'function': cannot import 'rover'"),
    ('parts:\n  - file: rover.urdf\n    prefx: a_\n', ':3:5: error A001',
     "'prefx': unknown key (did you mean 'prefix'?)"),
    ('parts:\n  - file: rover.urdf\n  - file: rover.urdf\n    at: chassis\n    prefix: b_\n'
     '    origin: {xyz: [0, 0]}\n', ':6:5: error A001', "'origin.xyz': expected 3 finite"),
    ('parts:\n  - file: rover.urdf\n  - file: rover.urdf\n    at: chassis\n    prefix: b_\n'
     '    origin: {rpy: [0, 0, .nan]}\n', ':6:5: error A001', "'origin.rpy': expected 3 finite"),
    ('parts:\n  - file: rover.urdf\n  - file: [rover.urdf\n', ':4:1: error A001',
     'YAML syntax'),
    ('parts:\n  - file: broken.urdf\n', ':2:5: error A001',
     "'file': part broken.urdf: "),
])
def test_errors_are_one_line_with_file_line_key_and_fix(
        tmp_path: Path, text: str, where: str, words: str) -> None:
    mobile_base().to_urdf(tmp_path / 'rover.urdf')
    (tmp_path / 'broken.urdf').write_text('<robot name="x"><link name="a"></robot>')
    path = tmp_path / 'bad.assembly.yaml'
    path.write_text(text)
    with pytest.raises(ParseError) as caught:
        Robot.from_assembly(path)
    message = str(caught.value)
    assert '\n' not in message and message.startswith(f'{path}{where}'), message
    assert words in message, message
    result = CliRunner().invoke(main, ['check', str(path)])
    assert result.exit_code == 2 and result.stdout.strip() == message


def test_commands_read_assembly_files(tmp_path: Path) -> None:
    path = _files(tmp_path)
    tree = CliRunner().invoke(main, ['tree', str(path), '-p', str(PACKAGES)])
    assert tree.exit_code == 0, tree.output
    assert 'wrist_mount [fixed] → gripper_palm' in tree.output
    out = tmp_path / 'out.urdf'
    convert = CliRunner().invoke(main, ['convert', str(path), str(out), '-p', str(PACKAGES)])
    assert convert.exit_code == 0, convert.output
    assert out.read_text() == _in_python(tmp_path).to_urdf()
    check = CliRunner().invoke(main, ['check', str(path), '-p', str(PACKAGES)])
    assert ' error ' not in check.output, check.output


def test_attach_command_writes_what_attach_does(tmp_path: Path) -> None:
    base, part = tmp_path / 'rover.urdf', tmp_path / 'gripper.urdf'
    mobile_base().to_urdf(base)
    gripper().to_urdf(part)
    out = tmp_path / 'rover_gripper.urdf'
    arguments = ['attach', str(base), str(part), '--at', 'mast', '--prefix', 'g_', '--xyz',
                 '0 0 0.3', '--rpy', '0 0 90', '--degrees', '-o', str(out)]
    result = CliRunner().invoke(main, arguments)
    assert result.exit_code == 0, result.output
    assert "('gripper' on 'mast' by joint 'mast_to_g_palm')" in result.output
    expected = Robot.from_urdf(base).attach(Robot.from_urdf(part), 'mast',
                                            Origin((0, 0, 0.3), (0, 0, 1.5707963267948966)),
                                            prefix='g_')
    assert out.read_text() == expected.to_urdf()
    again = CliRunner().invoke(main, arguments)
    assert again.exit_code == 2 and again.output == f'urdfgenpy: {out} exists: pass --force ' \
        'to overwrite it\n'
    clash = CliRunner().invoke(main, ['attach', str(base), str(base), '--at', 'mast', '-o',
                                      str(tmp_path / 'x.urdf')])
    assert clash.exit_code == 2 and clash.output.count('\n') == 1
    assert clash.output.startswith("urdfgenpy: cannot attach 'rover' to 'rover': 9 names "
                                   "taken: link 'base_link', ")
    assert '(give the part --prefix rover_, or pass --joint-name for ' in clash.output
    assert not (tmp_path / 'x.urdf').exists()
    bad = CliRunner().invoke(main, [*arguments[:5], '--xyz', '1 2', '-o',
                                    str(tmp_path / 'y.urdf')])
    assert bad.exit_code == 2 and "'1 2' is not 3 numbers" in bad.output


def test_init_writes_the_macro_and_a_top_level_file_that_calls_it(tmp_path: Path) -> None:
    require_module('jinja2')
    robot = load(_files(tmp_path), {}, [PACKAGES])
    spec = PackageSpec('rover_arm_description', 'ament_cmake', tmp_path / 'src')
    files, _ = render_package(spec, robot, search_paths=[str(PACKAGES)])
    package = tmp_path / 'src' / spec.name
    for relative, data in files.items():
        (package / relative).parent.mkdir(parents=True, exist_ok=True)
        (package / relative).write_bytes(data)
    urdf = package / 'urdf'
    assert sorted(p.name for p in urdf.iterdir()) == [
        'materials.xacro', 'rover_arm.gazebo.xacro', 'rover_arm.macro.xacro',
        'rover_arm.ros2_control.xacro', 'rover_arm.urdf.xacro']
    macro = (urdf / 'rover_arm.macro.xacro').read_text()
    assert '<xacro:macro name="rover_arm" params="prefix parent *origin">' in macro
    assert 'rover_arm.macro.xacro' in (package / 'README.md').read_text()
    packages = {spec.name: package}
    for prefix in ('', 'twin_'):
        expanded = Robot.from_xacro(urdf / 'rover_arm.urdf.xacro', {'prefix': prefix},
                                    packages=packages)
        expected = Robot.from_urdf_string(robot.prefixed(prefix).to_urdf())
        assert [link.name for link in expanded.links] == [link.name for link in expected.links]
        assert expanded.joints == expected.joints
        # the blocks come from their own macros, called last: the same, in another order
        assert len(expanded.extensions) == len(expected.extensions)
        assert all(block in expanded.extensions for block in expected.extensions)
        assert [str(f) for f in expanded.validate() if f.severity == 'error'] == []


def test_relative_mesh_paths_of_parts_elsewhere_still_resolve(tmp_path: Path) -> None:
    from registry_robots import robot as registry_robot
    panda = registry_robot('panda.urdf')  # file://meshes/... relative to its own folder
    mobile_base().to_urdf(tmp_path / 'rover.urdf')
    path = tmp_path / 'rover_panda.assembly.yaml'
    path.write_text(f'parts:\n  - file: rover.urdf\n  - file: {panda}\n    at: chassis\n'
                    '    prefix: arm_\n')
    robot = Robot.from_assembly(path)
    meshes = [item.geometry.filename for link in robot.links
              for item in (*link.visuals, *link.collisions) if isinstance(item.geometry, Mesh)]
    assert meshes and all(not name.startswith('file:') for name in meshes)
    for name in meshes:  # read as a plain path, relative to the assembly file's folder
        assert (tmp_path / name).is_file(), name
    assert [str(f) for f in robot.validate() if f.code.startswith('R3')] == []


@pytest.mark.parametrize('command', ['attach', 'convert'])
def test_written_files_find_the_meshes_from_where_they_are(tmp_path: Path,
                                                           command: str) -> None:
    from helpers import load_yourdfpy
    from registry_robots import robot as registry_robot
    panda = registry_robot('panda.urdf')  # file://meshes/... relative to its own folder
    mobile_base().to_urdf(tmp_path / 'rover.urdf')
    assembly = tmp_path / 'rover_panda.assembly.yaml'
    assembly.write_text(f'parts:\n  - file: rover.urdf\n  - file: {panda}\n    at: chassis\n'
                        '    prefix: arm_\n')
    output = tmp_path / 'elsewhere' / 'out.urdf'
    output.parent.mkdir()
    arguments = (['attach', str(tmp_path / 'rover.urdf'), str(panda), '--at', 'chassis',
                  '--prefix', 'arm_', '-o'] if command == 'attach' else
                 ['convert', str(assembly)])
    result = CliRunner().invoke(main, [*arguments, str(output)])
    assert result.exit_code == 0, result.output
    meshes = [mesh for link in load_yourdfpy(output).links
              for item in (*link.visuals, *link.collisions)
              if (mesh := item.geometry.mesh) is not None]
    assert meshes
    for mesh in meshes:  # as yourdfpy resolves them: relative to the written file
        assert (output.parent / mesh.filename).resolve().is_file(), mesh.filename
