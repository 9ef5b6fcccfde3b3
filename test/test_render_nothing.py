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

"""A picture with nothing to draw names the meshes that did not resolve and the way out."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import require_module
import pytest

from urdfgenpy_ros import Box, Robot, Visual
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.viewer.pictures import package_pictures

MESHBOT = """<?xml version="1.0"?>
<robot name="meshbot">
  <link name="base_link">
    <visual><geometry><mesh filename="package://meshbot_description/meshes/base.stl"/>
    </geometry></visual>
    <collision><geometry><box size="0.3 0.2 0.1"/></geometry></collision>
  </link>
</robot>
"""


@pytest.fixture
def meshbot(tmp_path: Path) -> Path:
    require_module('vtkmodules')
    path = tmp_path / 'meshbot.urdf'
    path.write_text(MESHBOT)
    return path


def test_render_names_the_unresolved_mesh_and_suggests_collision(meshbot: Path) -> None:
    result = CliRunner().invoke(main, ['render', str(meshbot), '-o',
                                       str(meshbot.with_suffix('.png'))])
    assert result.exit_code == 2
    (line,) = result.stderr.splitlines()
    assert 'package://meshbot_description/meshes/base.stl' in line
    assert '--collision' in line and '--package-path' in line
    result = CliRunner().invoke(main, ['render', str(meshbot), '-o',
                                       str(meshbot.with_suffix('.png')), '--collision'])
    assert result.exit_code == 0, result.output
    assert meshbot.with_suffix('.png').read_bytes().startswith(b'\x89PNG')


def test_init_says_why_the_readme_has_no_picture(meshbot: Path) -> None:
    robot = Robot.from_urdf(meshbot)
    pictures, notes = package_pictures(robot)
    assert 'doc/robot.png' not in pictures
    assert any('no doc/robot.png' in note and 'base.stl' in note for note in notes)
    robot.links[0].add_visual(Visual(Box(0.1, 0.1, 0.1)))  # drawn, the mesh left out: said
    pictures, notes = package_pictures(robot)
    assert 'doc/robot.png' in pictures
    assert any('leaves out' in note and 'base.stl' in note for note in notes)
