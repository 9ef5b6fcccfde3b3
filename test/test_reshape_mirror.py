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
Mirrored limbs: judged by pinocchio, check_urdf, yourdfpy, MuJoCo and trimesh.

At mirrored joint positions, pinocchio's pose of every link of the copy must be the
reflection of the original's (``S W D``); the mirrored meshes keep their volume and their
bounding box is the reflected one; mimic joints keep following their leader (yourdfpy
moves them).
"""

from __future__ import annotations

from pathlib import Path
import random

from click.testing import CliRunner
from helpers import assert_check_urdf_accepts, require_module
import pytest
from test_reshape_dh import example_robot

from urdfgenpy_ros import (
    Box, Extension, Joint, JointLimit, JointMimic, Link, ModelError, Origin, Robot, Visual)
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.reshape.mirror import mirror_subtree

LIMBS = {  # file, first link of the limb, renaming
    'talos_leg': ('talos_data/robots/talos_reduced.urdf', 'leg_left_1_link',
                  {'left': 'mirror'}),
    'talos_arm': ('talos_data/robots/talos_reduced.urdf', 'arm_left_1_link',
                  {'left': 'mirror'}),
    'solo12_leg': ('solo_description/robots/solo12.urdf', 'FL_SHOULDER', {'FL_': 'ML_'}),
}


def _share() -> Path:
    return example_robot('.').parent.parent  # holds the package folder example-robot-data


def _absolute(text: str) -> str:
    """Return URDF text whose package:// and file:// mesh URIs are paths (for MuJoCo)."""
    return text.replace('package://example-robot-data/', f'{_share()}/example-robot-data/'
                        ).replace('file://', '')


def _reflection(axis: int):
    numpy = require_module('numpy')
    flip = numpy.eye(4)
    flip[axis, axis] = -1.0
    return flip


@pytest.mark.parametrize('limb', sorted(LIMBS))
def test_mirrored_limb_moves_as_the_reflection_and_loads_everywhere(limb: str,
                                                                    tmp_path: Path) -> None:
    numpy = require_module('numpy')
    pin = require_module('pinocchio')
    relative, root, rename = LIMBS[limb]
    robot = Robot.from_urdf(example_robot(relative))
    original = {link.name for link in robot.subtree(root)}
    rules = mirror_subtree(robot, root, 'xz', None, rename, mesh_folder=tmp_path / 'meshes',
                           search_paths=(_share(),))
    written = tmp_path / 'mirrored.urdf'
    written.write_text(_absolute(robot.to_urdf()))
    assert_check_urdf_accepts(written)
    model = pin.buildModelFromUrdf(str(written))
    data = model.createData()
    rng = random.Random(11)
    signs = {rule.original: (rule.name, rule.sign) for rule in rules}
    q = pin.neutral(model)
    for name, (twin, sign) in signs.items():
        value = rng.uniform(-1.0, 1.0)
        q[model.joints[model.getJointId(name)].idx_q] = value
        q[model.joints[model.getJointId(twin)].idx_q] = sign * value
    pin.framesForwardKinematics(model, data, q)
    flip = _reflection(1)
    renamed = {name: _renamed(name, rename) for name in original}
    for name in original:
        mine = data.oMf[model.getFrameId(name)].homogeneous
        copy = data.oMf[model.getFrameId(renamed[name])].homogeneous
        assert numpy.abs(copy - flip @ mine @ flip).max() < 1e-9, name
    yourdfpy = require_module('yourdfpy')
    loaded = yourdfpy.URDF.load(str(written), load_meshes=True, build_scene_graph=True)
    assert set(loaded.link_map) >= set(renamed.values())
    mujoco = require_module('mujoco')
    assert mujoco.MjModel.from_xml_path(str(written)).njnt >= len(rules)


def _renamed(name: str, rename: dict[str, str]) -> str:
    for old, new in rename.items():
        name = name.replace(old, new)
    return name


