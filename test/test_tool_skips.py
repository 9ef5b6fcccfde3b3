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

"""A missing tool skips naming the tool, never errors; with URDFGENPY_REQUIRE_TOOLS it fails."""

from __future__ import annotations

import os
from pathlib import Path
import subprocess
import sys

from helpers import REPO, require_module
import pytest

FAKE = 'urdfgenpy_no_such_tool'
"""A module nobody installs: it stands for an optional tool missing."""

TESTS = f"""
import pytest
from helpers import require_module


def test_helper():
    require_module('{FAKE}')


def test_plain_import():
    import {FAKE}  # noqa: F401


def test_importorskip():
    pytest.importorskip('{FAKE}')
"""
MODULE_LEVEL = f"""
from helpers import require_module

{FAKE} = require_module('{FAKE}')


def test_never_runs():
    pass
"""

BLOCKER = """
import sys


class Block:
    def find_spec(self, name, path=None, target=None):
        if name.split('.')[0] in {names!r}:
            raise ModuleNotFoundError(f'No module named {{name!r}} (blocked)', name=name)


sys.meta_path.insert(0, Block())
"""
OPTIONAL = ('trimesh', 'mujoco', 'pinocchio', 'pybullet', 'coal', 'manifold3d', 'yourdfpy',
            'selenium', 'rclpy', 'xacro', 'pydrake', 'scipy', 'vtkmodules', 'viser',
            'roboticstoolbox', 'spatialmath', 'coacd', 'jsonschema', 'junitparser', 'graphviz',
            'collada', 'example_robot_data', 'sensor_msgs', 'std_msgs', 'rcl_interfaces',
            'ament_index_python', 'fast_simplification', 'rtree', 'cmeel', 'mypy')
"""The optional tools the tests use: none is needed to collect them."""


def test_the_helper_skips_naming_the_tool(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv('URDFGENPY_REQUIRE_TOOLS', raising=False)
    with pytest.raises(pytest.skip.Exception, match=FAKE):
        require_module(FAKE)
    monkeypatch.setenv('URDFGENPY_REQUIRE_TOOLS', '1')
    with pytest.raises(pytest.fail.Exception, match=FAKE):
        require_module(FAKE)


def _pytest(folder: Path, required: bool, *arguments: str, path: str = '') -> str:
    """Run pytest (with this suite's plugin) on ``folder``; return its report."""
    env = {key: value for key, value in os.environ.items()
           if key != 'URDFGENPY_REQUIRE_TOOLS'}
    env['PYTHONPATH'] = os.pathsep.join([*filter(None, [path]), str(REPO / 'test'), str(REPO)])
    if required:
        env['URDFGENPY_REQUIRE_TOOLS'] = '1'
    result = subprocess.run(
        [sys.executable, '-m', 'pytest', '-p', 'tool_skips', '-p', 'no:cacheprovider', '-rsf',
         '-q', '--continue-on-collection-errors', '--rootdir', str(folder), *arguments,
         str(folder)], cwd=folder, capture_output=True, text=True, timeout=300, env=env)
    return result.stdout + result.stderr


@pytest.mark.slow
def test_every_way_of_missing_a_tool_skips_naming_it_or_fails_in_ci(tmp_path: Path) -> None:
    (tmp_path / 'test_tools.py').write_text(TESTS)
    (tmp_path / 'test_module_level.py').write_text(MODULE_LEVEL)
    local = _pytest(tmp_path, required=False)
    assert '4 skipped' in local and 'error' not in local.lower(), local
    assert local.count(FAKE) >= 4, local  # each skip names the tool
    ci = _pytest(tmp_path, required=True)
    summary = ci.strip().splitlines()[-1]
    assert summary.startswith('3 failed, 1 error'), ci  # the module's: at collection


@pytest.mark.slow
def test_the_suite_is_collected_without_any_optional_tool(tmp_path: Path) -> None:
    (tmp_path / 'sitecustomize.py').write_text(BLOCKER.format(names=set(OPTIONAL)))
    said = _pytest(REPO / 'test', False, '--collect-only', path=str(tmp_path))
    assert 'tests collected' in said and 'error' not in said.splitlines()[-1], said
    assert "trimesh not importable (No module named 'trimesh' (blocked))" in said, said
