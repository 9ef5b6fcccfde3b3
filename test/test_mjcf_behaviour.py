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
The MJCF behaves as the robot does, judged by MuJoCo simulating it.

Resetting to the home keyframe holds the robot there; a stiff servo on a light finger
stays within its limits; per-joint gains reach the compiled actuators; a rotor's inertia
becomes armature; what is not written is said.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import require_module
import pytest
import registry_robots

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.formats.mjcf import MjcfResult, write_mjcf
from urdfgenpy_ros.model.errors import ModelError

# A two-joint arm: a shoulder that gravity loads, and a 5 g finger (a 1 x 1 x 4 cm box)
# whose servo steps across its 0-0.8 rad range. ros2_control homes the shoulder at 0.6.
ARM = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base_link">
    <inertial><mass value="2"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
  </link>
  <link name="upper">
    <collision><origin xyz="0.15 0 0"/><geometry><box size="0.3 0.04 0.04"/></geometry>
    </collision>
    <inertial><origin xyz="0.15 0 0"/><mass value="1"/>
      <inertia ixx="0.0003" ixy="0" ixz="0" iyy="0.0076" iyz="0" izz="0.0076"/></inertial>
  </link>
  <link name="finger">
    <inertial><origin xyz="0 0 0.02"/><mass value="0.005"/>
      <inertia ixx="7.083e-07" ixy="0" ixz="0" iyy="7.083e-07" iyz="0" izz="8.333e-08"/>
    </inertial>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base_link"/><child link="upper"/><origin xyz="0 0 0.1"/>
    <axis xyz="0 1 0"/><limit lower="-1.5" upper="1.5" effort="100" velocity="2"/>
  </joint>
  <joint name="finger_joint" type="revolute">
    <parent link="upper"/><child link="finger"/><origin xyz="0.3 0 0"/>
    <axis xyz="1 0 0"/><limit lower="0" upper="0.8" effort="20" velocity="2"/>
  </joint>
  <ros2_control name="arm" type="system">
    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
    <joint name="shoulder"><command_interface name="position"/>
      <state_interface name="position"><param name="initial_value">0.6</param>
      </state_interface></joint>
    <joint name="finger_joint"><command_interface name="position"/>
      <state_interface name="position"/></joint>
  </ros2_control>
{extra}</robot>
"""
ROTOR = """  <ros2_control name="drives" type="actuator">
    <hardware><plugin>mock_components/GenericSystem</plugin></hardware>
    <transmission name="shoulder_drive">
      <plugin>transmission_interface/SimpleTransmission</plugin>
      <actuator name="shoulder_motor"><mechanical_reduction>50</mechanical_reduction>
        <param name="rotor_inertia">2e-5</param></actuator>
      <joint name="shoulder" role="joint1"/>
    </transmission>
  </ros2_control>
