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
MJCF export, judged by MuJoCo, pinocchio, yourdfpy, trimesh and a marked fixture.

MuJoCo compiles and steps the models; pinocchio and yourdfpy give the URDF's own numbers
and kinematics; trimesh reads the DAE volumes; the fixture marks each expected finding.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
import re

from click.testing import CliRunner
from helpers import assert_check_urdf_accepts, FIXTURES, require_module
import mjcf_judge
import pytest

from urdfgenpy_ros import Box, Inertial, Joint, JointLimit, JointMimic, Link, Origin, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.formats.mjcf import MjcfRefusedError, write_mjcf
from urdfgenpy_ros.model.geometry import Mesh
from urdfgenpy_ros.model.link import Visual

EVERYTHING = FIXTURES / 'mjcf' / 'everything.urdf'


@pytest.fixture(autouse=True)
def _mujoco() -> None:
    require_module('mujoco')


def test_every_loss_is_named_on_its_line_and_nothing_else() -> None:
    assert_check_urdf_accepts(EVERYTHING)  # a real URDF, as ROS reads it
    result = write_mjcf(load(EVERYTHING))
    reported = {(finding.location.line, finding.code) for finding in result.findings}
    assert len(result.findings) == len(reported)  # one finding per thing
    assert reported == mjcf_judge.marked_losses(EVERYTHING)
    assert all(finding.location.file == str(EVERYTHING) for finding in result.findings)


def test_strict_exits_1_on_a_loss_and_0_without(tmp_path: Path) -> None:
    runner = CliRunner()
    target = tmp_path / 'robot.xml'
    result = runner.invoke(main, ['convert', str(EVERYTHING), str(target), '--strict'])
    assert result.exit_code == 1, result.output
    assert 'error M808' in result.output and not target.exists()  # nothing written
    assert runner.invoke(main, ['convert', str(EVERYTHING), str(target), '-f']).exit_code == 0
    clean = Robot('clean').add_link(Link('base_link')).add_link(
        Link('wheel', inertial=Inertial.from_box(1.0, 0.1, 0.1, 0.1)))
    clean.add_joint(Joint('spin', 'continuous', 'base_link', 'wheel', axis=(0, 0, 1)))
    source = tmp_path / 'clean.urdf'
    clean.to_urdf(source)
    result = runner.invoke(main, ['convert', str(source), str(tmp_path / 'clean.xml'),
                                  '--strict'])
    assert result.exit_code == 0, result.output


def test_report_in_checks_json_and_sarif(tmp_path: Path) -> None:
    jsonschema = require_module('jsonschema')
    runner = CliRunner()  # click 8.2: result.stdout holds standard output only
    result = runner.invoke(main, ['convert', str(EVERYTHING), str(tmp_path / 'a.xml'),
                                  '--report', 'json'])
    document = json.loads(result.stdout)
    codes = {(entry['line'], entry['code']) for entry in document['files'][0]['findings']}
    assert codes == mjcf_judge.marked_losses(EVERYTHING) and document['warnings'] == len(codes)
    result = runner.invoke(main, ['convert', str(EVERYTHING), str(tmp_path / 'b.xml'),
                                  '--report', 'sarif'])
    sarif = json.loads(result.stdout)
    assert {rule['id'] for rule in sarif['runs'][0]['tool']['driver']['rules']} == {
        code for _, code in codes}
    assert jsonschema is not None


def test_everything_compiles_with_the_urdfs_physics(tmp_path: Path) -> None:
    robot = load(EVERYTHING)
    robot.to_mjcf(tmp_path / 'robot.xml')
    model = mjcf_judge.compile_mjcf(tmp_path / 'robot.xml')
    mjcf_judge.assert_steps_finite(model)
    assert mjcf_judge.assert_inertia_as_urdf(model, EVERYTHING) == 7
    assert mjcf_judge.assert_fk_as_pinocchio(model, EVERYTHING) > 0
    assert mjcf_judge.assert_joints_as_urdf(model, robot) == 4
    assert model.opt.timestep == 0.001  # the URDF's <mujoco><option>
    wheel = [index for index in range(model.ngeom)
             if model.geom_bodyid[index] == model.body('wheel').id]
    assert [model.geom_friction[index][0] for index in wheel] == [0.9]  # <gazebo> mu1


