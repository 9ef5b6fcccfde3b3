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
validate() judges small robots the way the engines do, one problem per fixture.

Each fixture is something real robots contain; the engines' verdicts are taken from the
engines themselves in the test (check_urdf, MuJoCo), never written down.
"""

from __future__ import annotations

from pathlib import Path

from helpers import check_urdf_verdict, FIXTURES, require_module
import pytest

from urdfgenpy_ros import Robot

PROBLEMS = FIXTURES / 'problems'


def mujoco_accepts(path: Path) -> bool:
    """Return whether MuJoCo compiles the URDF (meshes are not involved here)."""
    mujoco = require_module('mujoco')
    try:
        mujoco.MjModel.from_xml_path(str(path))
    except ValueError:
        return False
    return True


# fixture: the findings validate() gives, as (code, severity)
EXPECTED = {
    # A point mass on a fixed joint: both engines merge it into its parent.
    'marker_on_fixed_joint.urdf': {('I208', 'warning')},
    # A massless link between moving ones: MuJoCo merges it, Gazebo's converter drops it
    # with everything below it (the finger).
    'massless_adapter.urdf': {('I206', 'warning')},
    # A joint's missing parent: the cause only, not an echo about loops or roots.
    'missing_parent.urdf': {('S004', 'error'), ('C401', 'warning')},
    'zero_sphere_with_inertial.urdf': {('R304', 'error')},
    'tiny_moment.urdf': {('I202', 'error')},
    'barely_impossible_disc.urdf': {('I203', 'error')},
    'no_links.urdf': {('S001', 'error')},
}


@pytest.mark.parametrize('name', sorted(EXPECTED))
def test_findings_match_what_the_engines_do(name: str) -> None:
    path = PROBLEMS / name
    findings = {(finding.code, str(finding.severity))
                for finding in Robot.from_urdf(path).validate()}
    assert findings == EXPECTED[name]
    errors = {code for code, severity in findings if severity == 'error'}
    if check_urdf_verdict(path) and mujoco_accepts(path):
        assert not errors, 'both consumers accept it: an error would be a false alarm'
    if not mujoco_accepts(path) and name != 'no_links.urdf':
        assert errors, 'MuJoCo refuses it: validate() must say why'


def test_a_robot_without_links_fails_check(tmp_path: Path) -> None:
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main
    result = CliRunner().invoke(main, ['check', str(PROBLEMS / 'no_links.urdf')])
    assert result.exit_code == 1 and ' error S001 ' in result.stdout
