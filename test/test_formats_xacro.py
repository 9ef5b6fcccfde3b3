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

"""The Xacro writer: the real xacro expands it to exactly the model to_urdf() writes."""

from __future__ import annotations

from pathlib import Path

from helpers import (
    assert_check_urdf_accepts, canonical_blocks, load_yourdfpy, snapshot, xacro_expand)
from lxml import etree

from urdfgenpy_ros import Box, Extension, Inertial, Link, Robot, Visual


def _both(robot: Robot, folder: Path) -> tuple[Path, Path]:
    urdf = folder / f'{robot.name}.urdf'
    robot.save(urdf)
    source = folder / f'{robot.name}.urdf.xacro'
    robot.save(source)
    expanded = folder / f'{robot.name}.expanded.urdf'
    expanded.write_text(xacro_expand(source), encoding='utf-8')
    return urdf, expanded


def test_ptu_xacro_expands_to_the_same_model(ptu: Robot, tmp_path: Path) -> None:
    urdf, expanded = _both(ptu, tmp_path)
    assert snapshot(load_yourdfpy(expanded)) == snapshot(load_yourdfpy(urdf))
    assert_check_urdf_accepts(expanded)


def test_every_element_xacro_expands_to_the_same_model(every_element: Robot,
                                                       tmp_path: Path) -> None:
    urdf, expanded = _both(every_element, tmp_path)
    assert snapshot(load_yourdfpy(expanded)) == snapshot(load_yourdfpy(urdf))
    assert canonical_blocks(expanded.read_text()) == canonical_blocks(urdf.read_text())
    assert_check_urdf_accepts(urdf)
    assert_check_urdf_accepts(expanded)


def test_xacro_is_idiomatic(ptu: Robot) -> None:
    root = etree.fromstring(ptu.to_xacro().encode())
    xacro = '{http://www.ros.org/wiki/xacro}'
    properties = {p.get('name'): p.get('value') for p in root.iter(f'{xacro}property')}
    assert properties == {'base_plate_mass': '0.8', 'pan_link_mass': '0.18',
                          'tilt_link_mass': '0.12'}
    macros = sorted(m.get('name') for m in root.iter(f'{xacro}macro'))
    assert macros == ['box_inertial', 'cylinder_inertial']
    calls = [element.tag for element in root.iter(f'{xacro}box_inertial')]
    assert len(calls) == 2


def test_edited_and_explicit_inertials_fall_back_to_plain_tags(tmp_path: Path) -> None:
    edited = Inertial.from_box(1.0, 0.1, 0.2, 0.3)
    edited.ixx = 5.0
    robot = Robot('r').add_link(Link('a').set_inertial(edited))
    robot.add_link(Link('b').set_inertial(Inertial(2.0, 1, 0, 0, 1, 0, 1)))
    from urdfgenpy_ros import Joint
    robot.add_joint(Joint('j', 'fixed', 'a', 'b'))
    text = robot.to_xacro()
    assert 'box_inertial' not in text and 'value="${a_mass}"' in text
    urdf, expanded = _both(robot, tmp_path)
    assert snapshot(load_yourdfpy(expanded)) == snapshot(load_yourdfpy(urdf))
    assert load_yourdfpy(expanded).links[0].inertial.inertia[0][0] == 5.0


def test_dollar_text_is_escaped_so_xacro_keeps_it(tmp_path: Path) -> None:
    robot = Robot('r').add_link(Link('${prefix}base').add_visual(
        Visual(Box(1, 1, 1))))
    robot.add_extension(Extension.ros2_control(
        'sys', '<joint name="j"><param name="min">${-2*pi}</param>'
               '<param name="path">$(find pkg)/x</param></joint>'))
    urdf, expanded = _both(robot, tmp_path)
    text = expanded.read_text()
    assert '${-2*pi}' in text and '$(find pkg)/x' in text
    assert load_yourdfpy(expanded).links[0].name == '${prefix}base'
    assert canonical_blocks(text) == canonical_blocks(urdf.read_text())
