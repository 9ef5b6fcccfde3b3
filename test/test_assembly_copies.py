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


"""Two copies of one arm in one model, and the macro Xacro that makes such copies."""

from __future__ import annotations

from pathlib import Path

from assembly_parts import gripper, mobile_base
from helpers import assert_check_urdf_accepts, FIXTURES, load_yourdfpy, xacro_expand
from lxml import etree
import pytest
from registry_robots import robot as registry_robot, search_paths
from test_assembly import assert_every_reference_exists, references
from test_sdf import check_sdf  # noqa: F401 - the compiled libsdformat checker

from urdfgenpy_ros import Origin, Robot
from urdfgenpy_ros.examples import pan_tilt_unit
from urdfgenpy_ros.formats import load


def _two_armed() -> Robot:
    """Return the rover with two FR3 arms, each with a gripper (camera, ros2_control)."""
    robot = mobile_base()
    for side, y in (('left_', 0.12), ('right_', -0.12)):
        arm = load(registry_robot('fr3.urdf'), {}, search_paths())
        robot.attach(arm, 'chassis', Origin((0.1, y, 0.15)), prefix=side)
        robot.attach(gripper(), f'{side}fr3_link8', Origin((0, 0, 0.107)),
                     prefix=f'{side}gripper_')
    return robot


def test_two_copies_of_an_arm_clash_nowhere_and_every_reference_exists(
        tmp_path: Path) -> None:
    robot = _two_armed()
    text = robot.to_urdf()
    path = tmp_path / 'two_arms.urdf'
    path.write_text(text)
    assert_check_urdf_accepts(path)
    assert [str(f) for f in robot.validate(search_paths=search_paths())
            if f.severity == 'error'] == []
    assert_every_reference_exists(text)  # lxml's reading
    model = load_yourdfpy(path)  # yourdfpy's reading
    joints = {joint.name for joint in model.joints}
    links = {link.name for link in model.links}
    found = references(text)
    assert {j.mimic.joint for j in model.joints if j.mimic is not None} == {
        'left_fr3_finger_joint1', 'right_fr3_finger_joint1', 'left_gripper_left_finger_joint',
        'right_gripper_left_finger_joint'}
    assert set(found['ros2_control']) <= joints and len(found['ros2_control']) == 2 * (9 + 1)
    assert set(found['reference']) <= links | joints
    assert {'left_gripper_palm', 'right_gripper_palm'} <= set(found['reference'])
    root = etree.fromstring(text.encode())
    assert sorted(node.get('name') for node in root.findall('ros2_control')) == [
        'left_gripper_gripper', 'left_name', 'right_gripper_gripper', 'right_name']


def _lumped_parent(robot: Robot, link: str) -> str:
    """Return the link SDFormat merges ``link`` into: up through fixed joints."""
    joint = robot.parent_joint(link)
    while joint is not None and joint.type.value == 'fixed':
        link = joint.parent
        joint = robot.parent_joint(link)
    return link


@pytest.mark.engine
def test_sdformat_keeps_every_sensor_on_its_link(check_sdf, tmp_path: Path) -> None:  # noqa: F811
    robot = _two_armed()
    path = tmp_path / 'two_arms.urdf'
    robot.to_urdf(path)
    code, _, _, sensors, errors = check_sdf(path)
    assert code == 0, errors
    expected = {(_lumped_parent(robot, link.name), sensor.name, sensor.kind)
                for link in robot.links for sensor in link.sensors}
    assert len(expected) == 4  # the rover's lidar and IMU, a camera on each gripper
    # fr3_link8 hangs on link7 by a fixed joint: the camera lands on each arm's own link7
    assert {('left_fr3_link7', 'left_gripper_wrist_camera', 'camera'),
            ('right_fr3_link7', 'right_gripper_wrist_camera', 'camera')} <= expected
    assert sensors == expected
    sdf = tmp_path / 'two_arms.sdf'
    robot.to_sdf(sdf)
    code, _, _, native, errors = check_sdf(sdf)
    assert code == 0, errors
    assert native == {(link.name, sensor.name, sensor.kind)
                      for link in robot.links for sensor in link.sensors}


def _number_text(value: str) -> str:
    try:
        return ' '.join(repr(float(token)) for token in value.split())
    except ValueError:
        return value


def _canonical(text: str) -> bytes:
    """Return the XML without blank text, comments, unused namespaces; numbers spelt one way."""
    parser = etree.XMLParser(remove_blank_text=True, remove_comments=True)
    root = etree.fromstring(text.encode(), parser)
    for element in root.iter():
        for key, value in element.attrib.items():
            element.set(key, _number_text(value))
    return etree.tostring(root, method='c14n', exclusive=True)  # used namespaces only


def _read(name: str):
    return lambda: load(registry_robot(name), {}, search_paths())


def _every_element() -> Robot:
    return Robot.from_urdf(FIXTURES / 'packages/fixture_description/urdf/every_element.urdf')


@pytest.mark.parametrize('make', [pan_tilt_unit, gripper, mobile_base, _every_element,
                                  _read('fr3.urdf'), _read('so101.urdf'), _read('cookie.urdf')],
                         ids=['ptu', 'gripper', 'rover', 'every_element', 'fr3', 'so101',
                              'cookie'])
def test_macro_xacro_expanded_by_xacro_equals_the_prefixed_robot(make, tmp_path: Path) -> None:
    robot = make()
    top = tmp_path / f'{robot.name}.urdf.xacro'
    macro = robot.to_xacro(top, macro=True)
    assert (tmp_path / f'{robot.name}.macro.xacro').read_text() == macro
    assert 'params="prefix parent *origin"' in macro
    for prefix in ('left_', ''):
        expanded = xacro_expand(top, {'prefix': prefix})
        expected = robot.prefixed(prefix)
        # the same model, element for element, and the same XML
        assert Robot.from_urdf_string(expanded) == Robot.from_urdf_string(expected.to_urdf())
        assert _canonical(expanded) == _canonical(expected.to_urdf())


