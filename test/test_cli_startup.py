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
A one-file ``urdfgenpy check`` loads what checking needs, and the rest when asked for.

Each case runs the command in a fresh Python process (as the console script does) and
reads that process's ``sys.modules`` at exit: what a plain check of a two-link URDF never
uses (numpy, the mesh and engine libraries, the fixer, the writers' options, the JSON and
metadata modules of the reports) is not there, and a check that asks for it (``--fix``,
``--format sarif``) still loads and uses it. The readers compiled per element on their
first call read a robot the same whatever was read before, and in threads reading at
once. A process's own command line (``main()``, the console script) freezes the garbage
collector at exit, so exit does not walk every object: such a process prints, exits
and writes what the same command run in-process (CliRunner, which leaves the collector
alone) does, byte for byte. No time is asserted (bench/bench_speed.py measures it).
"""

from __future__ import annotations

import json
import os
from pathlib import Path
import subprocess
import sys

from click.testing import CliRunner

from helpers import FIXTURES, full_robot, REPO
from urdfgenpy_ros.cli import main

SMALL = """<?xml version="1.0"?>
<robot name="small">
  <link name="base"/>
  <link name="arm"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
</robot>
"""
RUN = """
import atexit, sys
listing = sys.argv.pop()
atexit.register(lambda: open(listing, 'w').write('\\n'.join(sorted(sys.modules))))
from urdfgenpy_ros.cli import main
main()
"""
FROZEN = """
import atexit, gc, sys
start = gc.get_freeze_count()  # what the interpreter freezes itself
atexit.register(lambda: print('frozen at exit:', gc.get_freeze_count() > start,
                              file=sys.stderr))
from urdfgenpy_ros.cli import main
if sys.argv.pop(1) == 'in-process':
    main.main(sys.argv[1:], standalone_mode=False)
else:
    main()
