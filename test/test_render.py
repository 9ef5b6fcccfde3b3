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


"""``urdfgenpy render``: a headless picture whose pixels sit where the kinematics says."""

from __future__ import annotations

from pathlib import Path
import sys

from click.testing import CliRunner
from helpers import require_module
import pytest

from urdfgenpy_ros import (Box, Cylinder, Joint, JointLimit, Link, Material, Mesh, Origin,
                           Robot, Sphere, Visual)
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.robot import Robot as RobotType

RED = Material('red', rgba=(1.0, 0.0, 0.0, 1.0))
GREEN = Material('green', rgba=(0.0, 1.0, 0.0, 1.0))


def _require_renderer() -> None:
    pytest.importorskip('vtkmodules')
    pytest.importorskip('trimesh')


def _marker_robot(mesh: Path | None = None) -> RobotType:
    """Return an arm whose tip carries a red ball and whose slider carries a green one."""
    robot = Robot('markers')
    base = Link('base_link').add_visual(Visual(Box(0.3, 0.3, 0.05),
                                               material=Material('grey', rgba=(.5, .5, .5, 1))))
    blue = Material('blue', rgba=(.2, .3, .9, 1))
    arm = Link('arm').add_visual(Visual(Cylinder(0.02, 0.5), material=blue,
                                        origin=Origin((0.25, 0, 0), (0, 1.5708, 0))))
    tip = Link('tip').add_visual(Visual(Sphere(0.04), material=RED))
    slider = Link('slider')
    if mesh is None:
        slider.add_visual(Visual(Sphere(0.04), material=GREEN))
    else:
        slider.add_visual(Visual(Mesh(str(mesh), scale=(0.5, 0.5, 0.5)), material=GREEN))
    for link in (base, arm, tip, slider):
        robot.add_link(link)
    robot.add_joint(Joint('shoulder', 'revolute', 'base_link', 'arm', origin=Origin((0, 0, .1)),
                          axis=(0, 0, 1), limit=JointLimit(-3, 3, effort=1, velocity=1)))
    robot.add_joint(Joint('tip_joint', 'fixed', 'arm', 'tip', origin=Origin((0.5, 0, 0))))
    robot.add_joint(Joint('slide', 'prismatic', 'base_link', 'slider',
                          origin=Origin((-0.3, 0, 0.1)), axis=(0, 1, 0),
                          limit=JointLimit(-0.3, 0.3, effort=1, velocity=1)))
    return robot


def _centroid(pixels, colour: int) -> tuple[float, float]:
    """Return the (column, row) centroid of the pixels that are mostly ``colour``."""
    import numpy
    channel = pixels[:, :, colour].astype(int)
    others = pixels.astype(int).sum(axis=2) - channel
    rows, columns = numpy.nonzero((channel > 120) & (others < channel * 0.6))
    assert len(rows) > 50, 'the marker is not in the picture'
    return float(columns.mean()), float(rows.mean())


def _expected_pixel(picture, point) -> tuple[float, float]:
    """Project a point with the picture's orthographic camera, from its parameters."""
    import numpy
    camera = picture.camera
    offset = numpy.asarray(point) - numpy.asarray(camera.focal_point)
    return (camera.width / 2 + offset @ numpy.asarray(camera.right) / camera.metres_per_pixel,
            camera.height / 2 - offset @ numpy.asarray(camera.up) / camera.metres_per_pixel)


@pytest.mark.parametrize('shoulder, slide, view', [(0.0, 0.0, 'top'), (1.2, 0.25, 'top'),
                                                   (-2.0, -0.2, 'iso')])
def test_markers_are_drawn_where_yourdfpy_puts_them(tmp_path: Path, shoulder: float,
                                                    slide: float, view: str) -> None:
    _require_renderer()
    yourdfpy = require_module('yourdfpy')
    from urdfgenpy_ros.viewer.render import render
    robot = _marker_robot()
    urdf = tmp_path / 'markers.urdf'
    robot.to_urdf(urdf)
    reference = yourdfpy.URDF.load(str(urdf), load_meshes=False)  # independent kinematics
    reference.update_cfg({'shoulder': shoulder, 'slide': slide})
    picture = render(robot, {'shoulder': shoulder, 'slide': slide}, view, (400, 300))
    for link, colour in (('tip', 0), ('slider', 1)):
        expected = _expected_pixel(picture, reference.get_transform(link)[:3, 3])
        found = _centroid(picture.pixels, colour)
        assert abs(found[0] - expected[0]) < 3 and abs(found[1] - expected[1]) < 3, \
            (link, found, expected)


