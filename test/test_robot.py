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

"""Building, navigating and editing a Robot; bad input fails at construction."""

from __future__ import annotations

import math
from pathlib import Path

from helpers import load_yourdfpy
import pytest

from urdfgenpy_ros import (
    Box, Cylinder, Inertial, Joint, JointLimit, JointMimic, JointType, Link, Material, Mesh,
    ModelError, Origin, Robot, Sphere, Visual)


def _chain(count: int) -> Robot:
    robot = Robot('chain').add_link(Link('l0'))
    for number in range(1, count):
        robot.add_link(Link(f'l{number}'))
        robot.add_joint(Joint(f'j{number}', 'continuous', f'l{number - 1}', f'l{number}'))
    return robot


def test_building_chains_and_keeps_order() -> None:
    robot = Robot('r').add_material(Material('m', rgba=(1, 0, 0, 1))).add_link(Link('a'))
    assert robot.add_link(Link('b')) is robot
    robot.add_joint(Joint('j', 'fixed', 'a', 'b'))
    assert [link.name for link in robot.links] == ['a', 'b']
    assert [joint.name for joint in robot.joints] == ['j']
    assert robot.materials[0].rgba == (1.0, 0.0, 0.0, 1.0)


def test_a_joint_type_set_by_name_is_a_joint_type(ptu: Robot, tmp_path: Path) -> None:
    """``joint.type = 'fixed'`` works like the constructor's name; a wrong one fails there."""
    joint = ptu.get_joint('tilt_joint')
    joint.type = 'fixed'
    joint.limit = None
    assert joint.type is JointType.FIXED and not joint.is_movable
    assert 'tilt_joint [fixed]' in ptu.tree_string()
    assert not [finding for finding in ptu.validate() if finding.severity == 'error']
    ptu.to_urdf(tmp_path / 'ptu.urdf')
    written = load_yourdfpy(tmp_path / 'ptu.urdf').joints
    assert [joint.type for joint in written if joint.name == 'tilt_joint'] == ['fixed']
    with pytest.raises(ModelError, match="joint 'tilt_joint': unknown type 'hinge'"):
        joint.type = 'hinge'
    assert joint.type is JointType.FIXED  # the joint is as it was


def test_a_value_of_the_wrong_kind_names_its_link_and_overwrites_nothing(
        ptu: Robot, tmp_path: Path) -> None:
    """``inertial.mass = 'abc'`` on a read robot: one error naming the link; the file stays."""
    target = tmp_path / 'ptu.urdf'
    ptu.to_urdf(target)
    robot = Robot.from_urdf(target)
    robot.get_link('tilt_link').inertial.mass = 'abc'
    robot.get_joint('pan_joint').origin = 'up'
    with pytest.raises(ModelError, match="^link 'tilt_link': cannot be written.*'abc'"):
        robot.to_urdf(target)
    with pytest.raises(ModelError, match="^link 'tilt_link'"):
        robot.to_xacro(tmp_path / 'ptu.urdf.xacro')
    assert Robot.from_urdf(target) == ptu  # the file as it was
    robot.get_link('tilt_link').inertial.mass = 0.25
    with pytest.raises(ModelError, match="^joint 'pan_joint': cannot be written"):
        robot.to_urdf(target)


def test_inertial_is_mutable_through_get_link(ptu: Robot) -> None:
    ptu.get_link('base_plate').inertial.mass = 100.0
    assert ptu.get_link('base_plate').inertial.mass == 100.0
    assert '<mass value="100"/>' in ptu.to_urdf()


