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
One error boundary: a user's mistake is one line, a bug in the package a traceback.

Each front end runs as the user runs it (a process of its own): the CLI, ``urdfgenpy init``
and the publisher node. A bug is injected deep inside, in one of the review's checks,
which all of them run; a wrong value is given the way a user gives it.
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path
import subprocess
import sys
from typing import Any

from helpers import REPO
import pytest

from urdfgenpy_ros.examples import pan_tilt_unit
from urdfgenpy_ros.scaffold.command import add_arguments
from urdfgenpy_ros.scaffold.verb import ScaffoldVerb

INJECT = """
import sys
import urdfgenpy_ros.formats.inertia_check as inertia_check
import urdfgenpy_ros.validation.checklist as checklist


def injected(*arguments):
    raise {kind}('injected bug')


checklist.check_inertia = inertia_check.check_inertia = injected  # the review's, a target's
"""
RUN_CLI = ('import sys\nfrom urdfgenpy_ros.cli import main\n'
           'main(sys.argv[1:], prog_name="urdfgenpy")\n')
RUN_INIT = ('import sys\nfrom urdfgenpy_ros.scaffold.command import main\n'
            'sys.exit(main(sys.argv[1:]))\n')
RUN_NODE = 'from urdfgenpy_ros.publisher.node import console_main\nconsole_main()\n'


def _run(code: str, *arguments: str, cwd: Path) -> subprocess.CompletedProcess:
    env = dict(os.environ, PYTHONPATH=str(REPO))
    return subprocess.run([sys.executable, '-c', code, *arguments], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=120)


def _is_a_bug(result: Any, kind: str) -> None:
    assert f'{kind}: ' in result.stderr and 'injected bug' in result.stderr, result.stderr
    assert 'Traceback (most recent call last)' in result.stderr
    assert result.returncode not in (0, 2)


def _one_line(result: Any, prog: str, words: str) -> None:
    lines = result.stderr.splitlines()
    assert result.returncode == 2, result.stderr
    assert len(lines) == 1 and lines[0].startswith(f'{prog}: ') and words in lines[0], lines
    assert 'Traceback' not in result.stderr


@pytest.fixture
def robot_file(tmp_path: Path) -> Path:
    path = tmp_path / 'ptu.urdf'
    pan_tilt_unit().to_urdf(path)
    return path


@pytest.mark.parametrize('kind', ['TypeError', 'KeyError'])
def test_a_bug_under_the_cli_is_a_traceback(kind: str, robot_file: Path) -> None:
    for command in (['check', str(robot_file)],
                    ['convert', str(robot_file), str(robot_file.with_suffix('.sdf'))]):
        if command[0] == 'convert':  # convert reviews only what libsdformat refuses
            robot = pan_tilt_unit()
            robot.get_link('pan_link').inertial.ixx = -1.0
            robot.to_urdf(robot_file)
        result = _run(INJECT.format(kind=kind) + RUN_CLI, *command, cwd=robot_file.parent)
        _is_a_bug(result, kind)


def test_a_wrong_value_under_the_cli_is_one_line(robot_file: Path) -> None:
    result = _run(RUN_CLI, 'check', str(robot_file), '--payload', '2kg',
                  cwd=robot_file.parent)
    _one_line(result, 'urdfgenpy', "Invalid value for '--payload': '2kg': give MASS@LINK")
    result = _run(RUN_CLI, 'check', str(robot_file), '--ignore', 'I2O5', cwd=robot_file.parent)
    _one_line(result, 'urdfgenpy', 'I2O5 is not a finding code')
    missing = robot_file.parent / 'missing.urdf'
    result = _run(RUN_CLI, 'tree', str(missing), cwd=robot_file.parent)
    _one_line(result, 'urdfgenpy', 'missing.urdf')


def test_a_bug_under_init_is_a_traceback(tmp_path: Path) -> None:
    result = _run(INJECT.format(kind='KeyError') + RUN_INIT, 'r_description', cwd=tmp_path)
    _is_a_bug(result, 'KeyError')
    assert not (tmp_path / 'r_description').exists()


def test_a_wrong_value_under_init_is_one_line(tmp_path: Path) -> None:
    result = _run(RUN_INIT, 'r_description', '--from', 'missing.urdf', cwd=tmp_path)
    _one_line(result, 'urdfgenpy init', '--from: missing.urdf does not exist')
    result = _run(RUN_INIT, 'r_description', '--build-type', 'catkin', cwd=tmp_path)
    _one_line(result, 'urdfgenpy init', "argument --build-type: invalid choice: 'catkin'")


def test_ros2_pkg_scaffold_says_its_own_name(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    parser = argparse.ArgumentParser(prog='ros2 pkg scaffold')
    add_arguments(parser)
    verb = ScaffoldVerb()
    arguments = parser.parse_args(['Bad Name', '--destination-directory', str(tmp_path)])
    assert verb.main(args=arguments) == 2
    (line,) = capsys.readouterr().err.splitlines()
    assert line.startswith("ros2 pkg scaffold: invalid package name 'Bad Name'")
    import urdfgenpy_ros.validation.checklist as checklist

    def injected(*_: object) -> None:
        raise TypeError('injected bug')

    monkeypatch.setattr(checklist, 'check_inertia', injected)
    good = parser.parse_args(['r_description', '--destination-directory', str(tmp_path)])
    with pytest.raises(TypeError, match='injected bug'):
        verb.main(args=good)


def _node(graph: Any, code: str, *parameters: str) -> tuple[int, str]:
    process = graph.start(*parameters, command=[sys.executable, '-c', code])
    output, _ = process.communicate(timeout=30)  # it exits by itself; a hang times out
    return process.returncode, output


@pytest.mark.slow
def test_a_bug_in_the_node_is_a_traceback_and_a_wrong_value_one_line(graph: Any) -> None:
    graph.env['PYTHONPATH'] = str(REPO)
    code, output = _node(graph, INJECT.format(kind='TypeError') + RUN_NODE)
    assert code != 0 and 'Traceback (most recent call last)' in output, output
    assert 'TypeError: injected bug' in output
    code, output = _node(graph, RUN_NODE, 'rate:=-5')
    errors = [line for line in output.splitlines() if line.strip()]
    assert code == 1 and 'Traceback' not in output, output
    assert len(errors) == 1 and "parameter 'rate': -5 is not a positive number" in errors[0]


def test_a_bug_in_the_viewer_reload_is_raised_a_mistake_is_its_status(tmp_path: Path) -> None:
    pytest.importorskip('viser')
    from browser import free_port
    from urdfgenpy_ros import Robot
    from urdfgenpy_ros.viewer.web import RobotViewer
    path = tmp_path / 'ptu.urdf'
    pan_tilt_unit().to_urdf(path)
    failure: list[BaseException] = []

    def load() -> Robot:
        if failure:
            raise failure[0]
        return Robot.from_urdf(path)

    viewer = RobotViewer(load, port=free_port())
    try:
        failure.append(FileNotFoundError(2, 'No such file or directory', str(path)))
        assert viewer.reload() is False
        assert viewer.status == ('**reload failed** (showing the last good model): '
                                 f'{path}: No such file or directory')
        failure[0] = KeyError('injected bug')
        with pytest.raises(KeyError, match='injected bug'):
            viewer.reload()
    finally:
        viewer.close()
