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

"""Every Python example in README.md runs as written."""

from __future__ import annotations

import os
from pathlib import Path
import re

from helpers import assert_check_urdf_accepts, REPO

BLOCKS = re.findall(r'```python\n(.*?)```', (REPO / 'README.md').read_text(), re.S)


def test_readme_examples_run_in_order(tmp_path: Path) -> None:
    # The files the reading example opens.
    from urdfgenpy_ros.examples import pan_tilt_unit
    from urdfgenpy_ros import Inertial
    robot = pan_tilt_unit()
    robot.get_link('base_link').set_inertial(Inertial.from_sphere(1.0, 0.1))
    robot.save(tmp_path / 'robot.urdf')
    (tmp_path / 'robot.urdf.xacro').write_text(
        '<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:arg name="dof" default="6"/><link name="base_link"/>'
        '<xacro:property name="n" value="$(arg dof)"/><link name="link_${n}"/>'
        '<joint name="j" type="fixed"><parent link="base_link"/><child link="link_${n}"/>'
        '</joint></robot>')
    cwd = os.getcwd()
    os.chdir(tmp_path)
    namespace: dict = {}
    try:
        for code in BLOCKS:
            exec(compile(code, 'README.md', 'exec'), namespace)
    finally:
        os.chdir(cwd)
    for urdf in tmp_path.glob('*.urdf'):
        assert_check_urdf_accepts(urdf)
