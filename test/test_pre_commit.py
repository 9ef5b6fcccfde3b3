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
The pre-commit hook on a repository of description packages, run by the real pre-commit.

Two packages, one including the other's macros by ``$(find)``, the macro file named
``*.urdf.xacro`` as many are: the hook's environment has xacro, finds the packages of the
repository, notes and skips the macro file, and fails on a real error.
"""

from __future__ import annotations

import os
from pathlib import Path
import shutil
import subprocess
import sys

from helpers import REPO, require_module
import pytest

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.0.1</version><description>x</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<export><build_type>ament_cmake</build_type></export></package>
"""
MACROS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="arm" params="parent">
    <link name="arm_link">
      <inertial><mass value="1"/>
        <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    </link>
    <joint name="shoulder" type="revolute"><parent link="${parent}"/><child link="arm_link"/>
      <axis xyz="0 0 1"/><limit lower="LOWER" upper="1" effort="10" velocity="1"/></joint>
  </xacro:macro>
</robot>
"""
ROBOT = """<?xml version="1.0"?>
<robot name="rover" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find arm_description)/urdf/arm.urdf.xacro"/>
  <link name="base_link">
    <inertial><mass value="5"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
  </link>
  <xacro:arm parent="base_link"/>
</robot>
"""


def _git(folder: Path, *arguments: str) -> None:
    subprocess.run(['git', *arguments], cwd=folder, check=True, capture_output=True,
                   timeout=60)


def _repository(root: Path, lower: str) -> Path:
    for name, file, text in (('arm_description', 'arm.urdf.xacro', MACROS),
                             ('rover_description', 'rover.urdf.xacro', ROBOT)):
        (root / 'src' / name / 'urdf').mkdir(parents=True, exist_ok=True)
        (root / 'src' / name / 'package.xml').write_text(PACKAGE_XML.format(name=name))
        (root / 'src' / name / 'urdf' / file).write_text(text.replace('LOWER', lower))
    _git(root, 'init', '-q')
    _git(root, 'add', '.')
    return root


@pytest.mark.slow
def test_the_hook_checks_a_repository_of_description_packages(tmp_path: Path) -> None:
    require_module('pre_commit')
    shutil.which('git') or pytest.skip('git not installed')
    pre_commit = str(Path(sys.executable).with_name('pre-commit'))
    env = dict(os.environ, PRE_COMMIT_HOME=str(tmp_path / 'cache'),
               PATH=f'{Path(sys.executable).parent}:{os.environ["PATH"]}')
    env.pop('PYTHONPATH', None)  # the hook runs its own installed copy, as for a user

    def run(repository: Path) -> subprocess.CompletedProcess:
        return subprocess.run([pre_commit, 'try-repo', str(REPO), 'urdfgenpy-check',
                               '--all-files', '--verbose'], cwd=repository, env=env,
                              capture_output=True, text=True, timeout=900)

    good = run(_repository(tmp_path / 'good', '-1'))
    assert good.returncode == 0, good.stdout[-3000:] + good.stderr[-2000:]
    assert 'arm.urdf.xacro: note: skipped, it holds Xacro macros only' in good.stdout
    assert '2 file(s): 0 error(s)' in good.stdout
    bad = run(_repository(tmp_path / 'bad', '2'))  # lower > upper, in the included macro
    assert bad.returncode == 1, bad.stdout[-3000:]
    assert 'error J104' in bad.stdout and 'arm.urdf.xacro' in bad.stdout