def test_mirrored_mesh_keeps_volume_and_its_bounds_are_reflected(tmp_path: Path) -> None:
    trimesh = require_module('trimesh')
    numpy = require_module('numpy')
    relative, root, rename = LIMBS['solo12_leg']
    robot = Robot.from_urdf(example_robot(relative))
    before = {link.name: link for link in robot.subtree(root)}
    mirror_subtree(robot, root, 'xz', None, rename, mesh_folder=tmp_path,
                   search_paths=(_share(),))
    checked = 0
    for name, link in before.items():
        for old, new in zip(link.visuals, robot.get_link(_renamed(name, rename)).visuals):
            source = trimesh.load(_absolute(old.geometry.filename), force='mesh')
            mirrored = trimesh.load(_absolute(new.geometry.filename), force='mesh')
            assert mirrored.volume == pytest.approx(source.volume, rel=1e-9)
            assert mirrored.is_winding_consistent and mirrored.volume > 0
            low, high = source.bounds
            assert numpy.allclose(mirrored.bounds, [[low[0], -high[1], low[2]],
                                                    [high[0], -low[1], high[2]]], atol=1e-12)
            checked += 1
    assert checked


def _arm() -> Robot:
    """Return a robot with a left arm: shoulder, elbow, a gripper with a mimic finger."""
    robot = Robot('bimanual')
    robot.add_link(Link('base_link').set_inertial(Inertial.from_box(5.0, 0.3, 0.3, 0.3)))
    for name in ('left_shoulder', 'left_upper', 'left_finger_a', 'left_finger_b'):
        link = Link(name).set_inertial(Inertial(0.5, 0.01, 0.001, 0.002, 0.02, 0.003, 0.03,
                                                origin=Origin((0.01, 0.02, 0.03),
                                                              (0.1, 0.2, 0.3))))
        link.add_visual(Visual(Box(0.05, 0.1, 0.2), origin=Origin((0.0, 0.05, 0.0),
                                                                  (0.3, 0.0, 0.2))))
        robot.add_link(link)
    robot.add_joint(Joint('left_shoulder_roll', 'revolute', 'base_link', 'left_shoulder',
                          origin=Origin((0.0, 0.2, 0.5), (0.1, 0.0, 0.3)), axis=(1, 0, 0),
                          limit=JointLimit(-0.5, 1.5)))
    robot.add_joint(Joint('left_elbow', 'revolute', 'left_shoulder', 'left_upper',
                          origin=Origin((0.0, 0.1, -0.3)), axis=(0, 1, 0),
                          limit=JointLimit(-2.0, 0.1)))
    robot.add_joint(Joint('left_finger_a_joint', 'prismatic', 'left_upper', 'left_finger_a',
                          origin=Origin((0.0, 0.0, -0.2)), axis=(0, 1, 0),
                          limit=JointLimit(0.0, 0.04)))
    robot.add_joint(Joint('left_finger_b_joint', 'revolute', 'left_upper', 'left_finger_b',
                          origin=Origin((0.0, 0.0, -0.2)), axis=(0, 0, 1),
                          limit=JointLimit(-1.0, 1.0),
                          mimic=JointMimic('left_finger_a_joint', 2.0, 0.1)))
    robot.get_link('left_upper').add_extension(Extension(
        '<gazebo reference="left_upper"><sensor name="left_imu" type="imu">'
        '<pose>0.1 0.2 0.3 0.4 0.5 0.6</pose></sensor></gazebo>'))
    robot.add_extension(Extension(
        '<transmission name="left_elbow_trans"><type>transmission_interface/Simple'
        'Transmission</type><joint name="left_elbow"><hardwareInterface>hardware_interface/'
        'EffortJointInterface</hardwareInterface></joint><actuator name="left_elbow_motor">'
        '<mechanicalReduction>1</mechanicalReduction></actuator></transmission>'))
    robot.add_extension(Extension(
        '<ros2_control name="arm" type="system"><hardware><plugin>mock_components/'
        'GenericSystem</plugin></hardware><joint name="left_elbow"><command_interface '
        'name="position"/></joint></ros2_control>'))
    robot.add_extension(Extension(
        '<gazebo><plugin name="jsp" filename="libgazebo_ros_joint_state_publisher.so">'
        '<joint_name>left_elbow</joint_name></plugin></gazebo>'))
    return robot


