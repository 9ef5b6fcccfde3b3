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
The MJCF export's prepare step and its source reads, judged by MuJoCo and a marked fixture.

MuJoCo's own URDF import says which inertias it refuses; ``prepare`` must refuse the
same, and ``write_mjcf`` raise it before writing. The losses of a robot as read come
from its file without writing it as URDF; the marked fixture judges their lines.
"""

from __future__ import annotations

from pathlib import Path

from helpers import FIXTURES, require_module
import mjcf_judge
import pytest

from urdfgenpy_ros import Inertial, Joint, Link, Robot
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.formats.mjcf import MjcfRefusedError, prepare, write_mjcf
from urdfgenpy_ros.formats.mjcf import write_prepared
import urdfgenpy_ros.formats.urdf
from urdfgenpy_ros.model.errors import ModelError

EVERYTHING = FIXTURES / 'mjcf' / 'everything.urdf'

INERTIAS = {  # (ixx, iyy, izz) of the moving link: what MuJoCo's URDF import makes of it
    'good': (0.01, 0.01, 0.01),
    'not positive-definite': (0.01, -0.01, 0.01),
    'triangle broken': (0.01, 0.01, 0.05),
}


def _arm(ixx: float, iyy: float, izz: float, mass: float = 1.0) -> Robot:
    robot = Robot('arm').add_link(Link('base_link'))
    robot.add_link(Link('upper', inertial=Inertial(mass, ixx=ixx, iyy=iyy, izz=izz)))
    robot.add_joint(Joint('shoulder', 'continuous', 'base_link', 'upper', axis=(0, 0, 1)))
    return robot


@pytest.mark.parametrize('case', [*INERTIAS, 'massless'])
def test_prepare_refuses_what_mujoco_refuses(case: str) -> None:
    mujoco = require_module('mujoco')
    robot = _arm(*INERTIAS.get(case, INERTIAS['good']), mass=0.0 if case == 'massless'
                 else 1.0)
    try:
        mujoco.MjModel.from_xml_string(robot.to_urdf())
        accepted = True
    except ValueError:
        accepted = False
    review = prepare(robot, {})
    assert bool(review.refused) is not accepted
    assert review.findings == review.refused.get('mujoco', [])
    if accepted:
        assert write_prepared(robot, review).text == write_mjcf(robot).text
        return
    with pytest.raises(MjcfRefusedError) as refused:
        write_mjcf(robot)
    with pytest.raises(MjcfRefusedError):
        write_prepared(robot, review)
    assert [finding.code for finding in refused.value.findings] == \
        [finding.code for finding in review.refused['mujoco']]


@pytest.mark.parametrize('options', [{'base': 'wobbly'}, {'actuators': 'muscle'},
                                     {'kp': -1}, {'kv': 'stiff'}])
def test_a_bad_option_is_refused_before_anything_is_written(
        options: dict, tmp_path: Path) -> None:
    robot = _arm(*INERTIAS['good'])
    with pytest.raises(ModelError) as said:
        prepare(robot, options)
    with pytest.raises(ModelError) as raised:
        write_mjcf(robot, tmp_path / 'robot.xml', **options)
    assert str(raised.value) == str(said.value)
    assert not any(tmp_path.iterdir())


def test_two_trees_are_refused_as_not_one_tree() -> None:
    robot = _arm(*INERTIAS['good']).add_link(Link('loose'))
    review = prepare(robot, {'fuse_fixed': True})
    assert [finding.code for finding in review.refused['mujoco']] == ['S002']
    with pytest.raises(ModelError, match='2 root links: MJCF needs one tree'):
        write_mjcf(robot)


def test_a_robot_as_read_is_not_written_as_urdf_to_find_its_losses(
        monkeypatch: pytest.MonkeyPatch) -> None:
    require_module('mujoco')  # checks the <mujoco> block's attributes (M808)
    robot = load(EVERYTHING)

    def refuse(*_: object, **__: object) -> str:
        raise AssertionError('the MJCF writer wrote the URDF')

    monkeypatch.setattr(urdfgenpy_ros.formats.urdf, 'write_urdf', refuse)
    result = write_mjcf(robot)
    assert {(finding.location.line, finding.code) for finding in result.findings} == \
        mjcf_judge.marked_losses(EVERYTHING)
    assert 'timestep="0.001"' in result.text  # the <mujoco> block, read from the model


def test_an_edited_robot_keeps_the_losses_on_their_lines() -> None:
    require_module('mujoco')
    robot = load(EVERYTHING)
    edited = next(link.inertial for link in robot.links if link.inertial is not None)
    edited.mass *= 2  # the same lines, written anew from the model
    result = write_mjcf(robot)
    assert {(finding.location.line, finding.code) for finding in result.findings} == \
        mjcf_judge.marked_losses(EVERYTHING)
