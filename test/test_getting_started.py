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
The calls a newcomer makes first, checked by independent tools.

Keyword arguments as the guides spell them; check_urdf and yourdfpy read what we write,
xacro expands our Xacro to the same model, and the numbers are the shapes' closed forms.
"""

from __future__ import annotations

import math
from pathlib import Path

from helpers import (
    assert_check_urdf_accepts, load_yourdfpy, pose_matrix, snapshot, xacro_expand)
import pytest

from urdfgenpy_ros import (
    Box, Cylinder, Inertial, Joint, JointLimit, Link, Material, Origin, Robot, Sphere, Visual)


def _camera_mast() -> Robot:
    """Build a two-joint camera mast the way the getting-started guide builds its robot."""
    white = Material('white', rgba=(0.95, 0.95, 0.95, 1.0))
    black = Material('black', rgba=(0.05, 0.05, 0.05, 1.0))
    foot = Box(length=0.3, width=0.2, height=0.04)
    base = Link('foot')
    base.add_visual(Visual(geometry=foot, origin=Origin.above(foot), material=white))
    base.set_inertial(Inertial.from_geometry(mass=2.0, geometry=foot))
    pole = Cylinder(radius=0.02, length=0.6)
    mast = Link('mast')
    mast.add_visual(Visual(geometry=pole, origin=Origin.above(pole), material=white))
    mast.set_inertial(Inertial.from_geometry(mass=0.4, geometry=pole))
    lens = Sphere(0.04)
    camera = Link('camera')
    camera.add_visual(Visual(geometry=lens, origin=Origin(xyz=(0.02, 0, 0)), material=black))
    camera.set_inertial(Inertial.from_geometry(mass=0.15, geometry=lens))
    robot = Robot('camera_mast')
    robot.add_material(white).add_material(black)
    robot.add_link(base).add_link(mast).add_link(camera)
    robot.add_joint(Joint('mast_joint', 'revolute', 'foot', 'mast',
                          origin=Origin(xyz=(0, 0, 0.04)), axis=(0, 0, 1),
                          limit=JointLimit(-2.0, 2.0, effort=8, velocity=1.0)))
    robot.add_joint(Joint('camera_joint', 'revolute', 'mast', 'camera',
                          origin=Origin(xyz=(0, 0, 0.6)), axis=(0, 1, 0),
                          limit=JointLimit(-0.7, 1.2, effort=2, velocity=2.0)))
    return robot


@pytest.fixture
def written(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
            capsys: pytest.CaptureFixture[str]) -> dict:
    """Build the mast and export it every way the guide shows, in a scratch folder."""
    monkeypatch.chdir(tmp_path)
    robot = _camera_mast()
    robot.save('mast.urdf')
    robot.print_tree()
    text = robot.tree_string()
    robot.save_tree('tree.txt')
    urdf_xml, xacro_xml = robot.to_urdf(), robot.to_xacro()
    robot.to_urdf('output.urdf')
    robot.to_xacro('output.xacro')
    robot.save('saved.urdf')
    robot.save('saved.xacro')
    return {'robot': robot, 'dir': tmp_path, 'text': text, 'urdf': urdf_xml,
            'xacro': xacro_xml, 'printed': capsys.readouterr().out}


def test_the_urdf_passes_check_urdf_and_yourdfpy_reads_every_value(written: dict) -> None:
    folder, ours = written['dir'], written['robot']
    assert_check_urdf_accepts(folder / 'mast.urdf')
    theirs = load_yourdfpy(folder / 'mast.urdf')
    assert [link.name for link in theirs.links] == ['foot', 'mast', 'camera']
    for link in theirs.links:
        mine = ours.get_link(link.name)
        assert link.inertial.mass == mine.inertial.mass
        assert link.inertial.inertia.tolist() == [list(row) for row in mine.inertial.tensor]
        assert (link.visuals[0].origin == pose_matrix(mine.visual.origin)).all()
        assert link.visuals[0].material.name == mine.visual.material.name
    for joint in theirs.joints:
        mine = ours.get_joint(joint.name)
        assert (joint.type, joint.parent, joint.child) == (mine.type.value, mine.parent,
                                                           mine.child)
        assert (joint.origin == pose_matrix(mine.origin)).all()
        assert joint.axis.tolist() == list(mine.axis)
        assert (joint.limit.lower, joint.limit.upper, joint.limit.effort,
                joint.limit.velocity) == (mine.limit.lower, mine.limit.upper,
                                          mine.limit.effort, mine.limit.velocity)
    colours = {material.name: material.color.rgba.tolist() for material in theirs.materials}
    assert colours == {'white': [0.95, 0.95, 0.95, 1.0], 'black': [0.05, 0.05, 0.05, 1.0]}


def test_every_export_writes_what_the_strings_hold(written: dict) -> None:
    folder = written['dir']
    assert (folder / 'tree.txt').read_text(encoding='utf-8') == written['text']
    assert 'camera_joint [revolute] → camera' in written['text']
    assert '\033[' not in written['printed'], 'colour codes printed to a non-terminal'
    assert written['urdf'] == (folder / 'output.urdf').read_text(encoding='utf-8')
    assert written['urdf'] == (folder / 'saved.urdf').read_text(encoding='utf-8')
    assert written['xacro'] == (folder / 'output.xacro').read_text(encoding='utf-8')
    assert written['xacro'] == (folder / 'saved.xacro').read_text(encoding='utf-8')
    expanded = folder / 'expanded.urdf'
    expanded.write_text(xacro_expand(folder / 'saved.xacro'))
    assert snapshot(load_yourdfpy(expanded)) == snapshot(load_yourdfpy(folder / 'saved.urdf'))


@pytest.mark.parametrize('shape, lift', [
    (Box(length=0.2, width=0.2, height=0.1), 0.05),
    (Cylinder(0.05, 0.3), 0.15),
    (Sphere(0.1), 0.1),  # a sphere's bottom lies a whole radius below its centre
])
def test_origin_above_puts_the_bottom_of_the_shape_at_zero(shape, lift: float) -> None:
    assert Origin.above(shape).xyz == (0.0, 0.0, lift)


def test_wheel_origin_turns_a_cylinder_axis_onto_y() -> None:
    wheel = Origin.wheel(xy=(-0.15, 0.0), z=0.05)
    assert wheel.xyz == (-0.15, 0.0, 0.05)
    matrix = pose_matrix(wheel)
    assert matrix[:3, 2].round(12).tolist() in ([0.0, 1.0, 0.0], [0.0, -1.0, 0.0])


def test_inertia_helpers_give_the_closed_forms() -> None:
    box = Inertial.from_box(mass=1.0, length=0.2, w=0.2, h=0.1)
    assert (box.ixx, box.iyy, box.izz) == pytest.approx(
        ((0.2 ** 2 + 0.1 ** 2) / 12, (0.2 ** 2 + 0.1 ** 2) / 12, (0.2 ** 2 + 0.2 ** 2) / 12),
        rel=1e-15)
    cylinder = Inertial.from_cylinder(mass=0.5, radius=0.05, length=0.2)
    assert (cylinder.ixx, cylinder.izz) == pytest.approx(
        (0.5 * (3 * 0.05 ** 2 + 0.2 ** 2) / 12, 0.5 * 0.05 ** 2 / 2), rel=1e-15)
    sphere = Inertial.from_sphere(mass=0.1, radius=0.03)
    assert sphere.ixx == sphere.iyy == sphere.izz == pytest.approx(0.4 * 0.1 * 0.03 ** 2)
    dispatched = Inertial.from_geometry(mass=1.0, geometry=Box(0.2, 0.2, 0.1))
    assert dispatched.tensor == box.tensor
    assert all(math.isclose(value, 0.0) for value in (box.ixy, box.ixz, box.iyz))
