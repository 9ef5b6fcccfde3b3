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

"""A value set in Python that no URDF reader takes is one line, never a file urdfdom refuses."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from helpers import check_urdf_verdict, require_module
import pytest

from urdfgenpy_ros import ModelError, Robot
from urdfgenpy_ros.examples import pan_tilt_unit


def _no_mass(robot: Robot) -> None:
    next(link for link in robot.links if link.inertial).inertial.mass = None  # type: ignore


def _short_axis(robot: Robot) -> None:
    next(joint for joint in robot.joints if joint.axis).axis = (0.0, 1.0)  # type: ignore


def _no_name(robot: Robot) -> None:
    robot.name = None  # type: ignore[assignment]


EDITS: dict[str, tuple[Callable[[Robot], None], str]] = {
    'mass None': (_no_mass, 'inertial.mass = None'),
    'axis of two numbers': (_short_axis, 'axis = (0.0, 1.0) (expected 3 numbers)'),
    'no robot name': (_no_name, 'its name is None'),
}


@pytest.mark.parametrize('read', [False, True], ids=['built', 'read'])
@pytest.mark.parametrize('case', sorted(EDITS))
def test_a_value_no_reader_takes_is_one_line(tmp_path: Path, case: str, read: bool) -> None:
    edit, said = EDITS[case]
    path = tmp_path / 'ptu.urdf'
    pan_tilt_unit().to_urdf(path)
    robot = Robot.from_urdf(path) if read else pan_tilt_unit()
    edit(robot)
    # what the writer would have put there, judged by urdfdom: refused
    text = path.read_text()
    broken = {'mass None': (text, '<mass value="', '<mass foo="'),
              'axis of two numbers': (text, '<axis xyz="0 0 1"', '<axis xyz="0 1"'),
              'no robot name': (text, '<robot name="', '<robot foo="')}[case]
    bad = tmp_path / 'bad.urdf'
    bad.write_text(broken[0].replace(broken[1], broken[2], 1))
    assert bad.read_text() != text
    if case == 'mass None':  # urdfdom reads <mass/> as nothing said; MuJoCo refuses it
        with pytest.raises(ValueError, match="required attribute missing: 'value'"):
            require_module('mujoco').MjModel.from_xml_string(bad.read_text())
    else:
        assert not check_urdf_verdict(bad, timeout=10)
    with pytest.raises(ModelError) as raised:
        robot.to_urdf()
    message = str(raised.value)
    assert said in message and '\n' not in message
