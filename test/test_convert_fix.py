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

"""``convert --fix``: from a refused Xacro to an SDF libsdformat loads, each repair said."""

from __future__ import annotations

from pathlib import Path
import re

from click.testing import CliRunner
from helpers import check_urdf, require_module
import pytest
import test_sdf

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main

check_sdf = test_sdf.check_sdf  # the session fixture running libsdformat's checker
# A vacuum base as create_2 has it: the body's tensor breaks the triangle inequality (it has
# a cylinder to take one from); a cliff sensor's link has a bad tensor and no shape at all.
BASE = """<?xml version="1.0"?>
<robot name="vacuum" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="body_mass" value="3.5"/>
  <link name="base_link">
    <inertial><mass value="${body_mass}"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.05"/></inertial>
    <collision><geometry><cylinder radius="0.17" length="0.09"/></geometry></collision>
  </link>
  <link name="wheel">
    <inertial><mass value="0.1"/>
      <inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.0001" iyz="0" izz="0.0001"/></inertial>
  </link>
  <joint name="wheel_joint" type="continuous"><parent link="base_link"/><child link="wheel"/>
    <axis xyz="0 1 0"/></joint>
  <link name="cliff_sensor_link">
    <inertial><origin xyz="0.01 0 0"/><mass value="0.01"/>
      <inertia ixx="0.0001" ixy="0" ixz="0" iyy="0.0001" iyz="0" izz="0.001"/></inertial>
  </link>
  <joint name="cliff_joint" type="continuous"><parent link="base_link"/>
    <child link="cliff_sensor_link"/><axis xyz="0 0 1"/></joint>
</robot>
"""


@pytest.fixture
def source(tmp_path: Path) -> Path:
    path = tmp_path / 'vacuum.urdf.xacro'
    path.write_text(BASE)
    return path


@pytest.mark.engine
def test_convert_fix_writes_an_sdf_libsdformat_loads(check_sdf, source: Path,
                                                     tmp_path: Path) -> None:
    trimesh = require_module('trimesh')
    target = tmp_path / 'vacuum.sdf'
    refused = CliRunner().invoke(main, ['convert', str(source), str(target)])
    assert refused.exit_code == 2 and 'pass --fix' in refused.stderr
    result = CliRunner().invoke(main, ['convert', str(source), str(target), '--fix',
                                       '--fix-radius', '0.02'])
    assert result.exit_code == 0, result.output
    fixed = [line for line in result.stderr.splitlines() if ': fixed I203 ' in line]
    assert len(fixed) == 2
    assert any("'base_link'" in line and 'cylinder' in line for line in fixed)
    assert any("'cliff_sensor_link'" in line and 'solid sphere of radius 0.02 m' in line
               and '--fix-radius' in line for line in fixed)
    assert source.read_text() == BASE  # the source is not touched
    code, _, inertials, _, errors = check_sdf(target)
    assert code == 0, errors
    solid = trimesh.creation.cylinder(radius=0.17, height=0.09, sections=512)
    solid.density = 3.5 / solid.volume
    assert sorted(inertials['base_link'][4:]) == pytest.approx(
        sorted(solid.moment_inertia.diagonal()), rel=1e-3)
    sphere = 2.0 / 5.0 * 0.01 * 0.02 ** 2
    mass, *centre = inertials['cliff_sensor_link'][:4]
    assert (mass, centre) == (pytest.approx(0.01), pytest.approx([0.01, 0.0, 0.0]))
    assert inertials['cliff_sensor_link'][4:] == pytest.approx([sphere] * 3)


def test_convert_fix_to_urdf_gives_a_clean_robot(source: Path, tmp_path: Path) -> None:
    target = tmp_path / 'vacuum.urdf'
    result = CliRunner().invoke(main, ['convert', str(source), str(target), '--fix'])
    assert result.exit_code == 0, result.output
    assert check_urdf(target).returncode == 0
    assert [f.code for f in Robot.from_urdf(target).validate() if f.severity == 'error'] == []


def test_check_fix_on_xacro_points_to_a_repair_that_works(source: Path, tmp_path: Path) -> None:
    result = CliRunner().invoke(main, ['check', '--fix', str(source)])
    assert result.exit_code == 2
    (note,) = [line for line in result.stdout.splitlines() if 'not fixed' in line]
    refused = set(re.findall(r'([A-Z]\d{3}) link', note.partition('not fixed: ')[2]))
    assert refused == {'I205'}  # a warning, which convert --fix leaves: check --fix repairs it
    assert (f'urdfgenpy convert {source} OUT.urdf and repair that with urdfgenpy check --fix '
            'OUT.urdf') in note
    target = tmp_path / 'OUT.urdf'
    assert CliRunner().invoke(main, ['convert', str(source), str(target)]).exit_code == 0
    CliRunner().invoke(main, ['check', '--fix', str(target)])
    assert check_urdf(target).returncode == 0
    assert 'I205' not in {finding.code for finding in Robot.from_urdf(target).validate()}