def test_ros2_control_interfaces_become_actuators_of_their_types(tmp_path: Path) -> None:
    import mujoco
    model = mujoco.MjModel.from_xml_string(write_mjcf(load(EVERYTHING), kp=50.0).text)
    kinds = {}
    for index in range(model.nu):
        joint = model.joint(model.actuator_trnid[index][0]).name
        # position servo: bias -kp * q; velocity servo: bias -kv * qdot (MuJoCo's encoding)
        kind = 'position' if model.actuator_biasprm[index][1] < 0 else 'velocity'
        kinds[joint] = (kind, tuple(model.actuator_ctrlrange[index]),
                        model.actuator_gear[index][0])
    # shoulder: min/max -1..1 times the transmission's reduction 2; wheel: +-velocity limit
    assert kinds == {'shoulder': ('position', (-2.0, 2.0), 2.0),
                     'wheel_joint': ('velocity', (-10.0, 10.0), 1.0)}
    assert 'finger_joint' not in kinds  # a mimic follower is never actuated


def _mimic_pair() -> Robot:
    robot = Robot('pair').add_link(Link('base_link'))
    for name in ('leader_link', 'follower_link'):
        robot.add_link(Link(name, inertial=Inertial.from_box(
            0.5, 0.1, 0.02, 0.02, origin=Origin((0.05, 0.0, 0.0)))))
    robot.add_joint(Joint('leader', 'revolute', 'base_link', 'leader_link', axis=(0, 1, 0),
                          limit=JointLimit(-2, 2, effort=10, velocity=1)))
    robot.add_joint(Joint('follower', 'revolute', 'base_link', 'follower_link',
                          origin=Origin((0, 0.2, 0)), axis=(0, 1, 0),
                          limit=JointLimit(-3, 3, effort=10, velocity=1),
                          mimic=JointMimic('leader', multiplier=-1.5, offset=0.1)))
    return robot


def test_a_driven_mimic_pair_keeps_the_urdfs_relation() -> None:
    import mujoco
    model = mujoco.MjModel.from_xml_string(write_mjcf(_mimic_pair(), actuators='motor').text)
    assert model.nu == 1 and model.neq == 1
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    worst, moved = 0.0, 0.0
    while data.time < 1.0:
        data.ctrl[0] = 0.02 * math.sin(2 * math.pi * data.time)
        mujoco.mj_step(model, data)
        worst = max(worst, abs(data.qpos[1] - (0.1 - 1.5 * data.qpos[0])))
        moved = max(moved, abs(data.qpos[0]))
    assert moved > 0.1 and worst < 1e-6


def _dae(path: Path) -> None:
    """Write a DAE in millimetres, Y up, of a box off its origin (trimesh writes it)."""
    trimesh = require_module('trimesh')
    box = trimesh.creation.box((100.0, 200.0, 300.0))
    box.apply_translation((50.0, 0.0, 100.0))
    text = trimesh.exchange.dae.export_collada(box).decode()
    text = re.sub(r'<created>.*?</modified>', '', text, flags=re.DOTALL)
    path.write_text(text.replace('<up_axis>', '<unit meter="0.001" name="millimeter"/>'
                                 '<up_axis>'))