def test_every_reference_is_renamed_and_mimic_follows_its_mirrored_leader(
        tmp_path: Path) -> None:
    numpy = require_module('numpy')
    yourdfpy = require_module('yourdfpy')
    robot = _arm()
    rules = {rule.name: rule.sign for rule in mirror_subtree(robot, 'left_shoulder')}
    # roll about x and yaw about z turn the other way; pitch about y and a slide along y keep
    assert rules == {'right_shoulder_roll': -1, 'right_elbow': 1, 'right_finger_a_joint': -1,
                     'right_finger_b_joint': -1}
    assert robot.get_joint('right_shoulder_roll').limit.lower == -1.5
    assert robot.get_joint('right_shoulder_roll').limit.upper == 0.5
    mimic = robot.get_joint('right_finger_b_joint').mimic
    assert (mimic.joint, mimic.multiplier, mimic.offset) == ('right_finger_a_joint', 2.0, -0.1)
    text = robot.to_urdf(tmp_path / 'arm.urdf')
    for piece in ('<gazebo reference="right_upper">', '<sensor name="right_imu"',
                  '<transmission name="right_elbow_trans">', '<joint name="right_elbow">',
                  '<actuator name="right_elbow_motor">', '<joint_name>right_elbow</joint_name>',
                  '<joint_name>left_elbow</joint_name>', '0.1 -0.2 0.3 -0.4 0.5 -0.6'):
        assert piece in text, piece
    assert text.count('<ros2_control') == 1 and text.count('<joint name="right_elbow">') == 2
    assert_check_urdf_accepts(tmp_path / 'arm.urdf')
    model = yourdfpy.URDF.load(str(tmp_path / 'arm.urdf'), load_meshes=False)
    flip = _reflection(1)
    rng = random.Random(5)
    for _ in range(20):
        values = {name: rng.uniform(-0.5, 0.5) for name in
                  ('left_shoulder_roll', 'left_elbow', 'left_finger_a_joint')}
        config = dict(values)
        config.update({name.replace('left', 'right'): rules[name.replace('left', 'right')]
                       * value for name, value in values.items()})
        model.update_cfg(config)  # yourdfpy moves the mimic joints from their leaders
        for name in ('left_shoulder', 'left_upper', 'left_finger_a', 'left_finger_b'):
            mine = model.get_transform(name, 'base_link')
            twin = model.get_transform(name.replace('left', 'right'), 'base_link')
            assert numpy.abs(twin - flip @ mine @ flip).max() < 1e-9, name
    inertial = robot.get_link('right_upper').inertial
    assert (inertial.ixy, inertial.ixz, inertial.iyz) == (-0.001, 0.002, -0.003)


def test_a_copy_whose_names_are_taken_is_refused_and_nothing_changes() -> None:
    robot = _arm()
    before = robot.to_urdf()
    with pytest.raises(ModelError, match="would take names in use: link 'left_shoulder'"):
        mirror_subtree(robot, 'left_shoulder', rename={'right_': 'left_'})
    with pytest.raises(ModelError, match="plane 'ab' is not one of"):
        robot.mirror('left_shoulder', plane='ab')
    assert robot.to_urdf() == before


def test_mirror_command_prints_each_joints_rule(tmp_path: Path) -> None:
    source, target = tmp_path / 'arm.urdf', tmp_path / 'both.urdf'
    _arm().to_urdf(source)
    result = CliRunner().invoke(main, ['mirror', str(source), '--root', 'left_shoulder',
                                       '-o', str(target)])
    assert result.exit_code == 0, result.output
    assert "joint 'right_shoulder_roll' mirrors 'left_shoulder_roll': positions negated" \
        in result.output
    assert "joint 'right_elbow' mirrors 'left_elbow': positions kept" in result.output
    assert Robot.from_urdf(target).has_link('right_finger_b')
    again = CliRunner().invoke(main, ['mirror', str(target), '--root', 'left_shoulder',
                                      '-o', str(tmp_path / 'x.urdf')])
    assert again.exit_code == 2 and 'would take names in use' in again.output


