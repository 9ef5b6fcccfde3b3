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
The SRDF on robots shaped as vendors make them, in small files written here.

A Robotiq-like gripper closing at its upper limit (pinocchio's kinematics judge which
state has the finger tips farther apart), a root link called ``world`` (UR, Robotiq, Z1),
a UR-like wrist whose tool frame is two fixed joints down beside an ``ft_frame``; the names
are judged against the URDF read with lxml.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import corpus_file, require_module
from lxml import etree
import numpy
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main


def _link(name: str, box: bool = True) -> str:
    geometry = ('<collision><origin xyz="0 0 0.02"/><geometry><box size="0.02 0.02 0.04"/>'
                '</geometry></collision>') if box else ''
    return f'<link name="{name}">{geometry}</link>'


def _joint(name: str, kind: str, parent: str, child: str, xyz: str = '0 0 0.1',
           axis: str = '0 0 1', limit: str = '-2 2', extra: str = '') -> str:
    low, high = limit.split()
    limits = (f'<limit lower="{low}" upper="{high}" effort="1" velocity="1"/>'
              if kind != 'fixed' else '')
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/>'
            f'<child link="{child}"/><origin xyz="{xyz}"/><axis xyz="{axis}"/>'
            f'{limits}{extra}</joint>')


def _arm(root: str = 'base_link') -> list[str]:
    parts = [_link(root, box=root != 'world'), _link('shoulder'), _link('wrist')]
    if root == 'world':
        parts[0] += _link('base_link') + _joint('world_joint', 'fixed', 'world', 'base_link',
                                                xyz='0 0 0')
        root = 'base_link'
    parts += [_joint('j1', 'revolute', root, 'shoulder'),
              _joint('j2', 'revolute', 'shoulder', 'wrist', axis='0 1 0')]
    return parts


def _gripper() -> list[str]:
    """Two fingers on knuckles that close as the leader goes from 0 to 0.8 (Robotiq)."""
    return [_link('gripper_base'), _link('left_knuckle', False),
            _link('right_knuckle', False), _link('left_tip', False),
            _link('right_tip', False),
            _joint('gripper_mount', 'fixed', 'wrist', 'gripper_base'),
            _joint('left_knuckle_joint', 'revolute', 'gripper_base', 'left_knuckle',
                   xyz='0.03 0 0.05', axis='0 -1 0', limit='0 0.8'),
            _joint('right_knuckle_joint', 'revolute', 'gripper_base', 'right_knuckle',
                   xyz='-0.03 0 0.05', axis='0 1 0', limit='0 0.8',
                   extra='<mimic joint="left_knuckle_joint"/>'),
            _joint('left_tip_joint', 'fixed', 'left_knuckle', 'left_tip', xyz='0 0 0.05'),
            _joint('right_tip_joint', 'fixed', 'right_knuckle', 'right_tip',
                   xyz='0 0 0.05')]


def _write(tmp_path: Path, parts: list[str], name: str = 'robot.urdf') -> Path:
    path = tmp_path / name
    path.write_text(f'<robot name="vendor">{"".join(parts)}</robot>')
    return path


def _srdf(urdf: Path, *options: str) -> tuple[etree._Element, str]:
    require_module('coal')
    output = urdf.with_suffix('.srdf')
    result = CliRunner().invoke(main, ['srdf', str(urdf), '-o', str(output), '--force',
                                       '--samples', '50', *options])
    assert result.exit_code == 0, result.output
    return etree.parse(str(output)).getroot(), result.stdout


def test_open_is_where_pinocchio_puts_the_finger_tips_farther_apart(tmp_path: Path) -> None:
    pinocchio = require_module('pinocchio')
    urdf = _write(tmp_path, _arm() + _gripper())
    srdf, _ = _srdf(urdf)
    model = pinocchio.buildModelFromUrdf(str(urdf))
    data = model.createData()
    gaps = {}
    for state in srdf.iterfind("group_state[@group='gripper']"):
        value = float(state.find("joint[@name='left_knuckle_joint']").get('value'))
        q = pinocchio.neutral(model)
        for joint in ('left_knuckle_joint', 'right_knuckle_joint'):  # the mimic by hand
            q[model.joints[model.getJointId(joint)].idx_q] = value
        pinocchio.framesForwardKinematics(model, data, q)
        tips = [data.oMf[model.getFrameId(tip)].translation for tip in ('left_tip', 'right_tip')]
        gaps[state.get('name')] = float(numpy.linalg.norm(tips[0] - tips[1]))
    assert set(gaps) == {'open', 'close'}
    assert gaps['open'] > gaps['close'] + 0.01, gaps  # 0.06 m at 0, 0.012 m at 0.8


