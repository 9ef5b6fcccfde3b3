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

"""colcon builds the package, and the ament index finds its executables as ros2 run does."""

from __future__ import annotations

from pathlib import Path
import subprocess
import sys

from helpers import assert_check_urdf_accepts


def _sourced(workspace: Path, command: str) -> subprocess.CompletedProcess:
    script = f'source install/setup.bash && {command}'
    return subprocess.run(['bash', '-c', script], cwd=workspace, capture_output=True,
                          text=True, timeout=120)


def test_install_tree_has_the_ros_layout(colcon_workspace: Path) -> None:
    workspace = colcon_workspace
    share = workspace / 'install' / 'urdfgenpy_ros' / 'share'
    assert (share / 'ament_index' / 'resource_index' / 'packages' / 'urdfgenpy_ros').is_file()
    assert (share / 'urdfgenpy_ros' / 'package.xml').is_file()
    for executable in ('urdfgenpy', 'publisher'):
        assert (workspace / 'install' / 'urdfgenpy_ros' / 'lib' / 'urdfgenpy_ros' /
                executable).is_file()


def test_ament_index_finds_urdfgenpy_and_it_runs(colcon_workspace: Path) -> None:
    workspace = colcon_workspace
    # What `ros2 run urdfgenpy_ros urdfgenpy` does: the package prefix from the ament
    # index, then lib/<package>/<executable>.
    locate = ('python3 -c "from ament_index_python.packages import get_package_prefix; '
              "import os; print(os.path.join(get_package_prefix('urdfgenpy_ros'), 'lib', "
              "'urdfgenpy_ros', 'urdfgenpy'))\"")
    found = _sourced(workspace, locate.replace('python3', sys.executable))
    assert found.returncode == 0, found.stderr
    executable = Path(found.stdout.strip())
    assert executable == workspace / 'install' / 'urdfgenpy_ros' / 'lib' / 'urdfgenpy_ros' / \
        'urdfgenpy'
    ran = _sourced(workspace, f'{executable} example -o out && {sys.executable} -c '
                   '"import urdfgenpy_ros; print(urdfgenpy_ros.__file__)"')
    assert ran.returncode == 0, ran.stderr
    assert 'pan_joint [revolute] → pan_link' in ran.stdout
    assert str(workspace / 'install') in ran.stdout.splitlines()[-1]
    assert_check_urdf_accepts(workspace / 'out' / 'ptu.urdf')
