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
A mirrored limb's names: one to one, every occurrence of the limb's token, shapes too.

Judged by what check_urdf, yourdfpy and pinocchio read from the written file: as many
links and joints as the source and its copy hold, the names the robot's own other limb
has, and every copy link placed as the reflection of the link it copies.
"""

from __future__ import annotations

from pathlib import Path
import random

from click.testing import CliRunner
from helpers import assert_check_urdf_accepts, require_module
import pytest
from test_reshape_dh import example_robot

from urdfgenpy_ros import (
    Box, Collision, Extension, Joint, JointLimit, Link, ModelError, Origin, Robot,
    UrdfgenpyError, Visual)
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.reshape.mirror import mirror_subtree

# OpenArm v10's names: a hand with a left and a right finger, on the left arm
_ARM = ('link0', 'link1', 'hand', 'left_finger', 'right_finger')
_PARENT = {'link0': None, 'link1': 'link0', 'hand': 'link1', 'left_finger': 'hand',
           'right_finger': 'hand'}


def _openarm() -> Robot:
    robot = Robot('openarm').add_link(Link('body'))
    for number, part in enumerate(_ARM):
        name = f'openarm_left_{part}'
        link = Link(name).add_visual(Visual(Box(0.05, 0.04, 0.03), name=f'{name}_visual',
                                            origin=Origin((0.01, 0.02, 0.0), (0.1, 0.2, 0.3))))
        robot.add_link(link.add_collision(Collision(Box(0.05, 0.04, 0.03),
                                                    name=f'{name}_collision')))
        parent = _PARENT[part]
        kind = 'fixed' if parent is None else 'prismatic' if 'finger' in part else 'revolute'
        side = -1.0 if part == 'right_finger' else 1.0
        robot.add_joint(Joint(
            f'openarm_left_{part}_joint', kind,
            'body' if parent is None else f'openarm_left_{parent}', name,
            origin=Origin((0.1, 0.2 * side + 0.03 * number, 0.05), (0.3, 0.1 * number, 0.2)),
            axis=None if kind == 'fixed' else (0.0, side, 0.0) if kind == 'prismatic'
            else (0.6, 0.0, 0.8),
            limit=None if kind == 'fixed' else JointLimit(0.0, 0.04, effort=5.0, velocity=1.0)))
    return robot


def _reflects(urdf: Path, pairs: dict[str, str], signs: dict[str, tuple[str, int]]) -> None:
    """Assert with pinocchio that each link ``pairs[name]`` is ``name``'s mirror image (xz)."""
    numpy = require_module('numpy')
    pin = require_module('pinocchio')
    model = pin.buildModelFromUrdf(str(urdf))
    data = model.createData()
    q = pin.neutral(model)
    rng = random.Random(7)
    for name, (twin, sign) in signs.items():
        value = rng.uniform(0.0, 0.04)
        q[model.joints[model.getJointId(name)].idx_q] = value
        q[model.joints[model.getJointId(twin)].idx_q] = sign * value
    pin.framesForwardKinematics(model, data, q)
    flip = numpy.diag([1.0, -1.0, 1.0, 1.0])
    for name, twin in pairs.items():
        mine = data.oMf[model.getFrameId(name, pin.FrameType.BODY)].homogeneous
        copy = data.oMf[model.getFrameId(twin, pin.FrameType.BODY)].homogeneous
        assert numpy.abs(copy - flip @ mine @ flip).max() < 1e-9, (name, twin)


def test_openarms_two_fingers_stay_two_links_named_as_its_right_arm(tmp_path: Path) -> None:
    yourdfpy = require_module('yourdfpy')
    robot = _openarm()
    rules = {rule.original: (rule.name, rule.sign)
             for rule in mirror_subtree(robot, 'openarm_left_link0')}  # left_: right_
    path = tmp_path / 'bimanual.urdf'
    robot.to_urdf(path)
    assert_check_urdf_accepts(path)
    read = yourdfpy.URDF.load(str(path), load_meshes=False, build_scene_graph=False)
    assert len(read.robot.links) == 1 + 2 * len(_ARM)  # 27 for 28 before
    assert len(read.robot.joints) == 2 * len(_ARM)
    right = {f'openarm_right_{part}' for part in _ARM}
    assert right <= {link.name for link in read.robot.links}  # right_finger, left_finger
    shapes = {shape.name for link in read.robot.links if link.name in right
              for shape in (*link.visuals, *link.collisions)}
    assert shapes == {f'{name}_{kind}' for name in right for kind in ('visual', 'collision')}
    _reflects(path, {f'openarm_left_{part}': f'openarm_right_{part}' for part in _ARM},
              rules)


