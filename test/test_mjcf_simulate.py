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
The written MJCF simulates, judged by MuJoCo: a diff-drive robot on the scene's floor.

Velocity servos on light wheels need an implicit integrator; a floating base must start
on the floor, not in it. MuJoCo steps the scene and measures the contacts.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import require_module
import pytest

from urdfgenpy_ros.cli import main

# a diff-drive robot as ros2_control_demos' example_2 lays it out: a box chassis whose
# bottom is 4 cm below its origin, two wheels of 3.4e-5 kg m^2 driven by velocity
DIFFBOT = """<?xml version="1.0"?>
<robot name="diffbot">
  <link name="base_link">
    <visual><geometry><box size="0.4 0.2 0.08"/></geometry></visual>
    <collision><geometry><box size="0.4 0.2 0.08"/></geometry></collision>
    <inertial><mass value="0.3"/>
      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.004" iyz="0" izz="0.005"/></inertial>
  </link>
{wheels}
  <link name="caster">
    <collision><geometry><sphere radius="0.025"/></geometry></collision>
    <inertial><mass value="0.01"/>
      <inertia ixx="2.5e-6" ixy="0" ixz="0" iyy="2.5e-6" iyz="0" izz="2.5e-6"/></inertial>
  </link>
  <joint name="caster_joint" type="fixed">
    <parent link="base_link"/><child link="caster"/><origin xyz="0.15 0 -0.015"/>
  </joint>
  <ros2_control name="DiffBot" type="system">
    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
    <joint name="left_wheel_joint"><command_interface name="velocity"/></joint>
    <joint name="right_wheel_joint"><command_interface name="velocity"/></joint>
  </ros2_control>
</robot>
"""
WHEEL = """  <link name="{side}_wheel">
    <collision><origin rpy="1.5708 0 0"/>
      <geometry><cylinder radius="0.025" length="0.01"/></geometry></collision>
    <inertial><mass value="0.2"/>
      <inertia ixx="3.4e-5" ixy="0" ixz="0" iyy="3.4e-5" iyz="0" izz="6.25e-5"/></inertial>
  </link>
  <joint name="{side}_wheel_joint" type="continuous">
    <parent link="base_link"/><child link="{side}_wheel"/>
    <origin xyz="-0.1 {y} -0.015"/><axis xyz="0 1 0"/>
  </joint>
"""


@pytest.fixture(autouse=True)
def _mujoco() -> None:
    require_module('mujoco')


def _diffbot(folder: Path, block: str = '') -> Path:
    sides = (('left', 0.12), ('right', -0.12))
    wheels = ''.join(WHEEL.format(side=side, y=y) for side, y in sides)
    path = folder / 'diffbot.urdf'
    path.write_text(DIFFBOT.format(wheels=wheels).replace('</robot>', block + '</robot>'))
    return path


def _convert(folder: Path, *extra: str) -> Path:
    result = CliRunner().invoke(main, ['convert', str(_diffbot(folder)),
                                       str(folder / 'diffbot.xml'), '--base', 'floating',
                                       '--scene', *extra])
    assert result.exit_code == 0, result.output
    return folder / 'scene.xml'


def test_a_floating_diffbot_drives_on_the_floor_for_two_seconds(tmp_path: Path) -> None:
    import mujoco
    import numpy
    model = mujoco.MjModel.from_xml_path(str(_convert(tmp_path)))
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    # at t=0 nothing is in the floor: every contact MuJoCo finds is touching, not inside
    assert data.ncon > 0
    assert min(data.contact[index].dist for index in range(data.ncon)) >= -1e-6
    data.ctrl[:] = 1.0
    while data.time < 2.0:
        mujoco.mj_step(model, data)
    bad = int(mujoco.mjtWarning.mjWARN_BADQACC)
    assert data.warning[bad].number == 0
    assert numpy.all(numpy.isfinite(data.qpos)) and numpy.all(numpy.isfinite(data.qvel))
    assert abs(data.qvel[7] - 1.0) < 0.1  # the wheels turn as commanded
    header = (tmp_path / 'diffbot.xml').read_text().split('-->')[0]
    assert 'implicitfast' in header and 'rests on the floor' in header


def test_the_users_integrator_is_kept(tmp_path: Path) -> None:
    import mujoco
    _diffbot(tmp_path, '<mujoco><option integrator="RK4"/></mujoco>\n')
    result = CliRunner().invoke(main, ['convert', str(tmp_path / 'diffbot.urdf'),
                                       str(tmp_path / 'diffbot.xml')])
    assert result.exit_code == 0, result.output
    model = mujoco.MjModel.from_xml_path(str(tmp_path / 'diffbot.xml'))
    assert model.opt.integrator == mujoco.mjtIntegrator.mjINT_RK4


def test_a_floating_mesh_below_its_origin_starts_on_the_floor(tmp_path: Path) -> None:
    import mujoco
    trimesh = require_module('trimesh')
    trimesh.creation.box((0.2, 0.2, 0.2)).export(tmp_path / 'cube.stl')
    (tmp_path / 'block.urdf').write_text(
        '<robot name="block"><link name="base_link"><collision><origin xyz="0 0 -0.3"/>'
        '<geometry><mesh filename="cube.stl" scale="2 2 2"/></geometry></collision>'
        '<inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0"'
        ' izz="0.01"/></inertial></link></robot>')
    result = CliRunner().invoke(main, ['convert', str(tmp_path / 'block.urdf'),
                                       str(tmp_path / 'out' / 'block.xml'), '--base',
                                       'floating', '--scene'])
    assert result.exit_code == 0, result.output
    model = mujoco.MjModel.from_xml_path(str(tmp_path / 'out' / 'scene.xml'))
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    assert all(data.contact[index].dist >= -1e-6 for index in range(data.ncon))
    start = data.qpos[2]
    while data.time < 0.5:
        mujoco.mj_step(model, data)
    assert abs(data.qpos[2] - start) < 1e-3  # it rests: neither falls nor is pushed up