"""
NEVER = ('numpy', 'scipy', 'trimesh', 'mujoco', 'manifold3d', 'yaml', 'xacro', 'rclpy')
"""Libraries a plain check of a URDF file has no use for."""
LATER = ('json', 'importlib.metadata', 'xml.etree.ElementTree',
         'urdfgenpy_ros.validation.fix', 'urdfgenpy_ros.validation.rewrite',
         'urdfgenpy_ros.formats.options', 'urdfgenpy_ros.formats.writer_options',
         'urdfgenpy_ros.formats.prepare', 'urdfgenpy_ros.formats.sdf_refusals',
         'urdfgenpy_ros.formats.urdf', 'urdfgenpy_ros.formats.xacro_read',
         'urdfgenpy_ros.cli.check_xacro', 'urdfgenpy_ros.cli.convert',
         'urdfgenpy_ros.validation.statics', 'urdfgenpy_ros.validation.preflight',
         'urdfgenpy_ros.validation.mujoco_preflight', 'urdfgenpy_ros.dynamics')
"""Modules of the reports, the fixer, the writers and the other checks: asked for only."""


def _run(arguments: list[str], folder: Path) -> tuple[subprocess.CompletedProcess, set[str]]:
    """Run ``urdfgenpy ARGUMENTS`` as a process; return it and the modules it loaded."""
    listing = folder / 'modules.json'
    environment = dict(os.environ)
    environment['PYTHONPATH'] = os.pathsep.join(
        [str(REPO), *filter(None, [environment.get('PYTHONPATH')])])
    done = subprocess.run([sys.executable, '-c', RUN, *arguments, str(listing)],
                          env=environment, cwd=folder, capture_output=True, text=True,
                          timeout=60)
    return done, set(listing.read_text().splitlines())


def _loaded(modules: set[str], names: tuple[str, ...]) -> list[str]:
    """Return the modules of ``modules`` that are one of ``names`` or inside one."""
    return sorted(module for module in modules
                  if any(module == name or module.startswith(f'{name}.') for name in names))


def test_a_plain_check_loads_neither_the_heavy_libraries_nor_what_it_does_not_ask_for(
        tmp_path: Path) -> None:
    path = tmp_path / 'small.urdf'
    path.write_text(SMALL)
    done, modules = _run(['check', str(path)], tmp_path)
    in_process = CliRunner().invoke(main, ['check', str(path)])
    assert (done.returncode, done.stdout) == (in_process.exit_code, in_process.stdout)
    assert 'C401' in done.stdout and done.stderr.endswith('1 warning(s), 0 unreadable\n')
    assert 'urdfgenpy_ros.validation.checklist' in modules  # it did check
    assert _loaded(modules, NEVER) == []
    assert _loaded(modules, LATER) == []


def test_a_check_that_asks_for_the_fixer_and_a_report_loads_them(tmp_path: Path) -> None:
    path = tmp_path / 'small.urdf'
    path.write_text(SMALL.replace('xyz="0 0 1"', 'xyz="0 0 2"'))  # J102: --fix scales it
    done, modules = _run(['check', '--fix', '--format', 'sarif', 'small.urdf'], tmp_path)
    assert done.returncode == 0, done.stderr
    assert 'axis xyz="0 0 1"' in path.read_text()
    assert json.loads(done.stdout)['version'] == '2.1.0'
    assert {'urdfgenpy_ros.validation.fix', 'urdfgenpy_ros.validation.rewrite', 'json',
            'importlib.metadata'} <= modules


def test_readers_compiled_on_first_use_read_the_same_whatever_came_before_or_beside(
        tmp_path: Path) -> None:
    (tmp_path / 'small.urdf').write_text(SMALL)
    full_robot().to_urdf(tmp_path / 'full.urdf')
    code = ('import sys\nfrom concurrent.futures import ThreadPoolExecutor\n'
            'from urdfgenpy_ros import Robot\n'
            'with ThreadPoolExecutor(8) as pool:  # the first reads of each element at once\n'
            '    robots = list(pool.map(Robot.from_urdf, sys.argv[1:]))\n'
            'print(*sorted({robot.to_urdf() + repr(robot) for robot in robots\n'
            '               if robot.name != "small"}), sep="")')
    environment = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(REPO), *filter(None, [os.environ.get('PYTHONPATH')])]))
    outputs = [subprocess.run([sys.executable, '-c', code, *paths], env=environment,
                              cwd=tmp_path, capture_output=True, text=True, check=True,
                              timeout=60).stdout
               for paths in (['full.urdf'], ['small.urdf', 'full.urdf'], ['full.urdf'] * 8)]
    assert outputs[0] == outputs[1] == outputs[2]
    assert '<mesh' in outputs[0] and '<mimic' in outputs[0]


def test_only_a_process_own_command_line_freezes_the_collector_at_exit(tmp_path: Path) -> None:
    (tmp_path / 'small.urdf').write_text(SMALL)
    environment = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(REPO), *filter(None, [os.environ.get('PYTHONPATH')])]))
    said = [subprocess.run([sys.executable, '-c', FROZEN, how, 'check', 'small.urdf'],
                           env=environment, cwd=tmp_path, capture_output=True, text=True,
                           timeout=60).stderr.splitlines()[-1]
            for how in ('process', 'in-process')]
    assert said == ['frozen at exit: True', 'frozen at exit: False']


def test_a_process_writes_and_says_what_the_same_command_in_process_does(
        tmp_path: Path) -> None:
    packages = FIXTURES / 'packages'
    source = packages / 'fixture_description' / 'urdf' / 'every_element.urdf'
    for target in ('robot.xml', 'robot.sdf', 'robot.urdf'):  # MJCF converts its STL mesh
        arguments = ['convert', str(source), str(tmp_path / 'out' / target), '-p',
                     str(packages)]
        runs = []
        for how in ('process', 'in-process'):
            (tmp_path / 'out').mkdir()
            if how == 'process':
                done, _ = _run(arguments, tmp_path)
                said = (done.returncode, done.stdout, done.stderr)
            else:
                result = CliRunner().invoke(main, arguments)
                said = (result.exit_code, result.stdout, result.stderr)
            written = {path.relative_to(tmp_path / 'out'): path.read_bytes()
                       for path in sorted((tmp_path / 'out').rglob('*')) if path.is_file()}
            runs.append((said, written))
            for path in sorted((tmp_path / 'out').rglob('*'), reverse=True):
                path.unlink() if path.is_file() else path.rmdir()
            (tmp_path / 'out').rmdir()
        assert runs[0] == runs[1]
        assert Path(target) in runs[0][1] or runs[0][0][0] != 0