def test_a_dae_mesh_keeps_its_volume_and_place(tmp_path: Path) -> None:
    import mujoco
    import numpy
    trimesh = require_module('trimesh')
    _dae(tmp_path / 'part.dae')
    robot = Robot('dae').add_link(Link('base_link')).add_link(Link(
        'part', inertial=Inertial.from_box(1.0, 0.1, 0.1, 0.1),
        visuals=[Visual(Mesh(str(tmp_path / 'part.dae'), scale=(1.0, 2.0, 1.0)),
                        origin=Origin((0.1, 0.2, 0.3), (0.3, 0.2, 0.1)))]))
    robot.add_joint(Joint('fixed', 'fixed', 'base_link', 'part',
                          origin=Origin((0.0, 0.0, 1.0), (0.0, 0.0, 0.5))))
    (tmp_path / 'out').mkdir()
    robot.to_mjcf(tmp_path / 'out' / 'robot.xml', meshdir='meshes')
    source = trimesh.load(str(tmp_path / 'part.dae'), force='mesh')
    converted = trimesh.load(str(tmp_path / 'out' / 'meshes' / 'part.obj'), force='mesh')
    assert abs(converted.volume - source.volume * 1e-9) <= 1e-6 * abs(converted.volume)
    # where the URDF puts it: millimetres to metres (the up axis ignored, as RViz does),
    # the scale, the origins
    vertices = numpy.asarray(source.vertices) * 0.001
    vertices = vertices * (1.0, 2.0, 1.0)
    for xyz, rpy in (((0.1, 0.2, 0.3), (0.3, 0.2, 0.1)), ((0.0, 0.0, 1.0), (0.0, 0.0, 0.5))):
        matrix = trimesh.transformations.euler_matrix(*rpy, axes='sxyz')
        matrix[:3, 3] = xyz
        vertices = vertices @ matrix[:3, :3].T + matrix[:3, 3]
    model = mjcf_judge.compile_mjcf(tmp_path / 'out' / 'robot.xml')
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    geom = next(index for index in range(model.ngeom) if model.geom_type[index] == 7)
    mesh = model.geom_dataid[geom]
    start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
    local = model.mesh_vert[start:start + count]
    placed = local @ data.geom_xmat[geom].reshape(3, 3).T + data.geom_xpos[geom]
    assert numpy.allclose(placed.min(axis=0), vertices.min(axis=0), rtol=0, atol=1e-6)
    assert numpy.allclose(placed.max(axis=0), vertices.max(axis=0), rtol=0, atol=1e-6)


def test_two_runs_write_the_same_bytes(tmp_path: Path) -> None:
    _dae(tmp_path / 'part.dae')
    robot = load(EVERYTHING)
    robot.get_link('arm').add_visual(Visual(Mesh(str(tmp_path / 'part.dae'))))
    files = []
    for run in ('a', 'b'):
        robot.to_mjcf(tmp_path / run / 'robot.xml', scene=True)
        files.append({path.relative_to(tmp_path / run): path.read_bytes()
                      for path in sorted((tmp_path / run).rglob('*')) if path.is_file()})
    assert files[0] == files[1] and len(files[0]) == 3
    robot.save(tmp_path / 'c' / 'robot.mjcf', scene=True)  # .mjcf is MJCF too, options pass
    assert (tmp_path / 'c' / 'robot.mjcf').read_bytes() == files[0][Path('robot.xml')]


def test_fused_links_stay_as_sites_with_the_lumped_inertia(tmp_path: Path) -> None:
    robot = load(EVERYTHING)
    robot.to_mjcf(tmp_path / 'robot.xml', fuse_fixed=True)
    model = mjcf_judge.compile_mjcf(tmp_path / 'robot.xml')
    assert model.site('tool') is not None and model.nbody == len(robot.links)  # 9-1+world
    assert mjcf_judge.assert_inertia_as_pinocchio(model, EVERYTHING) > 0
    assert mjcf_judge.assert_fk_as_pinocchio(model, EVERYTHING) > 0


def test_base_fixed_floating_and_world(tmp_path: Path) -> None:
    import mujoco
    pair = _mimic_pair()
    pair.get_link('base_link').inertial = Inertial.from_box(2.0, 0.2, 0.2, 0.2)
    fixed = write_mjcf(pair)
    assert 'base: fixed (the default' in fixed.notes[0] and 'base: fixed' in fixed.text
    model = mujoco.MjModel.from_xml_string(write_mjcf(pair, base='floating').text)
    assert model.jnt_type[0] == mujoco.mjtJoint.mjJNT_FREE
    data = mujoco.MjData(model)
    for _ in range(500):
        mujoco.mj_step(model, data)
    assert data.qpos[2] < -0.5  # it falls
    welded = Robot('welded').add_link(Link('world')).add_link(
        Link('base_link', inertial=Inertial.from_box(1.0, 0.1, 0.1, 0.1)))
    welded.add_joint(Joint('weld', 'fixed', 'world', 'base_link', origin=Origin((0, 0, 1))))
    model = mujoco.MjModel.from_xml_string(write_mjcf(welded, base='floating').text)
    assert model.njnt == 0 and model.nbody == 2 and model.body_pos[1][2] == 1.0


