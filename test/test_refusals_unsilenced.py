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
What a target refuses is refused whatever silences the finding in a review.

A suppression comment (``urdfgenpy: ignore I202``) and ``--ignore`` silence a finding in
``check``; MuJoCo still refuses the file, and so ``write_mjcf``, ``convert`` to MJCF and
``convert`` to SDF (libsdformat refuses the same tensor) refuse it and write nothing.
MuJoCo's own URDF import judges the file.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from click.testing import CliRunner
from helpers import require_module
import pytest

from urdfgenpy_ros import Inertial, Joint, Link, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.formats.mjcf import MjcfRefusedError, write_mjcf

COMMENT = '<!-- urdfgenpy: ignore I202 -->'


def _silenced(tmp_path: Path) -> Path:
    """Write an arm whose moving link has a tensor MuJoCo refuses, its I202 silenced."""
    robot = Robot('arm').add_link(Link('base_link'))
    robot.add_link(Link('upper', inertial=Inertial(1.0, ixx=0.01, iyy=-0.01, izz=0.01)))
    robot.add_joint(Joint('shoulder', 'continuous', 'base_link', 'upper', axis=(0, 0, 1)))
    text = robot.to_urdf()
    assert text.count('<link name="upper"') == 1
    path = tmp_path / 'arm.urdf'
    path.write_text(text.replace('<link name="upper"', f'{COMMENT}\n  <link name="upper"'))
    return path


def _run(*words: object) -> Any:
    return CliRunner().invoke(main, [str(word) for word in words])


@pytest.mark.parametrize('silencer', ['comment', '--ignore'])
def test_a_silenced_refusal_is_still_refused(tmp_path: Path, silencer: str) -> None:
    mujoco = require_module('mujoco')
    path = _silenced(tmp_path)
    plain = tmp_path / 'plain.urdf'
    plain.write_text(path.read_text().replace(COMMENT, ''))
    assert 'I202' in _run('check', plain).stdout  # what the silencer silences
    if silencer == '--ignore':
        path = plain
    with pytest.raises(ValueError):  # MuJoCo refuses the file, whatever the comment says
        mujoco.MjModel.from_xml_path(str(path))
    checked = _run('check', path, *(['--ignore', 'I202'] if silencer == '--ignore' else []))
    assert 'I202' not in checked.stdout, checked.output  # silenced for the review
    with pytest.raises(MjcfRefusedError) as refused:
        write_mjcf(Robot.from_urdf(path))
    assert [finding.code for finding in refused.value.findings] == ['I202']
    for target in (tmp_path / 'arm.xml', tmp_path / 'arm.sdf'):
        converted = _run('convert', path, target)
        assert converted.exit_code == 2 and 'I202' in converted.stderr, converted.output
        assert 'not written' in converted.stderr and not target.exists()
