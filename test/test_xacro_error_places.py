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

"""An error in an included Xacro file names that file and the line where the text is."""

from __future__ import annotations

from pathlib import Path
import re
import subprocess
import sys

import pytest

from urdfgenpy_ros import ParseError, Robot

TOP = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="parts.xacro"/>
  <link name="base_link"/>
  <xacro:parts/>
</robot>
"""
PARTS = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <!-- a few lines, so that a line of this file is not one of the top file's -->


  <xacro:macro name="parts">
    <link name="arm"/>
    <joint name="k">
      <parent link="base_link"/>
      <child link="arm"/>
    </joint>
  </xacro:macro>
</robot>
"""


def _write(folder: Path, parts: str) -> Path:
    (folder / 'parts.xacro').write_text(parts)
    (folder / 'top.urdf.xacro').write_text(TOP)
    return folder / 'top.urdf.xacro'


def test_a_missing_attribute_in_an_include_names_the_include(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    top = _write(tmp_path, PARTS)
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(top)
    where = raised.value.location
    line = PARTS.splitlines().index('    <joint name="k">') + 1
    assert (Path(where.file).name, where.line, where.column) == ('parts.xacro', line, 5)
    assert raised.value.code == 'P002' and 'expanded' not in str(raised.value)


def test_an_xml_error_in_an_include_is_where_xacro_says(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    top = _write(tmp_path, PARTS.replace('<link name="arm"/>', '<link name="arm">'))
    xacro = subprocess.run([str(Path(sys.executable).with_name('xacro')), str(top)],
                           capture_output=True, text=True, timeout=60, cwd=tmp_path)
    said = xacro.stdout + xacro.stderr  # its own message names the file and the line
    assert 'parts.xacro' in said
    line = int(re.search(r'line (\d+), column', said).group(1))
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(top)
    where = raised.value.location
    assert (Path(where.file).name, where.line) == ('parts.xacro', line)
    assert line <= len(PARTS.splitlines())