def test_a_tensor_mujoco_refuses_is_refused_before_writing(tmp_path: Path) -> None:
    import mujoco
    robot = _mimic_pair()
    robot.get_link('leader_link').inertial = Inertial(1.0, 1.0, 0.0, 0.0, 1.0, 0.0, 3.0)
    with pytest.raises(MjcfRefusedError) as refused:
        write_mjcf(robot, tmp_path / 'robot.xml')
    assert [finding.code for finding in refused.value.findings] == ['I203']
    assert not any(tmp_path.iterdir())
    with pytest.raises(ValueError, match='A \\+ B >= C'):  # MuJoCo's own import agrees
        mujoco.MjModel.from_xml_string(robot.to_urdf())
    source = tmp_path / 'bad.urdf'
    robot.to_urdf(source)
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'bad.xml')])
    assert result.exit_code == 2 and 'I203' in result.output
    assert not (tmp_path / 'bad.xml').exists()


def test_the_overlay_survives_a_new_conversion(tmp_path: Path) -> None:
    import mujoco
    overlay = tmp_path / 'extra.xml'
    overlay.write_text('<mujoco><actuator><position name="shoulder_position" kp="321"/>'
                       '</actuator><worldbody><body name="arm"><site name="marker" '
                       'pos="0.3 0 0"/></body></worldbody><keyframe><key name="up" '
                       'qpos="0 0 0 0 0 0 1 0 0 0 0.01 0.0035"/></keyframe></mujoco>')
    robot = load(EVERYTHING)
    for _ in range(2):  # converting again after the URDF changes keeps the hand tuning
        robot.get_link('arm').inertial.mass += 0.5
        model = mujoco.MjModel.from_xml_string(write_mjcf(robot, overlay=overlay).text)
        assert model.actuator('shoulder_position').gainprm[0] == 321.0
        assert model.site('marker').bodyid == model.body('arm').id
        assert model.nkey == 2 and model.body('arm').mass[0] == robot.get_link(
            'arm').inertial.mass


def test_home_keyframe_is_zero_clamped_to_the_limits() -> None:
    import mujoco
    robot = _mimic_pair()
    robot.get_joint('leader').limit = JointLimit(0.25, 1.0, effort=1, velocity=1)
    model = mujoco.MjModel.from_xml_string(write_mjcf(robot).text)
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key('home').id)
    assert list(data.qpos) == [0.25, 0.1 - 1.5 * 0.25]


def test_convert_help_lists_the_mjcf_options() -> None:
    result = CliRunner().invoke(main, ['convert', '--help'])
    for option in ('--fuse-fixed', '--base', '--actuators', '--scene', '--overlay',
                   '--strict', '--kp'):
        assert option in result.output


def test_mjcf_options_on_other_output_are_refused(tmp_path: Path) -> None:
    result = CliRunner().invoke(main, ['convert', str(EVERYTHING), str(tmp_path / 'r.sdf'),
                                       '--fuse-fixed'])
    assert result.exit_code == 2 and result.output.count('\n') == 1
    assert '--fuse-fixed apply to MJCF output' in result.output


def test_a_robot_without_inertial_on_a_moving_link_is_refused() -> None:
    robot = Robot('r').add_link(Link('base_link')).add_link(Link('arm', visuals=[
        Visual(Box(0.1, 0.1, 0.1))]))
    robot.add_joint(Joint('j', 'continuous', 'base_link', 'arm'))
    with pytest.raises(MjcfRefusedError, match='nothing written'):
        write_mjcf(robot)


NAN_ARM = """<?xml version="1.0"?>
<robot name="nanbot">
  <link name="base"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="arm"><inertial><mass value="1"/>
    <inertia ixx="nan" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
</robot>
"""


