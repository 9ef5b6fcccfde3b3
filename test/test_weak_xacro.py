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

"""A .urdf whose only Xacro is a $(...) in a mesh filename is read (urdfdom reads it), warned."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import check_urdf
import pytest

from urdfgenpy_ros import ParseError, Robot
from urdfgenpy_ros.cli import main

TOOL = """<?xml version="1.0"?>
<robot name="tool"{namespace}>
  <link name="base_link">
    <visual><geometry><mesh filename="{filename}"/></geometry></visual>
  </link>
</robot>
"""
FIND = '$(find tool_description)/meshes/gripper.stl'


def test_a_substitution_only_in_a_mesh_filename_is_a_warning(tmp_path: Path) -> None:
    path = tmp_path / 'tool.urdf'
    path.write_text(TOOL.format(namespace='', filename=FIND))
    assert check_urdf(path).returncode == 0  # urdfdom reads it
    robot = Robot.from_urdf(path)
    (warning,) = robot.read_warnings
    assert (warning.code, warning.location.line) == ('X104', 4)
    assert 'xacro' in warning.message
    assert robot.links[0].visuals[0].geometry.filename == FIND
    result = CliRunner().invoke(main, ['check', '--no-meshes', str(path)])
    assert ' X104 ' in result.stdout and ' X101 ' not in result.stdout


@pytest.mark.parametrize('namespace, filename', [
    (' xmlns:xacro="http://www.ros.org/wiki/xacro"', FIND),  # declared: it is Xacro
    ('', '${mesh_dir}/gripper.stl'),  # a property: nothing reads it but xacro
])
def test_stronger_evidence_is_still_refused(tmp_path: Path, namespace: str,
                                            filename: str) -> None:
    path = tmp_path / 'tool.urdf'
    path.write_text(TOOL.format(namespace=namespace, filename=filename))
    with pytest.raises(ParseError, match='X002'):
        Robot.from_urdf(path)