@pytest.mark.parametrize('make, words', [
    (lambda: Joint('j', 'hinge', 'a', 'b'), ["joint 'j'", "unknown type 'hinge'",
                                             'revolute, continuous']),
    (lambda: Box(0.1, -0.2, 0.3), ['box', 'width', 'positive', '-0.2']),
    (lambda: Cylinder(math.nan, 1.0), ['cylinder', 'radius', 'nan']),
    (lambda: Sphere(math.inf), ['sphere', 'radius', 'inf']),
    (lambda: Inertial(-1.0), ['inertial', 'mass', '>= 0', '-1.0']),
    (lambda: Inertial.from_box(math.nan, 1, 1, 1), ['mass', 'nan']),
    (lambda: Inertial.from_sphere(1.0, 0.0), ['sphere', 'radius', '0.0']),
    (lambda: JointLimit(-1, 1, effort=-5), ['limit', 'effort', '-5']),
    (lambda: Origin(xyz=(0, 0)), ['origin', 'xyz', '3 numbers']),
    (lambda: Origin(rpy=(0, math.nan, 0)), ['origin', 'rpy', 'finite']),
    (lambda: Material('m', rgba=(255, 0, 0, 1)), ["material 'm'", 'rgba', '255']),
    (lambda: Mesh('a.stl', scale=(1, 0, 1)), ["mesh 'a.stl'", 'scale']),
    (lambda: Joint('j', 'revolute', 'a', 'b', axis=(0, 0, 0)), ["joint 'j'", 'axis']),
    (lambda: Link(''), ['link', 'name']),
])
def test_bad_values_raise_value_error_naming_element_and_fix(make, words) -> None:
    with pytest.raises(ValueError) as raised:
        make()
    for word in words:
        assert word in str(raised.value)


def test_duplicate_names_are_refused() -> None:
    robot = Robot('r').add_link(Link('a')).add_link(Link('b'))
    with pytest.raises(ValueError, match="link 'a' already exists.*rename"):
        robot.add_link(Link('a'))
    robot.add_joint(Joint('j', 'fixed', 'a', 'b'))
    robot.add_link(Link('c'))
    with pytest.raises(ValueError, match="joint 'j' already exists"):
        robot.add_joint(Joint('j', 'fixed', 'b', 'c'))
    robot.add_material(Material('m'))
    with pytest.raises(ValueError, match="material 'm' already exists"):
        robot.add_material(Material('m'))


def test_joint_naming_a_missing_link_is_refused_with_a_suggestion() -> None:
    robot = Robot('r').add_link(Link('base_link')).add_link(Link('arm'))
    with pytest.raises(ValueError, match="parent link 'base_lnk' is not in robot 'r'.*"
                                         "did you mean 'base_link'.*add the link"):
        robot.add_joint(Joint('j', 'fixed', 'base_lnk', 'arm'))
    with pytest.raises(ValueError, match='parent and child are both'):
        robot.add_joint(Joint('j', 'fixed', 'arm', 'arm'))


def test_wrong_object_types_are_refused() -> None:
    with pytest.raises(TypeError, match='add_visual'):
        Link('a').add_visual(Box(1, 1, 1))
    with pytest.raises(TypeError, match='add_link'):
        Robot('r').add_link('a')


def test_navigation_from_root_through_parents_and_children(ptu: Robot) -> None:
    assert ptu.root.name == 'base_link'
    assert ptu.parent_joint('tilt_link').name == 'tilt_joint'
    assert ptu.parent_link('tilt_link').name == 'pan_link'
    assert ptu.parent_link('base_link') is None
    assert [link.name for link in ptu.child_links('base_plate')] == ['pan_link']
    assert [joint.name for joint in ptu.chain('tilt_link', 'base_plate')] == [
        'pan_joint', 'tilt_joint']
    assert [link.name for _, link in ptu.walk()] == ['base_link', 'base_plate', 'pan_link',
                                                     'tilt_link']
    with pytest.raises(KeyError, match="did you mean 'pan_link'"):
        ptu.get_link('pan_lnk')


def test_root_with_two_roots_explains_the_fix() -> None:
    robot = Robot('r').add_link(Link('a')).add_link(Link('b'))
    assert [link.name for link in robot.roots] == ['a', 'b']
    with pytest.raises(ValueError, match="exactly one root.*'a', 'b'.*connect them"):
        robot.root


def test_remove_link_refuses_children_unless_asked() -> None:
    robot = _chain(4)
    with pytest.raises(ValueError, match="link 'l1' has child links 'l2'.*subtree=True"):
        robot.remove_link('l1')
    removed = robot.remove_link('l1', subtree=True)
    assert [link.name for link in removed] == ['l1', 'l2', 'l3']
    assert [link.name for link in robot.links] == ['l0'] and robot.joints == []