@pytest.mark.parametrize('fingers', ['left_knuckle', 'left_knuckle right_knuckle'])
def test_undecided_keeps_the_upper_limit_and_says_so(fingers: str) -> None:
    """One finger tip, or tips at the knuckles' pivots (as far apart at both limits)."""
    parts = [part for part in _arm() + _gripper() if '_tip' not in part]
    robot = Robot.from_urdf_string(f'<robot name="one">{"".join(parts)}</robot>')
    from urdfgenpy_ros.moveit.gripper_states import opens_at_upper
    upper, note = opens_at_upper(robot, 'gripper', ('gripper_base', *fingers.split()),
                                 {'left_knuckle_joint': (0.0, 0.8)})
    assert upper and note is not None and 'upper limits' in note, note


def test_a_root_called_world_is_the_world_frame(tmp_path: Path) -> None:
    urdf = _write(tmp_path, _arm('world') + _gripper())
    srdf, output = _srdf(urdf)
    held = {joint.find('child').get('link') for joint in etree.parse(str(urdf)).getroot()
            .iter('joint') if joint.find('parent').get('link') == 'world'}
    assert srdf.find('virtual_joint') is None
    assert [chain.get('base_link') for chain in srdf.iter('chain')] == sorted(held)
    named = [value for element in srdf.iter('group', 'end_effector', 'chain', 'link')
             for key, value in element.attrib.items() if key != 'name' or element.tag == 'link']
    assert named and 'world' not in named
    assert "no virtual joint: the root link 'world' is the world frame" in output


def _ur_wrist() -> list[str]:
    return [_link('ft_frame', False), _link('flange', False), _link('tool0', False),
            _joint('wrist-ft_frame', 'fixed', 'wrist', 'ft_frame'),
            _joint('wrist-flange', 'fixed', 'wrist', 'flange'),
            _joint('flange-tool0', 'fixed', 'flange', 'tool0', xyz='0 0 0')]


def test_the_chain_ends_at_the_tool_frame(tmp_path: Path) -> None:
    urdf = _write(tmp_path, _arm('world') + _ur_wrist())
    srdf, _ = _srdf(urdf)
    parent = {joint.find('child').get('link'): joint.find('parent').get('link')
              for joint in etree.parse(str(urdf)).getroot().iter('joint')}
    leaves = set(parent) - set(parent.values())
    (chain,) = srdf.iter('chain')
    assert chain.get('tip_link') in leaves and chain.get('tip_link') == 'tool0'
    assert parent[parent[chain.get('tip_link')]] == 'wrist'  # flange, then the wrist


def test_a_group_option_replaces_the_group_over_the_same_joints(tmp_path: Path) -> None:
    urdf = _write(tmp_path, _arm('world') + _ur_wrist())
    srdf, _ = _srdf(urdf, '--group', 'manipulator=base_link:flange')
    assert [group.get('name') for group in srdf.iter('group')] == ['manipulator']
    assert [(s.get('name'), s.get('group')) for s in srdf.iter('group_state')] == [
        ('home', 'manipulator')]


@pytest.mark.parametrize('tip', ['wrist', 'tool0'])
def test_override_without_coal_is_found_in_python(tip: str) -> None:
    from urdfgenpy_ros.moveit.groups import find_groups
    robot = Robot.from_urdf_string(
        f'<robot name="ur">{"".join(_arm("world") + _ur_wrist())}</robot>')
    groups, _ = find_groups(robot, {'manipulator': ('base_link', tip)})
    assert [(group.name, group.tip) for group in groups] == [('manipulator', tip)]


def test_update_without_output_updates_the_file_in_place(tmp_path: Path) -> None:
    urdf = _write(tmp_path, _arm() + _gripper())
    _srdf(urdf)
    path = urdf.with_suffix('.srdf')
    text = path.read_text().replace('<group ', '<!-- mine -->\n    <group ', 1)
    path.write_text(text.replace('reason="Never"', 'reason="User"', 1))
    result = CliRunner().invoke(main, ['srdf', str(urdf), '--update', str(path),
                                       '--samples', '50'])
    assert result.exit_code == 0, result.output
    assert '<!-- mine -->' in path.read_text() and 'reason="User"' in path.read_text()
    etree.parse(str(path))  # whole, well-formed
    assert sorted(item.name for item in tmp_path.iterdir()) == ['robot.srdf', 'robot.urdf']
    result = CliRunner().invoke(main, ['srdf', str(urdf)])
    assert result.exit_code == 2 and "Missing option '--output'" in result.output


SRDF = """<?xml version="1.0"?>
<robot name="vendor">
  <group name="arm"><chain base_link="base_link" tip_link="wrist_old"/></group>
  <!-- <group_state name="home" group="arm"> in a comment is no element -->
  <group_state name="home" group="arm">
      <joint name="j1" value="0"/>   <joint name="j9" value="0"/>
  </group_state>
        <disable_collisions link1="base_link" link2="gone" reason="Never"/>
  <disable_collisions
      link1="shoulder" link2="old_wrist" reason="Adjacent"/>
</robot>
"""


