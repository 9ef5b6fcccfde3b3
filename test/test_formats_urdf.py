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

"""The URDF writer: check_urdf accepts it, yourdfpy reads back exactly our model."""

from __future__ import annotations

import math
from pathlib import Path
import random

from helpers import assert_check_urdf_accepts, load_yourdfpy, pose_matrix
from lxml import etree
import pytest

from urdfgenpy_ros import Box, Joint, JointLimit, Link, Origin, Robot, Visual


def _same(matrix, origin: Origin) -> bool:
    return bool((matrix == pose_matrix(origin)).all())


def _optional(origin: Origin):
    return None if origin.is_identity else origin


def test_every_element_passes_check_urdf(every_element: Robot, tmp_path: Path) -> None:
    path = tmp_path / 'every.urdf'
    every_element.to_urdf(path)
    assert_check_urdf_accepts(path)


def test_every_element_reads_back_in_yourdfpy(every_element: Robot, tmp_path: Path) -> None:
    path = tmp_path / 'every.urdf'
    every_element.save(path)
    theirs = load_yourdfpy(path)
    ours = every_element
    assert theirs.name == ours.name
    assert [m.name for m in theirs.materials] == [m.name for m in ours.materials]
    for material in theirs.materials:
        mine = ours.get_material(material.name)
        assert tuple(material.color.rgba) == mine.rgba
        assert (material.texture.filename if material.texture else None) == mine.texture
    assert [link.name for link in theirs.links] == [link.name for link in ours.links]
    for link in theirs.links:
        mine = ours.get_link(link.name)
        assert link.inertial.mass == mine.inertial.mass
        assert link.inertial.inertia.tolist() == [list(row) for row in mine.inertial.tensor]
        assert _same(link.inertial.origin, mine.inertial.origin)
        for kind in ('visuals', 'collisions'):
            for their, my in zip(getattr(link, kind), getattr(mine, kind), strict=True):
                assert their.name == my.name
                if my.origin.is_identity:
                    assert their.origin is None
                else:
                    assert _same(their.origin, my.origin)
                shape = type(my.geometry).__name__.lower()
                geometry = getattr(their.geometry, shape)
                if shape == 'box':
                    assert tuple(geometry.size) == my.geometry.size
                elif shape == 'mesh':
                    assert geometry.filename == my.geometry.filename
                    assert tuple(geometry.scale) == my.geometry.scale
                else:
                    assert geometry.radius == my.geometry.radius
    assert [joint.name for joint in theirs.joints] == [joint.name for joint in ours.joints]
    for joint in theirs.joints:
        mine = ours.get_joint(joint.name)
        assert (joint.type, joint.parent, joint.child) == (
            mine.type.value, mine.parent, mine.child)
        assert _same(joint.origin, mine.origin)
        assert tuple(joint.axis) == mine.effective_axis
        for part, names in (('limit', ('lower', 'upper', 'effort', 'velocity')),
                            ('dynamics', ('damping', 'friction')),
                            ('mimic', ('joint', 'multiplier', 'offset')),
                            ('calibration', ('rising', 'falling')),
                            ('safety_controller', ('soft_lower_limit', 'soft_upper_limit',
                                                   'k_position', 'k_velocity'))):
            their, my = getattr(joint, part), getattr(mine, part)
            assert (their is None) == (my is None), (joint.name, part)
            if my is not None:
                values = [getattr(my, n) for n in names]
                assert [type(v)(getattr(their, n)) for n, v in zip(names, values)] == values


def test_extension_blocks_are_written_with_references(every_element: Robot) -> None:
    root = etree.fromstring(every_element.to_urdf().encode())
    gazebo = root.findall('gazebo')
    assert [block.get('reference') for block in gazebo] == ['base_link', 'rev', None]
    assert root.find('gazebo[@reference="base_link"]/material').text == 'Gazebo/Red'
    assert root.find('transmission/joint').get('name') == 'rev'
    assert root.find('ros2_control').get('type') == 'system'


def test_random_floats_read_back_bit_for_bit(tmp_path: Path) -> None:
    rng = random.Random(7)

    def number() -> float:
        return rng.choice([rng.uniform(-10, 10), rng.uniform(-1e-9, 1e-9),
                           rng.uniform(-1e9, 1e9), 1 / 3, -0.0, 0.1 + 0.2])

    robot = Robot('floats').add_link(Link('base'))
    for index in range(50):
        origin = Origin((number(), number(), number()), (number(), number(), number()))
        lower, upper = sorted((number(), number()))
        robot.add_link(Link(f'l{index}'))
        robot.add_joint(Joint(f'j{index}', 'revolute', 'base', f'l{index}', origin=origin,
                              axis=(0, 0, 1), limit=JointLimit(lower, upper,
                                                               effort=abs(number()),
                                                               velocity=abs(number()))))
    path = tmp_path / 'floats.urdf'
    robot.to_urdf(path)
    root = etree.parse(str(path)).getroot()
    for element, joint in zip(root.iter('joint'), robot.joints, strict=True):
        origin = element.find('origin')
        assert tuple(map(float, origin.get('xyz').split())) == joint.origin.xyz
        assert tuple(map(float, origin.get('rpy').split())) == joint.origin.rpy
        limit = element.find('limit')
        assert [float(limit.get(n)) for n in ('lower', 'upper', 'effort', 'velocity')] == [
            joint.limit.lower, joint.limit.upper, joint.limit.effort, joint.limit.velocity]
    theirs = load_yourdfpy(path)
    for their, mine in zip(theirs.joints, robot.joints):
        assert (their.limit.lower, their.limit.upper) == (mine.limit.lower, mine.limit.upper)
    assert_check_urdf_accepts(path)


def test_names_are_escaped(tmp_path: Path) -> None:
    name = 'a&b <"c">'
    robot = Robot('r&d').add_link(Link(name).add_visual(Visual(Box(1, 1, 1))))
    path = tmp_path / 'escaped.urdf'
    robot.to_urdf(path)
    theirs = load_yourdfpy(path)
    assert theirs.name == 'r&d' and theirs.links[0].name == name


def test_output_is_deterministic(every_element: Robot) -> None:
    from helpers import full_robot
    assert every_element.to_urdf() == full_robot().to_urdf()


def test_pi_is_written_exactly() -> None:
    robot = Robot('r').add_link(Link('a')).add_link(Link('b'))
    robot.add_joint(Joint('j', 'fixed', 'a', 'b', origin=Origin(rpy=(math.pi, 0, 0))))
    assert 'rpy="3.141592653589793 0 0"' in robot.to_urdf()


def test_save_refuses_an_unknown_suffix(ptu: Robot, tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="unknown suffix '.txt'"):
        ptu.save(tmp_path / 'ptu.txt')
