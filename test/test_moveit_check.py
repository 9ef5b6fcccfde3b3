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
``urdfgenpy check --srdf``: an SRDF against its robot, findings at the SRDF's lines.

The files are example-robot-data's Panda URDF and SRDF, edited as a user would (a link
renamed in the URDF, a state value out of range, a chain turned round, a colliding pair
added as "Never"); the lines expected are found in the file's text, and the collision
rate is recomputed with pinocchio and coal (test/moveit_oracle.py).
"""

from __future__ import annotations

import json
from pathlib import Path
import re

from click.testing import CliRunner
from helpers import require_module
from lxml import etree
from moveit_oracle import PinocchioWorld, rate, UrdfFacts
import numpy
import pytest
from test_moveit_srdf import _share, _urdf

from urdfgenpy_ros.cli import main
from urdfgenpy_ros.moveit.srdf_check import check_srdf
from urdfgenpy_ros.robot import Robot


def _srdf() -> Path:
    return _share() / 'example-robot-data/robots/panda_description/srdf/panda.srdf'


def _lines_naming(path: Path, name: str) -> list[int]:
    """Return the lines of ``path`` holding ``"name"`` (the file's text, not a parser)."""
    return [number for number, line in enumerate(path.read_text().splitlines(), 1)
            if f'"{name}"' in line]


def _check(urdf: Path, srdf: Path, *options: str) -> tuple[int, str]:
    result = CliRunner().invoke(main, ['check', str(urdf), '--srdf', str(srdf), '-p',
                                       str(_share()), *options])
    return result.exit_code, result.stdout


@pytest.fixture()
def renamed(tmp_path: Path) -> Path:
    """Return a copy of Panda's URDF with panda_link5 renamed, meshes still found."""
    text = _urdf('panda').read_text().replace('"panda_link5"', '"forearm_link"')
    path = tmp_path / 'panda.urdf'
    path.write_text(text)
    return path


def test_a_renamed_link_is_reported_at_each_line_naming_it(renamed: Path) -> None:
    require_module('coal')
    status, out = _check(renamed, _srdf(), '--format', 'json')
    findings = [f for report in json.loads(out)['files'] for f in report['findings']
                if f['code'] == 'K901']
    assert status == 1
    assert sorted(f['line'] for f in findings) == _lines_naming(_srdf(), 'panda_link5')
    assert all(f['file'] == str(_srdf()) for f in findings)
    assert all("'panda_link5'" in f['message'] for f in findings)


@pytest.mark.parametrize('output', ['text', 'sarif', 'junit'])
def test_stale_names_in_every_format(renamed: Path, output: str) -> None:
    require_module('coal')
    status, out = _check(renamed, _srdf(), '--format', output)
    lines = _lines_naming(_srdf(), 'panda_link5')
    assert status == 1
    if output == 'text':
        found = [int(m) for m in re.findall(r'panda\.srdf:(\d+):\d+: error K901', out)]
    elif output == 'sarif':
        results = json.loads(out)['runs'][0]['results']
        found = [r['locations'][0]['physicalLocation']['region']['startLine']
                 for r in results if r['ruleId'] == 'K901']
    else:
        found = [int(m) for m in re.findall(r'K901[^"]*\(line (\d+)\)', out)]
    assert sorted(found) == lines


@pytest.mark.engine  # pinocchio on a real robot
def test_states_chains_and_colliding_never_pairs(tmp_path: Path) -> None:
    require_module('coal')
    text = _srdf().read_text()
    text = text.replace('name="panda_joint4" value="-2.35619"',
                        'name="panda_joint4" value="0.5"')  # above -0.0698
    text = text.replace('</robot>', '    <group name="bent"><chain base_link="panda_link7" '
                        'tip_link="panda_link2"/></group>\n'
                        '    <disable_collisions link1="panda_link1" link2="panda_link6" '
                        'reason="Never"/>\n</robot>')
    srdf = tmp_path / 'panda.srdf'
    srdf.write_text(text)
    robot = Robot.from_urdf(_urdf('panda'))
    findings = check_srdf(robot, srdf, samples=300, seed=5, search_paths=[_share()])
    by_code = {f.code: f for f in findings}
    assert by_code['K903'].location.line == _lines_naming(srdf, 'panda_joint4')[1]
    assert by_code['K902'].location.line == _lines_naming(srdf, 'panda_link7')[-1]
    never = [f for f in findings if f.code == 'K904']
    assert [f.location.line for f in never] == [len(text.splitlines()) - 1]
    # the rate, recomputed by pinocchio on the same 300 states
    require_module('pinocchio')
    facts = UrdfFacts(_urdf('panda'))
    low, high = facts.ranges[:, 0], facts.ranges[:, 1]
    rows = low + numpy.random.default_rng(5).random((300, len(low))) * (high - low)
    world = PinocchioWorld(_urdf('panda'), [str(_share())])
    hits = round(rate(world, facts, rows, ('panda_link1', 'panda_link6')) * 300)
    assert hits and f'collide in {hits} of 300 random states' in never[0].message


def test_the_shipped_panda_srdf_matches_its_urdf() -> None:
    require_module('coal')
    status, out = _check(_urdf('panda'), _srdf())
    assert 'K90' not in out, out


def test_a_virtual_joint_name_is_a_joint_of_the_srdf(tmp_path: Path) -> None:
    root = etree.parse(str(_srdf())).getroot()
    assert root.find('virtual_joint') is None  # this SRDF has none: add one, name it
    text = _srdf().read_text().replace('</robot>', '    <virtual_joint name="world_joint" '
                                       'type="fixed" parent_frame="world" '
                                       'child_link="panda_link0"/>\n    <passive_joint '
                                       'name="world_joint"/>\n</robot>')
    srdf = tmp_path / 'panda.srdf'
    srdf.write_text(text)
    robot = Robot.from_urdf(_urdf('panda'))
    assert check_srdf(robot, srdf, samples=0) == []