def test_a_nan_inertia_mujoco_refuses_is_refused_before_writing(tmp_path: Path) -> None:
    require_module('mujoco')
    import mujoco
    urdf, out = tmp_path / 'nanbot.urdf', tmp_path / 'nanbot.xml'
    urdf.write_text(NAN_ARM)
    with pytest.raises(ValueError, match='mass and inertia of moving bodies'):
        mujoco.MjModel.from_xml_path(str(urdf))  # MuJoCo's own import refuses it
    result = CliRunner().invoke(main, ['convert', str(urdf), str(out)])
    assert result.exit_code == 2 and not out.exists()
    assert 'nanbot.urdf:5:' in result.stderr and "error R305 link 'arm'" in result.stderr
    assert 'write finite numbers' in result.stderr and 'Traceback' not in result.output


def test_sensors_measure_what_gazebos_would() -> None:
    import mujoco
    import numpy
    from urdfgenpy_ros.model.link import Collision
    from urdfgenpy_ros.model.sensors import Camera, ForceTorque, Imu, Lidar
    robot = Robot('sensing').add_link(Link('base_link', inertial=Inertial.from_box(
        1.0, 0.1, 0.1, 0.1))).add_link(Link('head', inertial=Inertial.from_box(
            1.0, 0.1, 0.1, 0.1))).add_link(Link('wall', collisions=[Collision(Box(0.1, 4, 4))]))
    robot.add_joint(Joint('neck', 'revolute', 'base_link', 'head', axis=(0, 0, 1),
                          origin=Origin((0, 0, 1), (0, 0, 0.3)),
                          limit=JointLimit(-1, 1, effort=1, velocity=1)))
    robot.add_joint(Joint('wall_joint', 'fixed', 'base_link', 'wall',
                          origin=Origin((2.05, 0, 1))))
    head = robot.get_link('head')
    head.add_sensor(Camera('cam', origin=Origin((0.1, 0, 0.05), (0, 0.2, 0)), fov=1.2))
    head.add_sensor(Imu('imu', origin=Origin((0, 0, 0.02), (0.1, 0, 0))))
    head.add_sensor(Lidar('scan', samples=5, min_angle=-0.5, max_angle=0.5, range_max=30.0))
    robot.get_joint('neck').add_sensor(ForceTorque('ft'))
    result = write_mjcf(robot)
    assert [finding.code for finding in result.findings] == ['M801']  # the sensors are carried
    model = mujoco.MjModel.from_xml_string(result.text)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)

    def read(name: str) -> numpy.ndarray:
        sensor = model.sensor(name)
        return data.sensordata[sensor.adr[0]:sensor.adr[0] + sensor.dim[0]]

    # rays at 0.3 + (-0.5 .. 0.5) rad hit the wall 2 m ahead at 2 / cos(angle), or miss
    for index, angle in enumerate(0.3 + numpy.linspace(-0.5, 0.5, 5)):
        hits = abs(2.0 * math.tan(angle)) < 2.0
        expected = 2.0 / math.cos(angle) if hits else -1.0
        assert abs(read(f'scan_ray{index}')[0] - expected) < 1e-9
    gravity = 9.81  # an accelerometer at rest reads the reaction to gravity, in its frame
    assert numpy.allclose(read('imu_accelerometer'),
                          (0, gravity * math.sin(0.1), gravity * math.cos(0.1)), atol=1e-9)
    assert numpy.allclose(read('ft_torque'), 0.0, atol=1e-9) and read('ft_force')[2] > 0
    # the camera looks along the sensor's +X (yawed 0.3, pitched 0.2 down), +Z up
    camera = model.camera('cam')
    axes = data.cam_xmat[camera.id].reshape(3, 3)
    forward = (math.cos(0.3) * math.cos(0.2), math.sin(0.3) * math.cos(0.2), -math.sin(0.2))
    assert numpy.allclose(-axes[:, 2], forward, atol=1e-12)
    assert abs(model.cam_fovy[camera.id] - math.degrees(2 * math.atan(
        math.tan(0.6) * 480 / 640))) < 1e-9
    head.sensors[2].vertical_samples = 16  # a 3D lidar: one ring is written, and said
    assert sorted(finding.code for finding in write_mjcf(robot).findings) == ['M801', 'M806']


