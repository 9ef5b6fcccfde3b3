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

"""Front ends speak in their own words: a missing extra, a unit hint, one line each."""

from __future__ import annotations

from pathlib import Path
import subprocess
import sys

from click.testing import CliRunner
from helpers import REPO, require_module
from lxml import etree
import pytest

from urdfgenpy_ros.cli import main

# Python without ROS 2's packages: a finder that refuses them, as a plain venv does.
WITHOUT_ROS = """
import runpy, sys
class Refuse:
    def find_spec(self, name, path=None, target=None):
        if name.split('.')[0] in ('rclpy', 'rcl_interfaces', 'std_msgs', 'sensor_msgs'):
            raise ModuleNotFoundError(f'No module named {name!r}', name=name)
sys.meta_path.insert(0, Refuse())
runpy.run_module('urdfgenpy_ros.publisher', run_name='__main__')
"""


def test_publisher_without_the_ros_extra_is_one_line_naming_it() -> None:
    result = subprocess.run([sys.executable, '-c', WITHOUT_ROS], capture_output=True,
                            text=True, timeout=60, cwd=REPO)
    assert result.returncode == 1
    assert 'Traceback' not in result.stderr
    (line,) = result.stderr.splitlines()
    assert "pip install 'urdfgenpy_ros[ros]'" in line and 'rcl_interfaces' in line


def test_inertia_of_a_millimetre_mesh_hints_with_its_own_option(tmp_path: Path) -> None:
    trimesh = require_module('trimesh')
    path = tmp_path / 'plate.stl'
    trimesh.creation.box((200.0, 100.0, 50.0)).export(path)  # millimetres
    result = CliRunner().invoke(main, ['inertia', str(path), '--mass', '2'])
    assert result.exit_code == 0, result.output
    assert result.stderr.splitlines() == [
        'warning: plate.stl spans 200 m: if it is in millimetres, pass --scale 0.001']
    result = CliRunner().invoke(main, ['inertia', str(path), '--mass', '2', '--scale', '0.001'])
    assert result.exit_code == 0 and result.stderr == ''
    inertia = etree.fromstring(result.stdout).find('inertia')
    solid = trimesh.creation.box((0.2, 0.1, 0.05))
    solid.density = 2.0 / solid.volume
    for name, want in zip(('ixx', 'iyy', 'izz'), solid.moment_inertia.diagonal()):
        assert float(inertia.get(name)) == pytest.approx(want, rel=1e-9)
