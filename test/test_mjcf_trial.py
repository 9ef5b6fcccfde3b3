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
MJCF export findings of a new-user trial on real robots, each judged by MuJoCo.

MuJoCo compiles the written models, steps them and reports their contacts; the robots
are small ones built here in the shape of the trial's (a bad mesh, a fixed-base arm, a
gripper, ros2_control parameters and transmissions).
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import require_module
import pytest

from urdfgenpy_ros.cli import main


@pytest.fixture(autouse=True)
def _mujoco() -> None:
    require_module('mujoco')


INERTIAL = ('<inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" '
            'ixy="0" ixz="0" iyz="0"/></inertial>')


def _arm(body: str = '', extra: str = '') -> str:
    """Return a two-link arm's URDF with ``body`` in link 'a' and ``extra`` in the robot."""
    return f"""<robot name="arm">
  <link name="base_link">{INERTIAL}</link>
  <link name="a">{body}{INERTIAL}</link>
  <joint name="j1" type="revolute"><parent link="base_link"/><child link="a"/>
    <axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="10" velocity="1"/></joint>
{extra}</robot>
"""


@pytest.mark.parametrize('content', [b'', b'solid x\nendsolid x\n', b'\0' * 84],
                         ids=['empty', 'ascii-no-facet', 'binary-no-triangle'])
def test_an_unreadable_mesh_is_an_m809_finding_and_the_rest_is_written(
        tmp_path: Path, content: bytes) -> None:
    import mujoco
    (tmp_path / 'empty.stl').write_bytes(content)
    source = tmp_path / 'robot.urdf'
    source.write_text(_arm('<visual><geometry><mesh filename="empty.stl"/></geometry>'
                           '</visual><collision><geometry><box size="0.1 0.1 0.1"/>'
                           '</geometry></collision>'))
    target = tmp_path / 'robot.xml'
    result = CliRunner().invoke(main, ['convert', str(source), str(target)])
    assert result.exit_code == 0, result.output
    line = [text for text in result.output.splitlines() if 'M809' in text]
    assert len(line) == 1 and line[0].startswith(f'{source}:3:') and "link 'a'" in line[0]
    assert 'empty.stl' in line[0] and 'Traceback' not in result.output
    model = mujoco.MjModel.from_xml_path(str(target))
    assert model.nmesh == 0 and model.ngeom == 1  # the box stays, the mesh geom is out
    assert model.body('a').id > 0


def test_a_missing_package_gives_one_hint(tmp_path: Path) -> None:
    import mujoco
    source = tmp_path / 'robot.urdf'
    source.write_text(_arm('<visual><geometry><mesh filename="package://nowhere_pkg/a.stl"/>'
                           '</geometry></visual>'))
    target = tmp_path / 'robot.xml'
    result = CliRunner().invoke(main, ['convert', str(source), str(target)])
    assert result.exit_code == 0, result.output
    line = next(text for text in result.output.splitlines() if 'M809' in text)
    assert line.count('--package-path') == 1 and line.count(' (') == 1, line
    assert mujoco.MjModel.from_xml_path(str(target)).nmesh == 0


def _box(size: str, xyz: str = '0 0 0') -> str:
    return (f'<collision><origin xyz="{xyz}"/><geometry><box size="{size}"/></geometry>'
            '</collision>')


def _gripper_arm() -> str:
    """Return a fixed-base arm whose shoulder overlaps the base, with two overlapping fingers."""
    def link(name: str, collision: str) -> str:
        return f'<link name="{name}">{collision}{INERTIAL}</link>'

    def finger(name: str, side: int) -> str:
        return (f'<joint name="{name}_joint" type="prismatic"><parent link="hand"/>'
                f'<child link="{name}"/><origin xyz="0 {side * 0.01} 0.3"/>'
                f'<axis xyz="0 {side} 0"/><limit lower="0" upper="0.04" effort="20" '
                'velocity="0.1"/></joint>')
    return f"""<robot name="gripper_arm">
  {link("base_link", _box("0.2 0.2 0.2"))}
  {link("shoulder", _box("0.1 0.1 0.3", "0 0 0.1"))}
  {link("hand", _box("0.1 0.1 0.1", "0 0 0.25"))}
  {link("left", _box("0.02 0.04 0.08"))}
  {link("right", _box("0.02 0.04 0.08"))}
  <joint name="pan" type="revolute"><parent link="base_link"/><child link="shoulder"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="50" velocity="1"/></joint>
  <joint name="tilt" type="revolute"><parent link="shoulder"/><child link="hand"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="50" velocity="1"/></joint>
  {finger("left", 1)}
  {finger("right", -1)}
</robot>
"""


