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

"""``init`` of a robot with errors refuses, repairs (--fix) or goes on (--allow-errors)."""

from __future__ import annotations

import os
from pathlib import Path
import subprocess
import sys

from helpers import ament_index, require_module
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.scaffold.command import main as init

# A vacuum-robot base as such packages write it: a cylinder body whose tensor breaks the
# triangle inequality (izz > ixx + iyy), the I203 create_2 has on base_link.
BASE = """<?xml version="1.0"?>
<robot name="vacuum">
  <link name="base_link">
    <inertial>
      <mass value="3.5"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.05"/>
    </inertial>
    <collision><geometry><cylinder radius="0.17" length="0.09"/></geometry></collision>
  </link>
</robot>
"""


@pytest.fixture
def source(tmp_path: Path) -> Path:
    path = tmp_path / 'vacuum.urdf'
    path.write_text(BASE)
    return path


def _init(source: Path, out: Path, *options: str) -> int:
    return init(['vacuum_description', '--from', str(source),
                 '--destination-directory', str(out), *options])


def _expand_package(package: Path, tmp_path: Path) -> str:
    """Return what the real xacro command makes of the package's robot, as colcon test runs it."""
    xacro = Path(sys.executable).parent / 'xacro'
    if not xacro.exists():
        pytest.skip('the xacro command is not installed (the xacro extra)')
    index = ament_index(tmp_path / 'index', {'vacuum_description': package})
    result = subprocess.run([str(xacro), str(package / 'urdf' / 'vacuum.urdf.xacro')],
                            capture_output=True, text=True, timeout=120,
                            env={**os.environ, **index}, check=False)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_a_robot_with_errors_is_refused_with_its_findings(
        source: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert _init(source, tmp_path / 'out') == 2
    err = capsys.readouterr().err.splitlines()
    assert err[0].startswith(f'{source}:') and "error I203 link 'base_link'" in err[0]
    assert err[-1].startswith('urdfgenpy init: the robot has 1 error (above)')
    assert '--fix' in err[-1] and '--allow-errors' in err[-1]
    assert not (tmp_path / 'out').exists()


def test_fix_writes_the_repaired_tensor_into_the_package_only(
        source: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    trimesh = require_module('trimesh')
    assert _init(source, tmp_path, '--fix') == 0
    err = capsys.readouterr().err
    assert 'fixed I203' in err and 'cylinder' in err
    assert source.read_text() == BASE  # the user's file is as it was
    package = tmp_path / 'vacuum_description'
    expanded = _expand_package(package, tmp_path)
    robot = Robot.from_urdf_string(expanded)
    # what the package's own test asserts: no errors
    assert [f for f in robot.validate(check_meshes=False) if f.severity == 'error'] == []
    # the tensor is trimesh's for a solid cylinder of that mass
    solid = trimesh.creation.cylinder(radius=0.17, height=0.09, sections=512)
    solid.density = 3.5 / solid.volume
    inertial = robot.get_link('base_link').inertial
    assert inertial.mass == 3.5
    for got, want in zip((inertial.ixx, inertial.iyy, inertial.izz),
                         solid.moment_inertia.diagonal()):
        assert got == pytest.approx(want, rel=1e-3)


def test_allow_errors_scaffolds_it_as_it_is_and_says_so(
        source: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert _init(source, tmp_path, '--allow-errors') == 0
    err = capsys.readouterr().err
    assert 'error I203' in err
    package = tmp_path / 'vacuum_description'
    expanded = _expand_package(package, tmp_path)
    codes = [f.code for f in Robot.from_urdf_string(expanded).validate(check_meshes=False)
             if f.severity == 'error']
    assert codes == ['I203']  # what the package's colcon test will find, init said first


def test_fix_gives_a_link_without_shapes_a_stated_sphere(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """create_2's cliff sensor links: a bad tensor and no shape to take one from."""
    path = tmp_path / 'vacuum.urdf'
    path.write_text(BASE.replace('</robot>', """  <link name="cliff_sensor_link">
    <inertial><mass value="0.01"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="1"/></inertial>
  </link>
  <joint name="cliff_joint" type="fixed"><parent link="base_link"/>
    <child link="cliff_sensor_link"/></joint>
</robot>"""))
    assert _init(path, tmp_path, '--fix') == 0
    err = capsys.readouterr().err
    assert "fixed I203 link 'cliff_sensor_link'" in err and 'solid sphere of radius 0.05 m' in err
    package = tmp_path / 'vacuum_description'
    robot = Robot.from_urdf_string(_expand_package(package, tmp_path))
    sensor = robot.get_link('cliff_sensor_link').inertial
    assert (sensor.ixx, sensor.iyy, sensor.izz) == pytest.approx([2 / 5 * 0.01 * 0.05 ** 2] * 3)
