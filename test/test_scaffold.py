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

"""Generated description packages build, install, expand, validate and test with colcon."""

from __future__ import annotations

import argparse
import os
from pathlib import Path
import py_compile
import re
import subprocess
import sys

from helpers import assert_check_urdf_accepts, FIXTURES, require_module
from lxml import etree
import pytest

from urdfgenpy_ros import Robot, Severity
from urdfgenpy_ros.scaffold.command import main as init
from urdfgenpy_ros.scaffold.verb import ScaffoldVerb


def _sources(folder: Path) -> dict[str, list[str]]:
    """Return, per kind of --from, the arguments that select it."""
    packages = FIXTURES / 'packages'
    table = folder / 'arm.yaml'
    table.write_text('convention: standard\ndegrees: true\nrows:\n'
                     '  - {joint: 1, a: 0, alpha: 90, d: 0.3}\n'
                     '  - {joint: 2, a: 0.4, alpha: 0, d: 0}\n'
                     '  - {joint: 3, a: 0, alpha: 0, d: 0.1, type: prismatic, upper: 0.2}\n')
    return {
        'example': [],
        'urdf': ['--from', str(packages / 'fixture_description/urdf/every_element.urdf'),
                 '--package-path', str(packages)],
        'xacro': ['--from', str(packages / 'fixture_description/urdf/arm.urdf.xacro'),
                  '--xacro-args', 'dof:=4', 'gripper:=true', '--package-path', str(packages)],
        'dh': ['--from', str(table)],
        'builder': ['--from', 'urdfgenpy_ros.examples:pan_tilt_unit'],
    }