def test_no_self_collision_at_home_and_the_fingers_stay_in_range(tmp_path: Path) -> None:
    import mujoco
    source = tmp_path / 'robot.urdf'
    source.write_text(_gripper_arm())
    target = tmp_path / 'robot.xml'
    result = CliRunner().invoke(main, ['convert', str(source), str(target),
                                       '--actuators', 'position', '--kp', '100',
                                       '--kv', '10'])
    assert result.exit_code == 0, result.output
    assert 'excluded from self-collision' in result.output
    model = mujoco.MjModel.from_xml_path(str(target))
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key('home').id)
    mujoco.mj_forward(model, data)
    assert data.ncon == 0, [(model.geom(c.geom1).name, model.geom(c.geom2).name)
                            for c in data.contact[:data.ncon]]
    excluded = {frozenset((model.body(int(pair & 0xFFFF)).name,
                           model.body(int(pair >> 16)).name)) for pair in model.exclude_signature}
    assert frozenset(('base_link', 'shoulder')) in excluded  # its parent is world-welded
    assert frozenset(('left', 'right')) in excluded  # siblings touching at home
    data.ctrl[:] = data.qpos[[model.joint(name).qposadr[0] for name in
                              ('pan', 'tilt', 'left_joint', 'right_joint')]]
    while data.time < 1.0:
        mujoco.mj_step(model, data)
    for name in ('left_joint', 'right_joint'):
        assert -1e-3 <= data.qpos[model.joint(name).qposadr[0]] <= 0.04 + 1e-3


def _two_joints(control: str) -> str:
    """Return a chain of two revolute joints (limits +-2) and the ``control`` block."""
    return f"""<robot name="pair">
  <link name="base_link">{INERTIAL}</link>
  <link name="a">{INERTIAL}</link>
  <link name="b">{INERTIAL}</link>
  <joint name="j1" type="revolute"><parent link="base_link"/><child link="a"/>
    <axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="10" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="a"/><child link="b"/>
    <origin xyz="0.3 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-2" upper="2" effort="10" velocity="1"/></joint>
  <ros2_control name="pair" type="system">
    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
{control}
  </ros2_control>
</robot>
"""


def _convert(tmp_path: Path, text: str, *options: str) -> tuple[object, str]:
    """Convert the URDF ``text``; return MuJoCo's model of the result and the output."""
    import mujoco
    source = tmp_path / 'robot.urdf'
    source.write_text(text)
    target = tmp_path / 'robot.xml'
    result = CliRunner().invoke(main, ['convert', str(source), str(target), '-f', *options])
    assert result.exit_code == 0, result.output
    return mujoco.MjModel.from_xml_path(str(target)), result.output


def test_ros2_control_initial_value_is_the_home_pose(tmp_path: Path) -> None:
    import mujoco
    model, _ = _convert(tmp_path, _two_joints("""
    <joint name="j1"><command_interface name="position"/>
      <state_interface name="position"><param name="initial_value">-1.57</param>
      </state_interface></joint>
    <joint name="j2"><param name="initial_value">5.0</param>
      <command_interface name="position"/><state_interface name="position"/></joint>"""))
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key('home').id)
    assert list(data.qpos) == [-1.57, 2.0]  # the second clamped to its upper limit


def test_a_ros2_control_transmission_is_the_gear(tmp_path: Path) -> None:
    model, output = _convert(tmp_path, _two_joints("""
    <joint name="j1"><command_interface name="position">
      <param name="min">-1</param><param name="max">1</param></command_interface></joint>
    <joint name="j2"><command_interface name="position"/></joint>
    <transmission name="t1"><plugin>transmission_interface/SimpleTransmission</plugin>
      <actuator name="a1" role="a1"/>
      <joint name="j1" role="j1"><mechanical_reduction>2.0</mechanical_reduction></joint>
    </transmission>
    <transmission name="t2"><plugin>transmission_interface/SimpleTransmission</plugin>
      <actuator name="a2" role="a2"><mechanical_reduction>4.0</mechanical_reduction>
      </actuator><joint name="j2" role="j2"/>
    </transmission>"""))
    gears = {model.actuator(number).name: model.actuator_gear[number][0]
             for number in range(model.nu)}
    assert gears == {'j1_position': 2.0, 'j2_position': 4.0}
    assert list(model.actuator_ctrlrange[0]) == [-2.0, 2.0]  # actuator units, as classic
    assert 'transmission' not in output


@pytest.mark.parametrize('option', [('--kp', '-5'), ('--kp', 'nan'), ('--kp', '0'),
                                    ('--kv', '-3'), ('--kv', 'inf')])
def test_a_bad_gain_is_refused_in_one_line(tmp_path: Path, option: tuple[str, str]) -> None:
    source = tmp_path / 'robot.urdf'
    source.write_text(_arm())
    target = tmp_path / 'robot.xml'
    result = CliRunner().invoke(main, ['convert', str(source), str(target), *option])
    assert result.exit_code == 2 and option[0] in result.output, result.output
    assert 'Traceback' not in result.output and not target.exists()


@pytest.mark.parametrize('gains', [{'kp': -1.0}, {'kv': float('nan')}])
def test_a_bad_gain_is_refused_by_the_api(gains: dict[str, float]) -> None:
    from urdfgenpy_ros import Inertial, Joint, JointLimit, Link, Robot
    from urdfgenpy_ros.model.errors import ModelError
    robot = Robot('arm').add_link(Link('base_link')).add_link(
        Link('a', inertial=Inertial.from_box(1.0, 0.1, 0.1, 0.1)))
    robot.add_joint(Joint('j1', 'revolute', 'base_link', 'a', axis=(0, 0, 1),
                          limit=JointLimit(-1, 1, effort=1, velocity=1)))
    with pytest.raises(ModelError, match=next(iter(gains))):
        robot.to_mjcf(**gains)