def test_remove_leaf_and_joint_keep_the_tree_consistent() -> None:
    robot = _chain(3)
    robot.remove_link('l2')
    assert [joint.name for joint in robot.joints] == ['j1']
    robot.remove_joint('j1')
    assert [link.name for link in robot.roots] == ['l0', 'l1']


def test_rename_link_updates_joints_and_references() -> None:
    robot = _chain(3)
    from urdfgenpy_ros import Extension
    robot.get_link('l1').add_extension(Extension.gazebo('<mu1>0.5</mu1>'))
    robot.add_extension(Extension.gazebo('<x/>', reference='l1'))
    robot.rename_link('l1', 'elbow')
    assert (robot.get_joint('j1').child, robot.get_joint('j2').parent) == ('elbow', 'elbow')
    assert [link.name for link in robot.links] == ['l0', 'elbow', 'l2']
    text = robot.to_urdf()
    assert text.count('reference="elbow"') == 2 and 'l1' not in text
    with pytest.raises(ValueError, match='taken'):
        robot.rename_link('l0', 'elbow')


def test_rename_joint_updates_mimics() -> None:
    robot = _chain(3)
    robot.get_joint('j2').mimic = JointMimic('j1', 2.0)
    robot.rename_joint('j1', 'shoulder')
    assert robot.get_joint('j2').mimic == JointMimic('shoulder', 2.0)
    assert [joint.name for joint in robot.joints] == ['shoulder', 'j2']


def test_rename_material_updates_visuals() -> None:
    red = Material('red', rgba=(1, 0, 0, 1))
    robot = Robot('r').add_material(red)
    robot.add_link(Link('a').add_visual(Visual(Box(1, 1, 1), material=red)))
    robot.rename_material('red', 'crimson')
    assert robot.get_link('a').visual.material.name == 'crimson'
    assert robot.materials[0] == Material('crimson', rgba=(1, 0, 0, 1))


def test_walk_terminates_on_a_loop() -> None:
    robot = _chain(3)
    robot._joints['back'] = Joint('back', 'fixed', 'l2', 'l0')
    assert robot.roots == []
    assert [link.name for _, link in robot.walk('l0')] == ['l0', 'l1', 'l2']
    assert 'not reachable from a root: l0, l1, l2' in robot.tree_string()


def test_equality_compares_the_model(ptu: Robot) -> None:
    from urdfgenpy_ros.examples import pan_tilt_unit
    assert ptu == pan_tilt_unit()
    ptu.get_joint('pan_joint').limit.upper = 3.0
    assert ptu != pan_tilt_unit()


def test_remove_material_returns_it_and_forgets_it(ptu: Robot) -> None:
    removed = ptu.remove_material('amber')
    assert removed.rgba == (1.0, 0.55, 0.0, 1.0)
    assert [material.name for material in ptu.materials] == ['charcoal']
    with pytest.raises(KeyError, match="no material 'amber'"):
        ptu.get_material('amber')


def test_rename_follows_every_reference_prefixed_follows() -> None:
    # One mechanism for both: a rename reaches what prefixed() reaches (transmission
    # elements naming the joint, plugin text naming the link), checked with lxml.
    from lxml import etree
    robot = Robot.from_urdf_string(
        '<robot name="r"><link name="base_link"/><link name="cup"/>'
        '<joint name="roll" type="continuous"><parent link="base_link"/><child link="cup"/>'
        '</joint><transmission name="t"><rollJoint name="roll"/></transmission>'
        '<gazebo><plugin name="p" filename="x.so"><frame_id>cup</frame_id></plugin></gazebo>'
        '</robot>')
    robot.rename_joint('roll', 'wrist_roll')
    robot.rename_link('cup', 'gripper')
    written = etree.fromstring(robot.to_urdf().encode())
    assert written.find('transmission/rollJoint').get('name') == 'wrist_roll'
    assert written.findtext('gazebo/plugin/frame_id') == 'gripper'
    assert written.find('joint/child').get('link') == 'gripper'