@pytest.mark.parametrize('plane, frame', [('yz', None), ('xy', 'left_shoulder'),
                                          ('xz', 'left_upper')])
def test_any_plane_of_any_frame_reflects_the_limb(plane: str, frame: str | None,
                                                  tmp_path: Path) -> None:
    numpy = require_module('numpy')
    yourdfpy = require_module('yourdfpy')
    robot = _arm()
    rules = mirror_subtree(robot, 'left_upper', plane, frame, {'left_': 'other_'})
    robot.to_urdf(tmp_path / 'arm.urdf')
    model = yourdfpy.URDF.load(str(tmp_path / 'arm.urdf'), load_meshes=False)
    at = model.get_transform(frame or 'base_link', 'base_link')  # all joints at 0
    axis = {'yz': 0, 'xz': 1, 'xy': 2}[plane]
    flip = _reflection(axis)
    reflection = at @ flip @ numpy.linalg.inv(at)
    rng = random.Random(3)
    for _ in range(20):
        values = {rule.original: rng.uniform(-0.5, 0.5) for rule in rules}
        config = dict(values)
        config.update({rule.name: rule.sign * values[rule.original] for rule in rules})
        model.update_cfg(config)
        for name in ('left_upper', 'left_finger_a', 'left_finger_b'):
            mine = model.get_transform(name, 'base_link')
            twin = model.get_transform(name.replace('left_', 'other_'), 'base_link')
            assert numpy.abs(twin - reflection @ mine @ flip).max() < 1e-9, name


def test_meshes_are_written_beside_the_originals_and_never_over_a_users_file(
        tmp_path: Path) -> None:
    trimesh = require_module('trimesh')
    numpy = require_module('numpy')
    from urdfgenpy_ros import Mesh
    (tmp_path / 'meshes').mkdir()
    part = trimesh.creation.box((0.1, 0.2, 0.3))
    part.apply_translation((0.01, 0.05, -0.1))  # off-centre, so the mirror image differs
    part.export(tmp_path / 'meshes' / 'left_part.stl')
    robot = _arm()
    robot.get_link('left_upper').add_visual(Visual(Mesh('meshes/left_part.stl')))
    source = tmp_path / 'arm.urdf'
    robot.to_urdf(source)
    for attempt in range(2):  # again: the same mirror image is there already, and is kept
        robot = Robot.from_urdf(source)
        robot.mirror('left_shoulder')
        assert robot.get_link('right_upper').visuals[-1].geometry.filename == \
            'meshes/left_part_mirror_xz.stl'
    robot.to_urdf(tmp_path / 'both.urdf')
    yourdfpy = require_module('yourdfpy')
    loaded = yourdfpy.URDF.load(str(tmp_path / 'both.urdf'), load_meshes=True)
    mirrored = trimesh.load(tmp_path / 'meshes' / 'left_part_mirror_xz.stl')
    original = trimesh.load(tmp_path / 'meshes' / 'left_part.stl')  # STL holds float32
    assert mirrored.volume == pytest.approx(original.volume, rel=1e-9)
    assert numpy.array_equal(mirrored.bounds[:, 1], -original.bounds[::-1, 1])
    assert 'right_upper' in loaded.link_map
    (tmp_path / 'meshes' / 'left_part_mirror_xz.stl').write_bytes(b'solid mine\nendsolid\n')
    with pytest.raises(ModelError, match='left_part_mirror_xz.stl exists and is not the mirror'):
        Robot.from_urdf(source).mirror('left_shoulder')
    assert (tmp_path / 'meshes' / 'left_part_mirror_xz.stl').read_bytes() == \
        b'solid mine\nendsolid\n'