@pytest.fixture(scope='module')
def workspace(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Generate every kind of package for both build types, then colcon build and test."""
    require_module('colcon_core')
    require_module('jinja2')
    root = tmp_path_factory.mktemp('scaffold')
    sources = _sources(root)
    for build_type in ('ament_cmake', 'ament_python'):
        for kind, arguments in sources.items():
            name = f'{kind}_{build_type.split("_")[1]}_description'
            code = init([name, '--build-type', build_type, '--destination-directory',
                         str(root / 'src'), '--maintainer-email', 'dev@example.com',
                         *arguments])
            assert code == 0, name
    colcon = str(Path(sys.executable).with_name('colcon'))
    env = dict(os.environ, PATH=f'{Path(sys.executable).parent}:{os.environ["PATH"]}')
    for verb in (['build'], ['test'], ['test-result', '--verbose']):
        result = subprocess.run([colcon, *verb, '--event-handlers', 'console_cohesion-']
                                if verb[0] != 'test-result' else [colcon, *verb],
                                cwd=root, capture_output=True, text=True, env=env,
                                timeout=900)
        assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    return root


PACKAGES = [f'{kind}_{kind_build}_description' for kind_build in ('cmake', 'python')
            for kind in ('example', 'urdf', 'xacro', 'dh', 'builder')]


def _sourced(workspace: Path, command: str) -> str:
    env = dict(os.environ, PATH=f'{Path(sys.executable).parent}:{os.environ["PATH"]}')
    result = subprocess.run(['bash', '-c', f'source install/setup.bash && {command}'],
                            cwd=workspace, capture_output=True, text=True, env=env,
                            timeout=120)
    assert result.returncode == 0, result.stderr
    return result.stdout


@pytest.mark.colcon
def test_two_packages_macro_files_alone_make_one_coloured_robot(workspace: Path,
                                                                tmp_path: Path) -> None:
    """Another package includes only the macro files: every colour comes along, once."""
    parts = ('example_cmake_description', 'builder_python_description')  # same materials
    calls = ''.join(
        f'<xacro:include filename="$(find {name})/urdf/ptu.macro.xacro"/>'
        for name in parts)
    user = tmp_path / 'two_units.urdf.xacro'
    user.write_text(
        '<?xml version="1.0"?><robot name="two" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        f'{calls}<link name="world"/>'
        '<xacro:ptu prefix="a_" parent="world"><origin xyz="0 0 0"/>'
        '</xacro:ptu><xacro:ptu prefix="b_" parent="world">'
        '<origin xyz="1 0 0"/></xacro:ptu></robot>')
    expanded = tmp_path / 'two_units.urdf'
    expanded.write_text(_sourced(workspace, f'xacro {user}'))
    assert_check_urdf_accepts(expanded)
    root = etree.parse(str(expanded)).getroot()
    defined = [node.get('name') for node in root.findall('material')]
    used = {node.get('name') for node in root.iterfind('link/visual/material')}
    assert used and used <= set(defined) and len(defined) == len(set(defined))
    robot = Robot.from_urdf(expanded)
    assert [str(f) for f in robot.validate() if f.severity is Severity.ERROR] == []


@pytest.mark.parametrize('name', PACKAGES)
@pytest.mark.colcon
def test_installed_package_expands_to_a_valid_urdf(workspace: Path, name: str,
                                                   tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    share = workspace / 'install' / name / 'share' / name
    for folder in ('urdf', 'launch', 'rviz', 'meshes', 'config'):
        assert (share / folder).is_dir(), folder
    (main,) = share.glob('urdf/*.urdf.xacro')
    # $(find NAME) resolves through the ament index of the sourced install.
    expanded = tmp_path / 'expanded.urdf'
    expanded.write_text(_sourced(workspace, f'xacro {main}'))
    assert_check_urdf_accepts(expanded)
    monkeypatch.setenv('AMENT_PREFIX_PATH', str(workspace / 'install' / name))
    robot = Robot.from_urdf(expanded)
    errors = [str(f) for f in robot.validate() if f.severity is Severity.ERROR]
    assert errors == []
    if name.startswith(('urdf_', 'xacro_')):  # their mesh was copied in, the URIs rewritten
        assert sorted(p.name for p in (share / 'meshes').iterdir()) == ['.gitkeep', 'cube.stl']
        assert f'package://{name}/meshes/cube.stl' in expanded.read_text()


@pytest.mark.parametrize('name', PACKAGES)
@pytest.mark.colcon
def test_package_xml_covers_every_package_the_launch_files_use(workspace: Path,
                                                               name: str) -> None:
    catkin_pkg = require_module('catkin_pkg.package')
    folder = workspace / 'src' / name
    package = catkin_pkg.parse_package(str(folder / 'package.xml'))
    depends = {dependency.name for dependency in package.exec_depends}
    used = set()
    for launch in (folder / 'launch').glob('*.launch.py'):
        py_compile.compile(str(launch), doraise=True)
        text = launch.read_text()
        used |= set(re.findall(r"package='([^']+)'", text))
        used |= set(re.findall(r"FindPackageShare\('([^']+)'\)", text)) - {name}
        used |= {'launch', 'launch_ros'}
    used.add('xacro')
    assert used <= depends, used - depends
    assert package.get_build_type() == ('ament_cmake' if '_cmake_' in name else
                                        'ament_python')


def test_the_verb_runs_as_ros2cli_drives_it(tmp_path: Path) -> None:
    parser = argparse.ArgumentParser(prog='ros2 pkg scaffold')
    verb = ScaffoldVerb()
    verb.add_arguments(parser, 'ros2')
    args = parser.parse_args(['demo_description', '--build-type', 'ament_python',
                              '--destination-directory', str(tmp_path), '--license', 'MIT'])
    assert verb.main(args=args) == 0
    assert 'MIT' in (tmp_path / 'demo_description' / 'package.xml').read_text()


@pytest.mark.parametrize('arguments, words', [
    (['Bad-Name'], "invalid package name 'Bad-Name'"),
    (['two__underscores'], 'two underscores in a row'),
    (['9lives'], 'must start with a lower-case letter'),
])
def test_bad_names_are_one_line_and_nothing_is_written(
        arguments: list[str], words: str, tmp_path: Path,
        capsys: pytest.CaptureFixture[str]) -> None:
    assert init([*arguments, '--destination-directory', str(tmp_path)]) == 2
    error = capsys.readouterr().err
    assert error.count('\n') == 1 and words in error
    assert list(tmp_path.iterdir()) == []


def test_existing_files_are_never_overwritten_without_force(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / 'ptu_description'
    target.mkdir()
    (target / 'notes.txt').write_text('mine')
    assert init(['ptu_description', '--destination-directory', str(tmp_path)]) == 2
    assert 'exists and is not empty' in capsys.readouterr().err
    assert sorted(p.name for p in target.iterdir()) == ['notes.txt']
    assert init(['ptu_description', '--destination-directory', str(tmp_path), '--force']) == 0
    assert (target / 'notes.txt').read_text() == 'mine'


def test_unwritable_destination_is_one_line_and_leaves_nothing(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    blocker = tmp_path / 'a_file'
    blocker.write_text('x')
    assert init(['ptu_description', '--destination-directory', str(blocker / 'sub')]) == 2
    error = capsys.readouterr().err
    assert error.count('\n') == 1 and 'cannot write' in error
    assert sorted(p.name for p in tmp_path.iterdir()) == ['a_file']