def test_example_is_not_blank_and_moves_with_its_joints(ptu: RobotType, tmp_path: Path) -> None:
    _require_renderer()
    import numpy
    urdf = tmp_path / 'ptu.urdf'
    ptu.to_urdf(urdf)
    images = []
    for index, joints in enumerate((['pan_joint=0', 'tilt_joint=0'],
                                    ['pan_joint=1.2', 'tilt_joint=-0.6'])):
        output = tmp_path / f'ptu{index}.png'
        arguments = ['render', str(urdf), '-o', str(output), '--size', '320x240']
        for joint in joints:
            arguments += ['--joints', joint]
        result = CliRunner().invoke(main, arguments)
        assert result.exit_code == 0, result.output
        assert output.read_bytes().startswith(b'\x89PNG')
        image = _read_png(output)
        assert image.shape[:2] == (240, 320)
        drawn = (image[:, :, :3] < 250).any(axis=2).mean()
        assert 0.05 < drawn < 0.9, drawn
        images.append(image)
    changed = (numpy.abs(images[0].astype(int) - images[1].astype(int)).sum(axis=2) > 30)
    assert changed.mean() > 0.01


def _read_png(path: Path):
    """Read a PNG with VTK's reader (another code path than the writer's)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[::-1]


def test_meshes_are_drawn(tmp_path: Path) -> None:
    _require_renderer()
    trimesh = require_module('trimesh')
    stl = tmp_path / 'ball.stl'
    trimesh.creation.icosphere(radius=0.08).export(stl)
    from urdfgenpy_ros.viewer.render import render
    picture = render(_marker_robot(stl), {'slide': 0.1}, 'top', (400, 300))
    assert not picture.problems
    _centroid(picture.pixels, 1)


def test_views_and_unknown_joint(ptu: RobotType) -> None:
    _require_renderer()
    from urdfgenpy_ros.model.errors import UrdfgenpyError
    from urdfgenpy_ros.viewer.render import render
    with pytest.raises(UrdfgenpyError, match="joint 'elbow': not a movable joint"):
        render(ptu, {'elbow': 1.0})
    widths = {view: render(ptu, {}, view, (200, 150)).camera.metres_per_pixel
              for view in ('front', 'side', 'top')}
    assert len(set(widths.values())) >= 2  # each view frames the robot its own way


def test_without_vtk_one_line_names_the_extra(ptu: RobotType, tmp_path: Path,
                                              monkeypatch: pytest.MonkeyPatch) -> None:
    urdf = tmp_path / 'ptu.urdf'
    ptu.to_urdf(urdf)
    monkeypatch.setitem(sys.modules, 'vtkmodules', None)  # as if not installed
    result = CliRunner().invoke(main, ['render', str(urdf), '-o', str(tmp_path / 'x.png')])
    assert result.exit_code == 2
    assert result.stderr == ('urdfgenpy: urdfgenpy render needs the Python package '
                             "'vtkmodules': pip install 'urdfgenpy_ros[render]'\n")


def test_init_puts_the_picture_and_the_tree_in_the_readme(tmp_path: Path) -> None:
    _require_renderer()
    pytest.importorskip('graphviz')
    from lxml import etree
    result = CliRunner().invoke(main, ['init', 'ptu_description', '--destination-directory',
                                       str(tmp_path)])
    assert result.exit_code == 0, result.output
    package = tmp_path / 'ptu_description'
    readme = (package / 'README.md').read_text()
    assert '![the robot](doc/robot.png)' in readme
    assert '![its kinematic tree](doc/tree.svg)' in readme
    image = _read_png(package / 'doc/robot.png')
    assert (image[:, :, :3] < 250).any(axis=2).mean() > 0.05  # the robot, not a blank
    texts = {text.text for text in etree.parse(str(package / 'doc/tree.svg')).iter(
        '{http://www.w3.org/2000/svg}text')}
    assert {'base_link', 'base_plate', 'pan_link', 'tilt_link', 'pan_joint'} <= texts


def test_init_without_the_extras_says_how_to_draw_them(tmp_path: Path,
                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, 'vtkmodules', None)  # as if not installed
    monkeypatch.setitem(sys.modules, 'graphviz', None)
    result = CliRunner().invoke(main, ['init', 'ptu_description', '--destination-directory',
                                       str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert result.stderr == ''
    package = tmp_path / 'ptu_description'
    assert not (package / 'doc').exists()
    readme = (package / 'README.md').read_text()
    assert 'doc/robot.png)' not in readme
    assert 'urdfgenpy render urdf/ptu.urdf.xacro -p .. -o doc/robot.png' in readme
