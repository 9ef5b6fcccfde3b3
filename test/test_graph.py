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


"""``urdfgenpy graph``: the diagram names every link and joint of the model."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import load_yourdfpy, require_module, require_tool
from lxml import etree
import pytest

from urdfgenpy_ros import Joint, Link
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.robot import Robot

SVG = '{http://www.w3.org/2000/svg}'


def _draw(robot: Robot, tmp_path: Path, name: str) -> tuple[Path, Path]:
    pytest.importorskip('graphviz')
    require_tool('dot')
    urdf = tmp_path / 'robot.urdf'
    robot.to_urdf(urdf)
    output = tmp_path / name
    result = CliRunner().invoke(main, ['graph', str(urdf), '-o', str(output)])
    assert result.exit_code == 0, result.output
    return urdf, output


def _groups(svg: Path, kind: str) -> dict[str, list[str]]:
    """Return the texts of each SVG group of class ``kind``, by the group's id."""
    root = etree.parse(str(svg)).getroot()
    return {group.get('id'): [text.text for text in group.iter(SVG + 'text')]
            for group in root.iter(SVG + 'g') if group.get('class') == kind}


def test_svg_has_a_box_per_link_and_a_labelled_edge_per_joint(
        every_element: Robot, tmp_path: Path) -> None:
    urdf, svg = _draw(every_element, tmp_path, 'tree.svg')
    reference = load_yourdfpy(urdf)  # the model as an independent reader sees it
    nodes, edges = _groups(svg, 'node'), _groups(svg, 'edge')
    assert {key.removeprefix('link:') for key in nodes} == {
        link.name for link in reference.links}
    for link in reference.links:
        assert nodes[f'link:{link.name}'] == [link.name]
    assert {key.removeprefix('joint:') for key in edges} == {
        joint.name for joint in reference.joints}
    root = etree.parse(str(svg)).getroot()
    for joint in reference.joints:
        label = edges[f'joint:{joint.name}']
        assert label[:2] == [joint.name, f'[{joint.type}]']
        if joint.type in ('revolute', 'prismatic'):
            lower, upper = joint.limit.lower, joint.limit.upper
            assert f'{lower:.4g} .. {upper:.4g}' in ' '.join(label)
        if joint.type in ('revolute', 'prismatic', 'continuous', 'planar'):
            axis = ' '.join(f'{value:.4g}' for value in joint.axis)
            assert f'axis {axis}' in label
        if joint.mimic is not None:
            assert f'mimics {joint.mimic.joint}' in label
        group = next(g for g in root.iter(SVG + 'g') if g.get('id') == f'joint:{joint.name}')
        stroke = group.find(SVG + 'path').get('stroke')
        assert (stroke == '#9a9a9a') == (joint.type == 'fixed'), joint.name


@pytest.mark.parametrize('suffix, magic', [('png', b'\x89PNG\r\n\x1a\n'), ('pdf', b'%PDF-')])
def test_png_and_pdf(ptu: Robot, tmp_path: Path, suffix: str, magic: bytes) -> None:
    _, output = _draw(ptu, tmp_path, f'tree.{suffix}')
    data = output.read_bytes()
    assert data.startswith(magic) and len(data) > 1000


def test_unknown_format_is_one_line_exit_2(ptu: Robot, tmp_path: Path) -> None:
    pytest.importorskip('graphviz')
    urdf = tmp_path / 'robot.urdf'
    ptu.to_urdf(urdf)
    result = CliRunner().invoke(main, ['graph', str(urdf), '-o', str(tmp_path / 'x.gif')])
    assert result.exit_code == 2
    assert result.stderr.count('\n') == 1 and "unknown diagram format 'gif'" in result.stderr


def test_a_wide_flat_tree_is_drawn_left_to_right(tmp_path: Path) -> None:
    """A base link with forty frames on it: a readable picture, not a strip of boxes."""
    pillow = require_module('PIL.Image')
    robot = Robot('base').add_link(Link('base_link'))
    for number in range(40):
        robot.add_link(Link(f'sensor_{number}_link'))
        robot.add_joint(Joint(f'sensor_{number}_joint', 'fixed', 'base_link',
                              f'sensor_{number}_link'))
    _, png = _draw(robot, tmp_path, 'tree.png')
    width, height = pillow.open(png).size
    assert max(width, height) / min(width, height) < 3, (width, height)