"""


@pytest.fixture(autouse=True)
def _mujoco() -> None:
    require_module('mujoco')


def _arm(folder: Path, extra: str = '') -> Path:
    path = folder / 'arm.urdf'
    path.write_text(ARM.format(extra=extra))
    return path


def _model(path: Path):
    import mujoco
    return mujoco.MjModel.from_xml_path(str(path))


def _simulate(model, key: str, seconds: float, ctrl: dict[str, float] | None = None):
    """Reset to keyframe ``key``, set ``ctrl`` by actuator joint, run; return the qpos seen."""
    import mujoco
    import numpy
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY,
                                                               key))
    for actuator in range(model.nu):
        joint = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT,
                                  model.actuator_trnid[actuator, 0])
        if ctrl and joint in ctrl:
            data.ctrl[actuator] = ctrl[joint]
    seen = [data.qpos.copy()]
    for _ in range(int(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
        seen.append(data.qpos.copy())
    return numpy.array(seen)


def _qpos(model, joint: str) -> int:
    import mujoco
    return int(model.jnt_qposadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, joint)])


def test_resetting_to_home_holds_every_actuated_joint(tmp_path: Path) -> None:
    robot = Robot.from_urdf(_arm(tmp_path))
    write_mjcf(robot, tmp_path / 'arm.xml', kp=500, kv=50)
    model = _model(tmp_path / 'arm.xml')
    seen = _simulate(model, 'home', 1.0)
    assert seen[0][_qpos(model, 'shoulder')] == pytest.approx(0.6)
    for joint in ('shoulder', 'finger_joint'):
        column = seen[:, _qpos(model, joint)]
        assert abs(column - column[0]).max() < 0.02, joint


def test_a_keyframe_the_overlay_adds_gets_the_ctrl_of_its_pose(tmp_path: Path) -> None:
    overlay = tmp_path / 'overlay.xml'
    overlay.write_text('<mujoco><keyframe><key name="reach" qpos="-0.4 0.5"/></keyframe>'
                       '</mujoco>')
    write_mjcf(Robot.from_urdf(_arm(tmp_path)), tmp_path / 'arm.xml', kp=500, kv=50,
               overlay=overlay)
    model = _model(tmp_path / 'arm.xml')
    seen = _simulate(model, 'reach', 1.0)
    assert abs(seen[:, _qpos(model, 'shoulder')] + 0.4).max() < 0.02
    assert abs(seen[:, _qpos(model, 'finger_joint')] - 0.5).max() < 0.02


def _ros2_control_robot(name: str) -> tuple[Path, list[Path]]:
    """Return a registry robot with <ros2_control> position servos and its package folders."""
    from importlib import metadata
    for path in registry_robots.robots():
        if path.stem == name:
            return path, registry_robots.search_paths()
    try:
        share = Path(str(metadata.distribution('example-robot-data').locate_file(
            'cmeel.prefix/share/example-robot-data/robots')))
    except metadata.PackageNotFoundError:
        pytest.skip('example-robot-data is not installed (the test extra installs it)')
    found = sorted(share.glob(f'*/*/{name}.urdf'))
    if not found:
        pytest.skip(f'{name} is not installed (the test extra installs it)')
    return found[0], [share]


@pytest.mark.engine
@pytest.mark.parametrize('name', ['fr3', 'tiago_pro', 'xarm7'])
def test_registry_robots_hold_their_home(name: str, tmp_path: Path) -> None:
    """Robots with <ros2_control> position servos, at FR3's nominal gains."""
    path, paths = _ros2_control_robot(name)
    robot = Robot.from_xacro(path, {'ros2_control': 'true'}, search_paths=paths) \
        if name == 'fr3' else Robot.from_urdf(path)
    result = write_mjcf(robot, tmp_path / 'robot.xml', kp=4500, kv=450, search_paths=paths)
    model = _model(tmp_path / 'robot.xml')
    assert model.nu > 0, result.notes
    seen = _simulate(model, 'home', 1.0)
    for actuator in range(model.nu):
        column = seen[:, model.jnt_qposadr[model.actuator_trnid[actuator, 0]]]
        assert abs(column - column[0]).max() < 0.02, actuator


def _finger_step(folder: Path, **options) -> tuple[float, list[str]]:
    """Step the finger from open to closed; return how far it went past a limit, the notes."""
    result = write_mjcf(Robot.from_urdf(_arm(folder)), folder / 'arm.xml', **options)
    model = _model(folder / 'arm.xml')
    finger = _simulate(model, 'home', 0.5, {'finger_joint': 0.8, 'shoulder': 0.6}
                       )[:, _qpos(model, 'finger_joint')]
    return max(-finger.min(), finger.max() - 0.8), result.notes


def test_a_stiff_servo_on_a_light_finger_stays_within_its_limits(tmp_path: Path) -> None:
    past, notes = _finger_step(tmp_path, kp=100, kv=10)
    assert past < 0.05
    said = [note for note in notes if note.startswith('armature added')]
    assert len(said) == 1 and 'finger_joint' in said[0], notes


def test_an_undamped_servo_is_named_with_the_damping_that_holds_it(tmp_path: Path) -> None:
    _, notes = _finger_step(tmp_path, kp=100)
    said = [note for note in notes if 'critical damping' in note]
    assert len(said) == 1, notes
    critical = float(said[0].split('finger_joint ')[1].split(',')[0].rstrip(')'))
    past, _ = _finger_step(tmp_path, kp={'default': 100},
                           kv={'default': 0.0, 'finger_joint': critical})
    assert past < 0.05


def test_the_users_armature_is_kept_and_the_stable_gain_named(tmp_path: Path) -> None:
    overlay = tmp_path / 'overlay.xml'
    overlay.write_text('<mujoco><worldbody><body name="finger"><joint name="finger_joint" '
                       'armature="1e-5"/></body></worldbody></mujoco>')
    _, notes = _finger_step(tmp_path, kp=100, kv=10, overlay=overlay)
    said = [note for note in notes if note.startswith("joint 'finger_joint': kp 100 is")]
    assert len(said) == 1, notes
    assert _model(tmp_path / 'arm.xml').dof_armature[1] == pytest.approx(1e-5)
    stable = float(said[0].split(': kp ')[2].split(' ')[0])
    past, notes = _finger_step(tmp_path, kp={'default': 100, 'finger_joint': stable}, kv=10,
                               overlay=overlay)
    assert past < 0.05
    assert not [note for note in notes if 'is unstable' in note]


