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


"""``convert SOURCE NAME:=VALUE... TARGET``: Xacro arguments before TARGET, as check takes them."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import check_urdf

from urdfgenpy_ros.cli import main

ARM = """<?xml version="1.0"?>
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="kind" default="small"/>
  <xacro:arg name="name" default="arm"/>
  <link name="$(arg name)_$(arg kind)_base"/>
</robot>
"""


def _source(tmp_path: Path) -> Path:
    source = tmp_path / 'arm.urdf.xacro'
    source.write_text(ARM)
    return source


def test_arguments_before_the_target_are_taken_as_arguments(tmp_path: Path) -> None:
    source, target = _source(tmp_path), tmp_path / 'out.urdf'
    result = CliRunner().invoke(main, ['convert', str(source), 'kind:=large', 'name:=ur',
                                       str(target)])
    assert result.exit_code == 0, result.output
    parsed = check_urdf(target)  # urdfdom reads the link the arguments named
    assert parsed.returncode == 0 and 'root Link: ur_large_base' in parsed.stdout, parsed.stdout


def test_arguments_with_no_target_say_how_to_give_one(tmp_path: Path) -> None:
    source = _source(tmp_path)
    result = CliRunner().invoke(main, ['convert', str(source), 'kind:=large', 'name:=ur'])
    assert result.exit_code == 2
    assert 'give one TARGET' in result.output and 'unknown suffix' not in result.output
    assert not list(tmp_path.glob('*.urdf'))