def test_a_zero_kv_is_a_servo_without_damping(tmp_path: Path) -> None:
    model, _ = _convert(tmp_path, _arm(), '--actuators', 'velocity', '--kv', '0')
    assert model.nu == 1


def test_strict_writes_nothing_and_reports_errors(tmp_path: Path) -> None:
    import json
    source = tmp_path / 'robot.urdf'
    source.write_text(_arm())  # the velocity limit is lost (M801)
    target = tmp_path / 'robot.xml'
    result = CliRunner().invoke(main, ['convert', str(source), str(target), '--strict',
                                       '--report', 'json'])
    assert result.exit_code == 1 and not target.exists()
    report = json.loads(result.stdout)
    assert report['errors'] == 1 and report['warnings'] == 0
    assert 'not written' in result.output and 'wrote' not in result.output
    model, _ = _convert(tmp_path, _arm())  # without --strict: written, MuJoCo reads it
    assert model.njnt == 1


def test_the_refusal_advice_is_true(tmp_path: Path) -> None:
    import mujoco
    bad_tensor = INERTIAL.replace('izz="0.001"', 'izz="0.003"')  # A + B < C: MuJoCo refuses
    source = tmp_path / 'tensor.urdf'
    source.write_text(_arm().replace(f'<link name="a">{INERTIAL}',
                                     f'<link name="a">{bad_tensor}'))
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'a.xml')])
    assert result.exit_code == 2 and 'urdfgenpy convert --fix' in result.output
    fixed = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'a.xml'),
                                      '--fix'])  # the advice, followed: MuJoCo reads it
    assert fixed.exit_code == 0, fixed.output
    assert mujoco.MjModel.from_xml_path(str(tmp_path / 'a.xml')).nbody == 3
    source.write_text(_arm().replace(f'<link name="a">{INERTIAL}', '<link name="a">'))
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'b.xml')])
    assert result.exit_code == 2 and 'I207' in result.output
    assert '--fix' not in result.output  # it repairs no missing inertial
    assert 'urdfgenpy inertia' in result.output


def test_actuators_option_reports_only_the_interfaces_it_did_not_write(
        tmp_path: Path) -> None:
    control = """
    <joint name="j1"><command_interface name="position"/>
      <command_interface name="velocity"/></joint>
    <joint name="j2"><command_interface name="position"/></joint>"""
    model, output = _convert(tmp_path, _two_joints(control), '--actuators', 'position')
    names = {model.actuator(number).name for number in range(model.nu)}
    assert names == {'j1_position', 'j2_position'}
    lost = [line for line in output.splitlines() if 'M805' in line and 'interface' in line]
    assert len(lost) == 1 and "'velocity' of joint 'j1'" in lost[0], lost


def test_unequal_mu1_mu2_says_mu1_is_the_friction_and_mu2_is_lost(tmp_path: Path) -> None:
    model, output = _convert(tmp_path, _arm(
        '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>',
        '<gazebo reference="a"><mu1>0.9</mu1><mu2>0.4</mu2></gazebo>'))
    assert model.geom_friction[0][0] == 0.9  # mu1 is MuJoCo's sliding friction
    lost = [line for line in output.splitlines() if '<mu' in line]
    assert len(lost) == 1 and 'M806' in lost[0] and '<mu2> 0.4 is not carried' in lost[0]
    assert '<mu1> 0.9 is it' in lost[0]


def test_the_gain_note_says_what_the_overlay_set(tmp_path: Path) -> None:
    overlay = tmp_path / 'overlay.xml'
    overlay.write_text('<mujoco><actuator><position name="j1_position" kp="300"/>'
                       '<position name="j2_position" kp="300"/></actuator></mujoco>')
    model, output = _convert(tmp_path, _two_joints(
        '<joint name="j1"><command_interface name="position"/></joint>'
        '<joint name="j2"><command_interface name="position"/></joint>'),
        '--overlay', str(overlay))
    assert list(model.actuator_gainprm[:, 0]) == [300.0, 300.0]
    note = [line for line in output.splitlines() if 'position actuators:' in line]
    assert len(note) == 1 and 'kp=300' in note[0] and 'kp=1 ' not in note[0], note


def test_the_api_warnings_point_at_the_callers_line(tmp_path: Path) -> None:
    import warnings
    from urdfgenpy_ros.formats import load
    source = tmp_path / 'robot.urdf'
    source.write_text(_arm())  # the velocity limit is lost (M801)
    robot = load(source)
    for write in (lambda: robot.to_mjcf(), lambda: robot.save(tmp_path / 'robot.xml')):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter('always')
            write()
        assert {Path(warning.filename).name for warning in caught} == {Path(__file__).name}
        assert 'M801' in str(caught[0].message)
        assert 'no actuator written' in str(caught[-1].message)
    import mujoco
    assert mujoco.MjModel.from_xml_path(str(tmp_path / 'robot.xml')).njnt == 1