def test_per_joint_gains_reach_the_compiled_actuators(tmp_path: Path) -> None:
    import mujoco
    source = _arm(tmp_path)
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'arm.xml'),
                                       '--kp', '2000', '--kp', 'finger_joint=50',
                                       '--kv', 'shoulder=30'])
    assert result.exit_code == 0, result.output
    model = _model(tmp_path / 'arm.xml')
    gains = {}
    for actuator in range(model.nu):
        joint = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT,
                                  model.actuator_trnid[actuator, 0])
        gains[joint] = (model.actuator_gainprm[actuator, 0],
                        -model.actuator_biasprm[actuator, 2])
    assert gains == {'shoulder': (2000.0, 30.0), 'finger_joint': (50.0, 0.0)}
    assert 'position actuators: kp=2000 (given), finger_joint 50' in result.output


@pytest.mark.parametrize(('words', 'said'), [
    (['--kp', 'elbow=5'], "the robot has no joint 'elbow'"),
    (['--kp', 'shoulder=x'], 'give NUMBER or JOINT=NUMBER'),
    (['--kp', '5', '--kp', '6'], 'gives the default twice'),
    (['--kp', 'shoulder=-1'], 'a finite number above zero'),
])
def test_a_bad_gain_is_one_line(tmp_path: Path, words: list[str], said: str) -> None:
    result = CliRunner().invoke(main, ['convert', str(_arm(tmp_path)),
                                       str(tmp_path / 'arm.xml'), *words])
    assert result.exit_code == 2
    assert said in result.output and 'Traceback' not in result.output
    assert not (tmp_path / 'arm.xml').exists()


def test_a_gain_mapping_of_a_wrong_kind_is_refused(tmp_path: Path) -> None:
    robot = Robot.from_urdf(_arm(tmp_path))
    with pytest.raises(ModelError, match=r"kp\['shoulder'\]="):
        robot.to_mjcf(kp={'shoulder': 'stiff'})
    with pytest.raises(ModelError, match='give a number, or a mapping'):
        robot.to_mjcf(kp=[100])


def test_a_rotor_inertia_becomes_the_reflected_armature(tmp_path: Path) -> None:
    robot = Robot.from_urdf(_arm(tmp_path, ROTOR))
    # kp is in actuator units: through the 50:1 reduction the joint sees 0.2 x 50^2
    result = write_mjcf(robot, tmp_path / 'arm.xml', kp=0.2, kv=0.02)
    model = _model(tmp_path / 'arm.xml')
    assert model.dof_armature[0] == pytest.approx(2e-5 * 50 * 50)
    assert any('rotor inertia x reduction^2' in note and 'shoulder 0.05' in note
               for note in result.notes)


def test_no_actuator_is_said(tmp_path: Path) -> None:
    text = ARM.format(extra='')
    start, end = text.index('  <ros2_control'), text.index('</ros2_control>')
    path = tmp_path / 'limp.urdf'
    path.write_text(text[:start] + text[end + len('</ros2_control>\n'):])
    result = write_mjcf(Robot.from_urdf(path))
    assert _model_of(result.text).nu == 0
    assert any(note.startswith('no actuator written') and '--actuators position' in note
               for note in result.advice)
    with pytest.warns(UserWarning, match='arm: no actuator written'):
        Robot.from_urdf(path).to_mjcf()
    with_servos = write_mjcf(Robot.from_urdf(path), actuators='position')
    assert not any(note.startswith('no actuator written') for note in with_servos.notes)


def _model_of(text: str):
    import mujoco
    return mujoco.MjModel.from_xml_string(text)


def test_a_mesh_missing_from_a_found_package_names_the_folder(tmp_path: Path) -> None:
    package = tmp_path / 'src' / 'arm_description'
    (package / 'meshes').mkdir(parents=True)
    (package / 'package.xml').write_text(
        '<package format="3"><name>arm_description</name></package>')
    text = ARM.format(extra='').replace(
        '<link name="finger">',
        '<link name="finger"><visual><geometry>'
        '<mesh filename="package://arm_description/meshes/finger.stl"/></geometry></visual>')
    path = tmp_path / 'arm.urdf'
    path.write_text(text)
    result: MjcfResult = write_mjcf(Robot.from_urdf(path), search_paths=[tmp_path / 'src'])
    said = [finding for finding in result.findings if finding.code == 'M809']
    assert len(said) == 1
    assert f"package 'arm_description' was found at {package}" in said[0].hint
    assert 'source' not in said[0].hint