def test_check_engines_mujoco_says_what_mujocos_import_drops(tmp_path: Path) -> None:
    import mujoco
    from urdfgenpy_ros.model.extensions import Extension
    from urdfgenpy_ros.model.link import Collision
    robot = _mimic_pair()
    robot.get_link('leader_link').add_collision(Collision(Box(0.1, 0.02, 0.02)))
    robot.add_extension(Extension.ros2_control('pair', '<joint name="leader">'
                                               '<command_interface name="position"/></joint>'))
    friction = Extension.gazebo('<mu1>0.7</mu1><mu2>0.7</mu2>')
    robot.get_link('leader_link').add_extension(friction)
    source = tmp_path / 'pair.urdf'
    robot.to_urdf(source)
    theirs = mujoco.MjModel.from_xml_path(str(source))  # MuJoCo's own URDF import
    assert theirs.nu == 0 and theirs.geom_friction[0][0] == 1.0
    ours = mujoco.MjModel.from_xml_string(write_mjcf(load(source)).text)
    geom = next(index for index in range(ours.ngeom) if ours.geom_group[index] == 3)
    assert ours.nu == 1 and ours.geom_friction[geom][0] == 0.7
    result = CliRunner().invoke(main, ['check', str(source), '--engines', 'mujoco',
                                       '--format', 'json'])
    found = {(entry['code'], entry['element'], entry['line'])
             for entry in json.loads(result.stdout)['files'][0]['findings']
             if entry['code'] in ('M508', 'M509')}
    text = source.read_text().splitlines()
    line = next(number for number, row in enumerate(text, 1) if 'command_interface' in row)
    block = next(number for number, row in enumerate(text, 1) if 'gazebo reference' in row)
    assert found == {('M508', "joint 'leader'", line), ('M509', "link 'leader_link'", block)}


def test_every_input_converts_a_dh_table_an_assembly_and_xacro(tmp_path: Path) -> None:
    from urdfgenpy_ros.dh import DHTable
    from urdfgenpy_ros.examples import pan_tilt_unit
    csv = tmp_path / 'arm.csv'
    csv.write_text('# convention: standard\njoint,a,alpha,d,theta_offset,type,lower,upper\n'
                   'shoulder,0,1.5707963267948966,0.1,0,revolute,-2,2\n'
                   'slide,0,0,0.2,0,prismatic,0,0.5\n')
    pan_tilt_unit().to_xacro(tmp_path / 'ptu.urdf.xacro')
    pan_tilt_unit().to_urdf(tmp_path / 'ptu.urdf')
    assembly = tmp_path / 'two.assembly.yaml'
    assembly.write_text('name: two\nparts:\n  - file: ptu.urdf\n  - file: ptu.urdf\n'
                        '    at: tilt_link\n    prefix: top_\n')
    for source, joints in ((csv, 2), (tmp_path / 'ptu.urdf.xacro', 2), (assembly, 4)):
        target = tmp_path / f'{source.name}.xml'
        result = CliRunner().invoke(main, ['convert', str(source), str(target)])
        assert result.exit_code == 0, result.output
        model = mjcf_judge.compile_mjcf(target)
        assert model.njnt == joints
        mjcf_judge.assert_steps_finite(model)
    # a DH skeleton's base has no mass: floating, MuJoCo would refuse it, so we do first
    assert DHTable.from_file(csv).to_robot('arm').root.inertial is None
    result = CliRunner().invoke(main, ['convert', str(csv), str(tmp_path / 'f.xml'),
                                       '--base', 'floating'])
    assert result.exit_code == 2 and 'I201' in result.output and 'floating' in result.output


