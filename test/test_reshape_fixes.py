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
Reshaping details a new user met: judged by libsdformat, PR2's own right arm, pinocchio.

Merged collisions keep the names Gazebo's lumping gives them; a mirror renames by prefix
as PR2's own arms are named (its old-style transmissions and camera topics too); tables
that CSV cannot hold are refused by the library; the convert options go together.
"""

from __future__ import annotations

from pathlib import Path
import random
import subprocess
import warnings

from click.testing import CliRunner
from helpers import assert_check_urdf_accepts, build_sdf_checker, require_module
import pytest
from test_reshape_dh import example_robot

from urdfgenpy_ros import ModelError, Origin, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.dh import DHTable

INERTIA = '<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" ' \
    'iyz="0"/></inertial>'
LEG = f"""<robot name="leg"><link name="base">{INERTIA}</link>
<link name="calf">{INERTIA}<collision><geometry><box size="1 1 1"/></geometry></collision>
<collision name="shin"><geometry><box size="1 2 1"/></geometry></collision>
<visual><geometry><box size="1 1 1"/></geometry></visual></link>
<link name="foot">{INERTIA}<collision><geometry><sphere radius="1"/></geometry></collision>
<collision><geometry><sphere radius="2"/></geometry></collision>
<collision name="sole"><geometry><sphere radius="3"/></geometry></collision>
<visual><geometry><sphere radius="1"/></geometry></visual></link>
<link name="toe"><collision><geometry><sphere radius="4"/></geometry></collision></link>
<joint name="knee" type="revolute"><parent link="base"/><child link="calf"/><axis xyz="1 0 0"/>
<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
<joint name="ankle" type="fixed"><parent link="calf"/><child link="foot"/>
<origin xyz="0 0 -0.3"/></joint>
<joint name="toe_joint" type="fixed"><parent link="foot"/><child link="toe"/>
<origin xyz="0.1 0 0"/></joint></robot>"""


def _gazebo_shapes(binary: Path, path: Path) -> dict[str, str]:
    """Return libsdformat's collisions and visuals of a URDF: name -> its geometry."""
    etree = require_module('lxml.etree')
    result = subprocess.run([str(binary), '--sdf', str(path)], capture_output=True, text=True,
                            timeout=60)
    assert result.returncode == 0, result.stderr
    text = result.stdout[result.stdout.index('<sdf'):]
    root = etree.fromstring(text[:text.index('</sdf>') + 6])
    return {node.get('name'): etree.tostring(node.find('geometry')).decode()
            for node in root.iter('collision', 'visual')}


@pytest.mark.engine
def test_merged_collisions_keep_the_names_gazebos_lumping_gives_them(tmp_path: Path) -> None:
    binary = build_sdf_checker(tmp_path)
    source = tmp_path / 'leg.urdf'
    source.write_text(LEG)
    theirs = _gazebo_shapes(binary, source)
    assert 'calf_fixed_joint_lump__foot_collision_2' in theirs  # as a contact sensor names it
    for drop_frames in (False, True):
        merged = tmp_path / f'merged_{drop_frames}.urdf'
        Robot.from_urdf(source).merge_fixed(drop_frames=drop_frames).to_urdf(merged)
        assert_check_urdf_accepts(merged)
        assert _gazebo_shapes(binary, merged) == theirs  # each name on the same geometry


def test_keep_takes_one_name_and_convert_takes_keep(tmp_path: Path) -> None:
    source = tmp_path / 'leg.urdf'
    source.write_text(LEG)
    robot = Robot.from_urdf(source)
    kept = robot.merge_fixed(keep='toe')  # one name, not the letters t, o, e
    assert kept.get_link('toe').collisions and not kept.get_link('foot').collisions
    target = tmp_path / 'out.urdf'
    result = CliRunner().invoke(main, ['convert', str(source), str(target), '--merge-fixed',
                                       '--keep', 'toe', '--keep', 'foot'])
    assert result.exit_code == 0, result.output
    out = Robot.from_urdf(target)
    assert len(out.get_link('foot').collisions) == 3 and out.get_link('toe').collisions
    for option in (['--drop-frames'], ['--keep', 'toe']):
        refused = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'x.urdf'),
                                            *option])
        assert refused.exit_code == 2
        assert f'{option[0]} applies with --merge-fixed only' in refused.output
        assert not (tmp_path / 'x.urdf').exists()