def test_every_occurrence_of_anymals_leg_token_is_renamed(tmp_path: Path) -> None:
    yourdfpy = require_module('yourdfpy')
    source = example_robot('anymal_c_simple_description/urdf/anymal.urdf')
    read = yourdfpy.URDF.load(str(source), load_meshes=False, build_scene_graph=False)
    right = {name for name in [*read.link_map, *read.joint_map] if 'RF_' in name}
    robot = Robot.from_urdf(source)
    robot.mirror('LF_HAA', rename={'LF_': 'XF_'}, mesh_folder=tmp_path / 'meshes',
                 search_paths=[example_robot('.').parent.parent])
    assert 'RF_HIP_RF_hip_fixed' in right  # the leg's token twice in one name
    path = tmp_path / 'anymal.urdf'
    robot.to_urdf(path)
    mirrored = yourdfpy.URDF.load(str(path), load_meshes=False, build_scene_graph=False)
    copy = {name for name in [*mirrored.link_map, *mirrored.joint_map]
            if 'XF_' in name}
    assert copy == {name.replace('RF_', 'XF_') for name in right}
    assert len(mirrored.robot.links) == len(read.robot.links) + len(
        [name for name in right if name in read.link_map])
    links = {name for name in read.link_map if 'LF_' in name}
    _reflects(path, {name: name.replace('LF_', 'XF_') for name in links}, {})


def test_names_the_renaming_would_merge_are_refused_naming_both(tmp_path: Path) -> None:
    robot = _openarm()
    before = robot.to_urdf()
    with pytest.raises(ModelError, match="links 'openarm_left_left_finger' and "
                       "'openarm_left_right_finger' would both be named 'openarm_x_finger'"):
        robot.mirror('openarm_left_link0', rename={'openarm_left_left_': 'openarm_x_',
                                                   'openarm_left_right_': 'openarm_x_'})
    assert robot.to_urdf() == before
    source = tmp_path / 'arm.urdf'
    source.write_text(before)
    result = CliRunner().invoke(main, ['mirror', str(source), '--root', 'openarm_left_link0',
                                       '--rename', 'openarm_left_left_:openarm_x_',
                                       '--rename', 'openarm_left_right_:openarm_x_',
                                       '-o', str(tmp_path / 'out.urdf')])
    assert result.exit_code == 2, result.output
    assert result.output.strip().splitlines()[-1] == (
        "urdfgenpy: mirror: links 'openarm_left_left_finger' and 'openarm_left_right_finger'"
        " would both be named 'openarm_x_finger' in the copy (pass --rename OLD:NEW that "
        'tells them apart)')
    assert not (tmp_path / 'out.urdf').exists()


def test_an_empty_key_is_a_prefix_of_names_only(tmp_path: Path) -> None:
    yourdfpy = require_module('yourdfpy')
    robot = _openarm()
    robot.get_link('openarm_left_hand').add_extension(Extension.gazebo('<mu1>0.8</mu1>'))
    robot.mirror('openarm_left_link0', rename={'': 'm_'})
    robot.to_urdf(tmp_path / 'arm.urdf')
    read = yourdfpy.URDF.load(str(tmp_path / 'arm.urdf'), load_meshes=False,
                              build_scene_graph=False)
    assert {f'm_openarm_left_{part}' for part in _ARM} <= set(read.link_map)
    assert len(read.robot.links) == 1 + 2 * len(_ARM)
    text = (tmp_path / 'arm.urdf').read_text()
    assert '<gazebo reference="m_openarm_left_hand">' in text
    assert text.count('<mu1>0.8</mu1>') == 2


def test_the_command_takes_a_prefix_for_a_limb_without_a_side(tmp_path: Path) -> None:
    yourdfpy = require_module('yourdfpy')
    source, target = tmp_path / 'arm.urdf', tmp_path / 'two.urdf'
    _openarm().to_urdf(source)
    result = CliRunner().invoke(main, ['mirror', str(source), '--root', 'openarm_left_link0',
                                       '--rename', ':m_', '-o', str(target)])
    assert result.exit_code == 0, result.output
    read = yourdfpy.URDF.load(str(target), load_meshes=False, build_scene_graph=False)
    assert {f'm_openarm_left_{part}' for part in _ARM} <= set(read.link_map)
    refused = CliRunner().invoke(main, ['mirror', str(source), '--root', 'openarm_left_link0',
                                        '--rename', ':', '-o', str(target), '-f'])
    assert refused.exit_code == 2 and "':' is not OLD:NEW" in refused.output