def test_losses_in_a_xacro_file_point_at_its_lines(tmp_path: Path) -> None:
    from urdfgenpy_ros.examples import pan_tilt_unit
    source = tmp_path / 'ptu.urdf.xacro'
    pan_tilt_unit().to_xacro(source)
    lines = source.read_text().splitlines()
    result = write_mjcf(load(source))
    for finding in result.findings:  # the velocity limits, at their joint's <limit>
        name = finding.element.split("'")[1]
        assert finding.location.file == str(source)
        assert finding.location.path == f"/robot/joint[@name='{name}']/limit"
        assert lines[finding.location.line - 1][finding.location.column - 1:].startswith(
            '<limit')
        opening = max(number for number, line in enumerate(lines[:finding.location.line])
                      if '<joint name=' in line)
        assert f'<joint name="{name}"' in lines[opening]
    assert [finding.code for finding in result.findings] == ['M801', 'M801']


@pytest.mark.parametrize('suffix', ['.ply', '.glb'])
def test_ply_and_glb_meshes_are_converted_with_their_volume(suffix: str,
                                                            tmp_path: Path) -> None:
    trimesh = require_module('trimesh')
    box = trimesh.creation.box((0.1, 0.2, 0.3))
    box.export(str(tmp_path / f'part{suffix}'))
    robot = Robot('r').add_link(Link('base_link', inertial=Inertial.from_box(
        1.0, 0.1, 0.2, 0.3), visuals=[Visual(Mesh(str(tmp_path / f'part{suffix}')))]))
    robot.to_mjcf(tmp_path / 'out' / 'robot.xml')
    converted = trimesh.load(str(tmp_path / 'out' / 'assets' / 'part.obj'), force='mesh')
    source = trimesh.load(str(tmp_path / f'part{suffix}'), force='mesh')
    assert abs(converted.volume - source.volume) <= 1e-6 * source.volume
    assert mjcf_judge.compile_mjcf(tmp_path / 'out' / 'robot.xml').nmesh == 1


def test_the_world_links_inertial_is_a_loss() -> None:
    robot = Robot('welded').add_link(Link('world', inertial=Inertial.from_box(
        1.0, 0.1, 0.1, 0.1))).add_link(Link('base_link', inertial=Inertial.from_box(
            1.0, 0.1, 0.1, 0.1)))
    robot.add_joint(Joint('weld', 'fixed', 'world', 'base_link'))
    result = write_mjcf(robot)
    assert [(finding.code, finding.element) for finding in result.findings] == [
        ('M807', "link 'world'")]


def test_a_mimic_mujoco_cannot_couple_is_a_loss() -> None:
    robot = _mimic_pair()
    robot.get_joint('follower').type = 'fixed'  # a mimic on a fixed joint couples nothing
    result = write_mjcf(robot)
    assert [(finding.code, finding.element) for finding in result.findings
            if finding.code != 'M801'] == [('M807', "joint 'follower'")]
    assert '<equality>' not in result.text


def test_undeclared_prefixes_convert_and_are_named_as_losses(tmp_path: Path) -> None:
    require_module('mujoco')
    import mujoco
    out = tmp_path / 'robot.xml'
    source = FIXTURES / 'robots' / 'undeclared_prefix.urdf'
    result = CliRunner().invoke(main, ['convert', str(source), str(out)])
    assert result.exit_code == 0, result.output
    model = mujoco.MjModel.from_xml_path(str(out))  # MuJoCo judges what was written
    assert (model.nbody, model.njnt) == (3, 1)
    assert 'drake:collision_filter_group' in result.output  # what MJCF cannot carry, named
    assert 'Traceback' not in result.output


def test_convert_replaces_no_file_of_the_users_without_force(tmp_path: Path) -> None:
    from urdfgenpy_ros.examples import pan_tilt_unit
    source = tmp_path / 'ptu.urdf'
    pan_tilt_unit().to_urdf(source)
    mine = tmp_path / 'scene.xml'
    mine.write_text('<mujoco><!-- my own scene --></mujoco>')
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'ptu.xml'),
                                       '--scene'])
    assert result.exit_code == 2 and 'scene.xml exists: pass --force' in result.output
    assert 'my own scene' in mine.read_text() and not (tmp_path / 'ptu.xml').exists()
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'ptu.xml'),
                                       '--scene', '--force'])
    assert result.exit_code == 0 and 'include file="ptu.xml"' in mine.read_text()
