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


"""The URDF writer's errors: a user's value of the wrong kind is one line, our bug a traceback."""

from pathlib import Path

import pytest

from urdfgenpy_ros import ModelError, Robot
from urdfgenpy_ros.formats.urdf_element import ElementWriter

ARM = Path(__file__).parent / 'fixtures' / 'io' / 'two_space.urdf'


def _bug(*args: object, **kwargs: object) -> str:
    raise TypeError('a bug in the writer')


def test_a_bug_in_the_writer_surfaces_with_its_traceback(monkeypatch) -> None:
    """An error inside the writer is not turned into the user's error, even beside one."""
    robot = Robot.from_urdf(ARM)
    first, second = robot.links[0], robot.links[1]
    first.name = first.name + '_edited'  # written anew: through write()
    monkeypatch.setattr(ElementWriter, 'write', _bug)
    with pytest.raises(TypeError, match='a bug in the writer') as raised:
        robot.to_urdf()
    assert not isinstance(raised.value, ModelError)
    assert raised.traceback[-1].name == '_bug'  # where it was raised, not re-raised
    second.inertial.mass = 'abc'  # a user's mistake in a link written later
    with pytest.raises(TypeError, match='a bug in the writer'):
        robot.to_urdf()


def test_a_bug_in_the_writer_of_a_built_robot_surfaces_too(monkeypatch) -> None:
    from urdfgenpy_ros.examples import pan_tilt_unit
    robot = pan_tilt_unit()
    monkeypatch.setattr(ElementWriter, 'object_text', _bug)
    with pytest.raises(TypeError, match='a bug in the writer'):
        robot.to_urdf()


@pytest.mark.parametrize('edit, words', [
    (lambda robot: setattr(robot.get_link('upper_arm').inertial, 'mass', 'abc'),
     ["link 'upper_arm'", "inertial.mass = 'abc'", 'a number']),
    (lambda robot: setattr(robot.joints[0], 'origin', 'up'),
     ["joint 'shoulder_pan'", "origin = 'up'"]),
])
def test_a_value_of_the_wrong_kind_is_one_line_naming_it(edit, words: list[str]) -> None:
    robot = Robot.from_urdf(ARM)
    edit(robot)
    with pytest.raises(ModelError) as raised:
        robot.to_urdf()
    message = str(raised.value)
    assert '\n' not in message and all(word in message for word in words), message
