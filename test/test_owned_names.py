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

"""Names are the robot's: ``link.name = 'x'`` renames everywhere; writer bugs keep a traceback."""

from __future__ import annotations

import copy
from pathlib import Path

from helpers import check_urdf, load_yourdfpy
import pytest

from urdfgenpy_ros import Extension, Joint, JointMimic, Link, ModelError, Robot
from urdfgenpy_ros.formats import urdf as urdf_format


def _arm() -> Robot:
    robot = Robot('arm').add_link(Link('base_link')).add_link(Link('upper'))
    robot.add_link(Link('finger'))
    robot.add_joint(Joint('shoulder', 'continuous', 'base_link', 'upper', axis=(0, 0, 1)))
    robot.add_joint(Joint('finger_joint', 'continuous', 'upper', 'finger', axis=(0, 0, 1),
                          mimic=JointMimic('shoulder')))
    robot.get_link('upper').add_extension(Extension('<gazebo reference="upper"/>'))
    return robot


def test_setting_a_link_name_renames_it_in_the_robot(tmp_path: Path) -> None:
    robot = _arm()
    robot.get_link('upper').name = 'forearm'
    assert robot.has_link('forearm') and not robot.has_link('upper')
    assert robot.get_joint('shoulder').child == 'forearm'
    assert robot.get_joint('finger_joint').parent == 'forearm'
    assert not [finding for finding in robot.validate() if finding.severity == 'error']
    robot.to_urdf(tmp_path / 'arm.urdf')
    assert check_urdf(tmp_path / 'arm.urdf').returncode == 0  # urdfdom finds the tree whole
    model = load_yourdfpy(tmp_path / 'arm.urdf')
    assert {joint.child for joint in model.joints} == {'forearm', 'finger'}
    assert 'reference="forearm"' in (tmp_path / 'arm.urdf').read_text()


def test_setting_a_joint_name_renames_its_mimics() -> None:
    robot = _arm()
    robot.get_joint('shoulder').name = 'shoulder_pan'
    assert robot.get_joint('shoulder_pan').child == 'upper'
    assert robot.get_joint('finger_joint').mimic.joint == 'shoulder_pan'
    with pytest.raises(ModelError, match="'finger_joint'.*taken"):
        robot.get_joint('shoulder_pan').name = 'finger_joint'


def test_a_taken_or_empty_name_is_refused_and_the_robot_is_unchanged() -> None:
    robot = _arm()
    with pytest.raises(ModelError, match='taken'):
        robot.get_link('upper').name = 'finger'
    with pytest.raises(ModelError, match='non-empty'):
        robot.get_link('upper').name = ''
    assert [link.name for link in robot.links] == ['base_link', 'upper', 'finger']


def test_copies_and_removed_elements_rename_only_themselves() -> None:
    robot = _arm()
    clone = copy.deepcopy(robot)
    clone.get_link('finger').name = 'thumb'
    assert clone.get_joint('finger_joint').child == 'thumb'
    assert robot.get_joint('finger_joint').child == 'finger'
    removed = robot.remove_link('finger')[0]
    removed.name = 'loose'
    assert removed.name == 'loose' and not robot.has_link('loose')
    assert Link('a').name == 'a'


def test_a_bug_in_the_writer_keeps_its_traceback(monkeypatch: pytest.MonkeyPatch) -> None:
    """An internal KeyError is not reported as the user's wrong value."""
    robot = _arm()

    def broken(*_args: object) -> str:
        raise KeyError('internal')

    monkeypatch.setattr(urdf_format.UrdfWriter, 'write_robot', broken)
    with pytest.raises(KeyError, match='internal'):
        robot.to_urdf()
    monkeypatch.undo()  # the writer works again: the user's value alone is to blame
    robot.get_link('upper').set_inertial(None)
    robot.get_joint('shoulder').axis = 'up'  # the user's own wrong value: one line
    with pytest.raises(ModelError, match="joint 'shoulder'.*axis = 'up'"):
        robot.to_urdf()