@pytest.mark.parametrize('relative, left, right, rename', [
    ('romeo_description/urdf/romeo.urdf', 'LHipYawLink', 'RHipYawLink', {'L': 'R', 'l_': 'r_'}),
    ('anymal_c_simple_description/urdf/anymal.urdf', 'LF_HAA', 'RF_HAA', {'L': 'R'}),
    ('simple_humanoid_description/urdf/simple_humanoid.urdf', 'LARM_LINK1', 'RARM_LINK1',
     {'L': 'R', 'l_': 'r_'}),
    pytest.param('baxter_description/urdf/baxter.urdf', 'left_arm_mount', 'right_arm_mount',
                 {'left_': 'right_', 'l_': 'r_'}, marks=pytest.mark.slow)])  # its DAE meshes
def test_a_mirrored_limb_takes_the_names_of_the_robots_other_limb(
        relative: str, left: str, right: str, rename: dict[str, str], tmp_path: Path) -> None:
    yourdfpy = require_module('yourdfpy')
    source = example_robot(relative)
    robot = Robot.from_urdf(source)
    for link in reversed(robot.subtree(right)):
        robot.remove_link(link.name)
    robot.mirror(left, rename=rename, mesh_folder=tmp_path / 'meshes',
                 search_paths=[example_robot('.').parent.parent])
    robot.to_urdf(tmp_path / 'mirrored.urdf')
    theirs = yourdfpy.URDF.load(str(source), load_meshes=False, build_scene_graph=False)
    mine = yourdfpy.URDF.load(str(tmp_path / 'mirrored.urdf'), load_meshes=False,
                              build_scene_graph=False)
    # Romeo's LFsrFL_frame is RFsrFL_frame; ANYmal's LF_HIP_LF_hip_fixed RF_HIP_RF_hip_fixed
    assert set(mine.link_map) == set(theirs.link_map)
    assert set(mine.joint_map) == set(theirs.joint_map)


SIDES = (('left_', 'right_'), ('l_', 'r_'), ('L', 'R'), ('LF_', 'RF_'), ('LH_', 'RH_'),
         ('FL_', 'FR_'), ('HL_', 'HR_'), ('Left', 'Right'), ('left', 'right'))


def _left_limbs(robot: Robot):
    """Yield each limb whose first link is named by a left side and has a right twin."""
    names = {link.name for link in robot.links}
    for old, new in SIDES:
        for link in robot.links:
            twin = new + link.name[len(old):]
            parent = robot.parent_joint(link.name)
            if link.name.startswith(old) and twin in names and parent is not None \
                    and not parent.parent.startswith(old) \
                    and link.name not in {item.name for item in robot.subtree(twin)}:
                yield link.name, twin, {old: new}


@pytest.mark.slow  # every robot of example-robot-data, their meshes mirrored
def test_a_left_limb_takes_its_right_twins_names_or_is_refused(tmp_path: Path) -> None:
    """The robots' own right limbs are the oracle: exactly their names, or one line."""
    yourdfpy = require_module('yourdfpy')
    share = example_robot('.').parent.parent
    checked = 0
    for source in sorted(example_robot('.').glob('*/urdf/*.urdf')):
        try:
            original = Robot.from_urdf(source)
        except UrdfgenpyError:  # a file urdfdom refuses too (ur3.urdf: no robot name)
            continue
        theirs = yourdfpy.URDF.load(str(source), load_meshes=False, build_scene_graph=False)
        for left, right, rename in list(_left_limbs(original)):
            robot = Robot.from_urdf(source)
            for link in reversed(robot.subtree(right)):
                robot.remove_link(link.name)
            try:
                robot.mirror(left, rename=rename, mesh_folder=tmp_path / str(checked),
                             search_paths=[share])
            except ModelError as error:
                assert '\n' not in str(error)
                continue
            robot.to_urdf(tmp_path / 'mirrored.urdf')
            mine = yourdfpy.URDF.load(str(tmp_path / 'mirrored.urdf'), load_meshes=False,
                                      build_scene_graph=False)
            assert (set(mine.link_map), set(mine.joint_map)) == (
                set(theirs.link_map), set(theirs.joint_map)), (source.name, left, rename)
            checked += 1
    assert checked >= 50