def test_srdf_findings_are_at_the_start_tags_column(tmp_path: Path) -> None:
    from urdfgenpy_ros.moveit.srdf_check import check_srdf
    urdf = _write(tmp_path, _arm())
    path = tmp_path / 'robot.srdf'
    path.write_text(SRDF)
    found = check_srdf(Robot.from_urdf(urdf), path, samples=0)
    lines = SRDF.splitlines()
    stale = {'wrist_old': 'chain', 'j9': 'joint', 'gone': 'disable_collisions',
             'old_wrist': 'disable_collisions'}
    assert sorted(f.message.split("'")[1] for f in found) == sorted(stale)
    for finding in found:
        where, name = finding.location, finding.message.split("'")[1]
        text = lines[where.line - 1]
        assert text[where.column - 1:].startswith(f'<{stale[name]}'), (finding, text)
        starts = [index for index in range(where.line) if f'<{stale[name]}' in lines[index]]
        assert where.line == starts[-1] + 1  # the start tag's line, also when it wraps
    assert {f.location.column for f in found} == {3, 9, 21, 38}


def test_a_urdf_given_as_srdf_is_one_line(tmp_path: Path) -> None:
    urdf = _write(tmp_path, _arm())
    xacro = tmp_path / 'robot.urdf.xacro'
    xacro.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                     '<xacro:include filename="arm.xacro"/></robot>')
    for wrong in (urdf, xacro):
        result = CliRunner().invoke(main, ['check', str(urdf), '--srdf', str(wrong)])
        assert result.exit_code == 2
        assert result.output.strip().splitlines() == [
            f'urdfgenpy: {wrong} is not an SRDF but a URDF or Xacro robot (it has <link>, '
            '<joint> or xacro elements): give --srdf the SRDF file (e.g. '
            'config/ROBOT.srdf), or make one: urdfgenpy srdf ROBOT -o robot.srdf']


def test_robotiq_2f85_on_kinova_gen3_opens_at_zero() -> None:
    """Kinova's Gen3 with the Robotiq 2F-85 (corpus): pinocchio measures the tips' gap."""
    pinocchio = require_module('pinocchio')
    path = corpus_file('kortex/kortex_description/robots/gen3_2f85.urdf')
    from urdfgenpy_ros.moveit.groups import find_groups
    from urdfgenpy_ros.moveit.srdf import group_states
    robot = Robot.from_urdf(path)
    groups, _ = find_groups(robot)
    states = {state.name: dict(state.values) for state in group_states(robot, groups, {})
              if state.group == 'gripper'}
    mimic = {joint.get('name'): (joint.find('mimic').get('joint'),
                                 float(joint.find('mimic').get('multiplier', '1')),
                                 float(joint.find('mimic').get('offset', '0')))
             for joint in etree.parse(str(path)).getroot().iter('joint')
             if joint.find('mimic') is not None}
    model = pinocchio.buildModelFromUrdf(str(path))
    data = model.createData()
    gaps = {}
    for name, values in states.items():
        q = pinocchio.neutral(model)
        for index in range(1, model.njoints):
            joint = model.names[index]
            leader, multiplier, offset = mimic.get(joint, (joint, 1.0, 0.0))
            if leader in values:  # continuous joints are (cos, sin) in pinocchio
                angle = values[leader] * multiplier + offset
                slot, size = model.joints[index].idx_q, model.joints[index].nq
                q[slot:slot + size] = [numpy.cos(angle), numpy.sin(angle)] if size == 2 \
                    else [angle]
        pinocchio.framesForwardKinematics(model, data, q)
        tips = [data.oMf[model.getFrameId(f'gen3_robotiq_85_{side}_finger_tip_link')]
                .translation for side in ('left', 'right')]
        gaps[name] = float(numpy.linalg.norm(tips[0] - tips[1]))
    assert set(gaps) == {'open', 'close'} and gaps['open'] > gaps['close'] + 0.03, gaps
    assert states['open'] == {'gen3_robotiq_85_left_knuckle_joint': 0.0}


def test_panda_still_opens_at_its_upper_limit() -> None:
    """Panda's prismatic fingers open at 0.04 (upper): pinocchio measures the fingers."""
    pinocchio = require_module('pinocchio')
    from test_moveit_srdf import _urdf
    from urdfgenpy_ros.moveit.groups import find_groups
    from urdfgenpy_ros.moveit.srdf import group_states
    robot = Robot.from_urdf(_urdf('panda'))
    notes: list[str] = []
    states = {state.name: dict(state.values)['panda_finger_joint1'] for state in
              group_states(robot, find_groups(robot)[0], {}, notes) if state.group == 'gripper'}
    model = pinocchio.buildModelFromUrdf(str(_urdf('panda')))
    data = model.createData()
    gaps = {}
    for name, value in states.items():
        q = pinocchio.neutral(model)
        for joint in ('panda_finger_joint1', 'panda_finger_joint2'):
            q[model.joints[model.getJointId(joint)].idx_q] = value
        pinocchio.framesForwardKinematics(model, data, q)
        fingers = [data.oMf[model.getFrameId(f'panda_{side}finger')].translation
                   for side in ('left', 'right')]
        gaps[name] = float(numpy.linalg.norm(fingers[0] - fingers[1]))
    assert gaps['open'] > gaps['close'] + 0.05 and not notes, (gaps, notes)