def test_mirroring_pr2s_left_arm_names_it_as_pr2s_right_arm(tmp_path: Path) -> None:
    share = example_robot('.').parent.parent
    pr2 = example_robot('pr2_description/urdf/pr2.urdf')
    robot = Robot.from_urdf(pr2)
    right = {link.name for link in robot.subtree('r_shoulder_pan_link')}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        robot.mirror('l_shoulder_pan_link', rename={'l_': 'mr_'},
                     mesh_folder=tmp_path / 'meshes', search_paths=[share])
    mirrored = {link.name for link in robot.subtree('mr_shoulder_pan_link')}
    assert mirrored == {'mr_' + name[2:] for name in right}  # r_gripper_l_finger_link ...
    text = robot.to_urdf()
    # PR2's old-style transmissions, as its right arm has them
    assert '<flexJoint mechanicalReduction="-1.0" name="mr_wrist_flex_joint"/>' in text
    assert '<passive_joint name="mr_gripper_l_finger_tip_joint"/>' in text
    original = pr2.read_text()
    assert '<imageTopicName>r_forearm_cam/image_raw</imageTopicName>' in original
    assert '<imageTopicName>mr_forearm_cam/image_raw</imageTopicName>' in text
    assert '<sensor:camera name="mr_forearm_cam_sensor">' in text
    assert not [w for w in caught if 'transmission' in str(w.message)]
    (tmp_path / 'pr2.urdf').write_text(text.replace('package://', f'{share}/'))
    assert_check_urdf_accepts(tmp_path / 'pr2.urdf')
    assert '"-0"' not in text  # a negated limit of 0 is written 0


def test_a_table_csv_cannot_hold_is_refused_by_the_library(tmp_path: Path) -> None:
    robot = Robot.from_urdf(example_robot('panda_description/urdf/panda.urdf'))
    table = DHTable.from_robot(robot, 'panda_link0', 'panda_hand')
    table.tool = Origin((0.0, 0.0, 0.1034))  # the TCP, as a user sets it
    with pytest.raises(ModelError, match='a base or tool transform, which CSV cannot hold'):
        table.save(tmp_path / 'panda.csv')
    assert not (tmp_path / 'panda.csv').exists()
    table.save(tmp_path / 'panda.yaml')  # YAML holds them
    assert DHTable.from_file(tmp_path / 'panda.yaml').tool.xyz == (0.0, 0.0, 0.1034)


def test_a_tip_on_a_moving_joint_is_told_of_the_modified_convention() -> None:
    numpy = require_module('numpy')
    pin = require_module('pinocchio')
    from test_dh import ARMS as PUBLISHED
    robot = PUBLISHED['ur5'].to_robot('ur5')
    standard = DHTable.from_robot(robot, 'base_link', 'link_6')
    standard.rows[-1].alpha += 1e-3  # lies after joint 6: it cannot move link_6
    with pytest.raises(ModelError, match='or use the modified convention'):
        robot.apply_dh(standard, 'base_link', 'link_6')
    modified = DHTable.from_robot(robot, 'base_link', 'link_6', 'modified')
    modified.rows[-1].alpha += 1e-3  # lies before joint 6: its origin takes it
    robot.apply_dh(modified, 'base_link', 'link_6')
    model = pin.buildModelFromXML(robot.to_urdf())
    data = model.createData()
    q = numpy.array([random.Random(3).uniform(-1, 1) for _ in range(model.nq)])
    pin.framesForwardKinematics(model, data, q)
    got = data.oMf[model.getFrameId('link_6')].homogeneous
    assert numpy.abs(got - numpy.array(modified.flange(list(q)))).max() < 1e-9


def test_a_transmission_shared_with_joints_outside_the_limb_is_said_not_mirrored(
        tmp_path: Path) -> None:
    source = tmp_path / 'arm.urdf'
    source.write_text(
        '<robot name="r"><link name="base_link"/><link name="left_arm"/><link name="head"/>'
        '<joint name="left_j" type="revolute"><parent link="base_link"/><child '
        'link="left_arm"/><origin xyz="0 0.2 0"/><axis xyz="1 0 0"/><limit lower="-1" '
        'upper="0" effort="1" velocity="1"/></joint><joint name="neck" type="revolute">'
        '<parent link="base_link"/><child link="head"/><axis xyz="0 0 1"/><limit lower="-1" '
        'upper="1" effort="1" velocity="1"/></joint><transmission name="coupled">'
        '<type>transmission_interface/DifferentialTransmission</type><joint name="left_j"/>'
        '<joint name="neck"/><actuator name="m1"/><actuator name="m2"/></transmission>'
        '</robot>')
    result = CliRunner().invoke(main, ['mirror', str(source), '--root', 'left_arm', '-o',
                                       str(tmp_path / 'two.urdf')])
    assert result.exit_code == 0, result.output
    lines = [line for line in result.output.splitlines() if line.startswith('warning:')]
    assert lines == ["warning: mirror: transmission 'coupled' drives left_j of the limb and "
                     'joints outside it: not mirrored (write its mirror image by hand)']
    assert_check_urdf_accepts(tmp_path / 'two.urdf')
    assert Robot.from_urdf(tmp_path / 'two.urdf').to_urdf().count('<transmission') == 1
