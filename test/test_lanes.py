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
The fast lane (test/lanes.py), judged by what pytest itself runs and reports.

A small suite in a scratch folder uses the lane as conftest.py does; pytest's own
``-rA`` lines say which tests ran, and its exit status that the budget never fails a run.
"""

from __future__ import annotations

import configparser
import os
from pathlib import Path
import subprocess
import sys

from helpers import REPO
import lanes

CONFTEST = """
import lanes
import pytest


def pytest_addoption(parser):
    lanes.add_options(parser)


def pytest_configure(config):
    lanes.configure(config)


@pytest.fixture
def graph():
    return 'a ROS graph'
"""
SUITE = """
import time
import pytest


def test_quick():
    pass


def test_sleepy():
    time.sleep(0.5)


@pytest.mark.slow
def test_marked_sleepy():
    time.sleep(0.5)


@pytest.mark.engine
def test_engine():
    pass


def test_asks_for_the_graph(graph):
    pass
"""


def _run(folder: Path, *arguments: str) -> subprocess.CompletedProcess:
    """Run pytest on the scratch suite, the lane on its path and no other plugin (fast)."""
    (folder / 'conftest.py').write_text(CONFTEST)
    (folder / 'test_suite.py').write_text(SUITE)
    env = dict(os.environ, PYTEST_DISABLE_PLUGIN_AUTOLOAD='1', PYTHONPATH=os.pathsep.join(
        [str(REPO / 'test'), os.environ.get('PYTHONPATH', '')]))
    return subprocess.run([sys.executable, '-m', 'pytest', '-rA', '-p', 'no:cacheprovider',
                           '--rootdir', str(folder), *arguments],
                          cwd=folder, capture_output=True, text=True, env=env, timeout=120)


def _ran(output: str) -> set[str]:
    """Return the tests pytest's -rA summary says passed."""
    return {line.split('::')[1] for line in output.splitlines() if line.startswith('PASSED ')}


def test_fast_leaves_out_marked_tests_and_users_of_the_graph(tmp_path: Path) -> None:
    result = _run(tmp_path, '--fast', '--fast-lane-budget', '0')
    assert result.returncode == 0, result.stdout + result.stderr
    assert _ran(result.stdout) == {'test_quick', 'test_sleepy'}
    assert '3 deselected' in result.stdout


def test_fast_and_a_marker_expression_both_apply(tmp_path: Path) -> None:
    result = _run(tmp_path, '--fast', '-m', 'not slow', '-k', 'quick or engine')
    assert _ran(result.stdout) == {'test_quick'}, result.stdout


def test_without_fast_everything_runs(tmp_path: Path) -> None:
    result = _run(tmp_path, '--fast-lane-budget', '0')
    assert _ran(result.stdout) == {'test_quick', 'test_sleepy', 'test_marked_sleepy',
                                   'test_engine', 'test_asks_for_the_graph'}
    assert 'fast lane budget' not in result.stdout


def test_an_unmarked_test_over_the_budget_is_named_and_the_run_passes(tmp_path: Path) -> None:
    result = _run(tmp_path, '--fast-lane-budget', '0.3')
    assert result.returncode == 0, result.stdout + result.stderr
    section = result.stdout.split('fast lane budget')[1].split('=====')[0]
    named = [line.split()[-1] for line in section.splitlines() if ' s  ' in line]
    assert named == ['test_suite.py::test_sleepy']  # not the marked one that sleeps as long
    assert '1 test(s) without a marker' in section


def test_unasked_the_run_says_nothing_of_the_budget_asked_it_uses_the_ini(
        tmp_path: Path) -> None:
    (tmp_path / 'pytest.ini').write_text('[pytest]\nfast_lane_budget = 0.3\n')
    quiet = _run(tmp_path, '--fast')
    assert quiet.returncode == 0 and 'fast lane budget' not in quiet.stdout, quiet.stdout
    asked = _run(tmp_path, '--fast', '--fast-lane-budget')
    assert asked.returncode == 0, asked.stdout + asked.stderr
    section = asked.stdout.split('fast lane budget')[1].split('=====')[0]
    assert 'test_suite.py::test_sleepy' in section and 'took over 0.3 s' in section


def test_the_markers_are_declared_and_undeclared_ones_refused() -> None:
    parser = configparser.ConfigParser()
    parser.read(REPO / 'setup.cfg')
    declared = {line.split(':')[0].strip()
                for line in parser['tool:pytest']['markers'].strip().splitlines()}
    assert set(lanes.LANE_MARKS) <= declared
    assert '--strict-markers' in parser['tool:pytest']['addopts'].split()