def test_macro_called_twice_with_parents_equals_attach(tmp_path: Path) -> None:
    arm = load(registry_robot('so101.urdf'), {}, search_paths())  # transmissions
    arm.to_xacro(tmp_path / 'so101.urdf.xacro', macro=True)
    base = mobile_base()
    for prefix, y in (('left_', 0.1), ('right_', -0.1)):
        base.attach(arm, 'chassis', Origin((0.1, y, 0.15), (0, 0, 0.3)), prefix=prefix)
    user = tmp_path / 'rover_arms.urdf.xacro'
    calls = ''.join(f'<xacro:so101 prefix="{p}" parent="chassis">'
                    f'<origin xyz="0.1 {y} 0.15" rpy="0 0 0.3"/></xacro:so101>'
                    for p, y in (('left_', 0.1), ('right_', -0.1)))
    body = mobile_base().to_urdf().split('>', 2)[2].rsplit('</robot>', 1)[0]
    user.write_text('<?xml version="1.0"?><robot name="rover" '
                    'xmlns:xacro="http://www.ros.org/wiki/xacro">'
                    f'<xacro:include filename="so101.macro.xacro"/>{body}{calls}</robot>')
    expanded = xacro_expand(user)
    path = tmp_path / 'rover_arms.urdf'
    path.write_text(expanded)
    assert_check_urdf_accepts(path)
    assert_every_reference_exists(expanded)
    ours = Robot.from_urdf_string(base.to_urdf())
    theirs = Robot.from_urdf_string(expanded)
    assert sorted(link.name for link in theirs.links) == sorted(link.name for link in ours.links)
    for joint in ours.joints:
        assert theirs.get_joint(joint.name) == joint
    for link in ours.links:
        assert theirs.get_link(link.name) == link
    transmissions = [b.name for b in theirs.extensions if b.tag == 'transmission']
    assert len(transmissions) == 2 * 6 and len(set(transmissions)) == 12


def test_transmission_elements_naming_joints_follow_and_unnamed_colours_stay() -> None:
    from lxml import etree
    from urdfgenpy_ros import Robot
    robot = Robot.from_urdf_string(
        '<robot name="wrist"><link name="base_link"/><link name="cup">'
        '<visual><geometry><box size="0.1 0.1 0.1"/></geometry>'
        '<material name=""><color rgba="0 0 1 1"/></material></visual></link>'
        '<joint name="roll" type="continuous"><parent link="base_link"/><child link="cup"/>'
        '</joint><transmission name="wrist_trans" type="pr2_mechanism_model/WristTransmission">'
        '<rightActuator name="r_motor"/><flexJoint name="roll" reduction="1"/>'
        '<rollJoint name="roll" reduction="1"/></transmission></robot>')
    copy = robot.prefixed('left_', materials=True)
    written = etree.fromstring(copy.to_urdf().encode())
    joints = {joint.get('name') for joint in written.iter('joint')}
    assert [item.get('name') for item in written.find('transmission')
            if item.tag.endswith('Joint')] == ['left_roll', 'left_roll']
    assert joints == {'left_roll'}
    assert written.find('transmission/rightActuator').get('name') == 'left_r_motor'
    assert [m.get('name') for m in written.iter('material')] == ['']  # unnamed: unchanged


def _coloured(name: str, rgba: tuple[float, float, float, float]) -> Robot:
    from urdfgenpy_ros import Box, Link, Material, Visual
    robot = Robot(name)
    robot.add_material(Material('black', rgba))
    robot.add_material(Material(f'{name}_only', (0.5, 0.5, 0.5, 1.0)))
    robot.add_link(Link(f'{name}_base').add_visual(
        Visual(Box(0.1, 0.1, 0.1), material=Material('black'))))
    return robot


def test_two_macro_files_defining_one_material_make_a_robot_urdfdom_reads(
        tmp_path: Path) -> None:
    """A material both robots define is defined once, by the file included first."""
    for name, rgba in (('first', (0.0, 0.0, 0.0, 1.0)), ('second', (0.1, 0.1, 0.1, 1.0))):
        _coloured(name, rgba).to_xacro(tmp_path / f'{name}.urdf.xacro', macro=True)
    user = tmp_path / 'both.urdf.xacro'
    user.write_text('<?xml version="1.0"?><robot name="both" '
                    'xmlns:xacro="http://www.ros.org/wiki/xacro">'
                    '<xacro:include filename="first.macro.xacro"/>'
                    '<xacro:include filename="second.macro.xacro"/>'
                    '<xacro:include filename="first.macro.xacro"/>'  # again: still once
                    '<link name="world"/>'
                    '<xacro:first prefix="a_" parent="world"><origin xyz="0 0 0"/></xacro:first>'
                    '<xacro:second prefix="b_" parent="world"><origin xyz="1 0 0"/>'
                    '</xacro:second></robot>')
    path = tmp_path / 'both.urdf'
    path.write_text(xacro_expand(user))
    assert_check_urdf_accepts(path)
    defined = etree.parse(str(path)).getroot().findall('material')
    assert sorted(node.get('name') for node in defined) == ['black', 'first_only', 'second_only']
    assert [node.find('color').get('rgba') for node in defined
            if node.get('name') == 'black'] == ['0 0 0 1']
    theirs = load_yourdfpy(path)
    assert {link.name for link in theirs.links} == {'world', 'a_first_base', 'b_second_base'}
