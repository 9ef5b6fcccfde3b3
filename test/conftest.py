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

"""Shared fixtures: the corpus, example robots, a colcon workspace, a ROS graph; the fast lane."""

from __future__ import annotations

from collections.abc import Iterator
import os
from pathlib import Path
import shutil
import subprocess
import sys

from helpers import CORPUS, full_robot, NO_CORPUS, REPO, require_module
import lanes
import pytest

from urdfgenpy_ros.examples import pan_tilt_unit
from urdfgenpy_ros.robot import Robot

pytest_plugins = ['tool_skips']  # a tool missing: a skip naming it, a failure in CI


def pytest_addoption(parser: pytest.Parser) -> None:
    """Add ``--fast`` and the fast lane's time budget (lanes.py)."""
    lanes.add_options(parser)


def pytest_configure(config: pytest.Config) -> None:
    """Select the fast lane when asked and name slow unmarked tests (lanes.py)."""
    lanes.configure(config)


@pytest.fixture(autouse=True, scope='session')
def _mesh_cache(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """Keep converted meshes in a folder of the run's own, not the user's cache."""
    saved = os.environ.get('URDFGENPY_CACHE_DIR')
    os.environ['URDFGENPY_CACHE_DIR'] = str(tmp_path_factory.mktemp('mesh-cache'))
    yield
    if saved is None:
        os.environ.pop('URDFGENPY_CACHE_DIR', None)
    else:
        os.environ['URDFGENPY_CACHE_DIR'] = saved


@pytest.fixture
def corpus() -> Path:
    """Return the third-party corpus directory, or skip when it is absent."""
    if not CORPUS.is_dir():
        pytest.skip(NO_CORPUS)
    return CORPUS


@pytest.fixture
def ptu() -> Robot:
    """Return the built-in pan-tilt unit."""
    return pan_tilt_unit()


@pytest.fixture
def every_element() -> Robot:
    """Return a robot using every element and attribute of the model."""
    return full_robot()


_SKIP = shutil.ignore_patterns('.git', '.venv', 'build', 'install', 'log', '__pycache__',
                               '.pytest_cache', '.hypothesis', '*.egg-info')


@pytest.fixture(scope='session')
def colcon_workspace(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Return a workspace in which colcon has built this repository (once per session)."""
    require_module('colcon_core')
    require_module('ament_index_python')
    root = tmp_path_factory.mktemp('ws')
    shutil.copytree(REPO, root / 'src' / 'urdfgenpy_ros', ignore=_SKIP)
    colcon = str(Path(sys.executable).with_name('colcon'))
    result = subprocess.run([colcon, 'build', '--event-handlers', 'console_cohesion-'],
                            cwd=root, capture_output=True, text=True, timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    return root


@pytest.fixture
def browser() -> Iterator:
    """Return a headless Chromium; quit it afterwards."""
    pytest.importorskip('selenium')
    from browser import Browser
    instance = Browser()
    yield instance
    instance.close()


@pytest.fixture
def graph():
    """Return an isolated ROS graph with a listener node; stop everything afterwards."""
    from ros_helpers import Graph
    ros = Graph()
    yield ros
    ros.close()
