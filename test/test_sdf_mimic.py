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
Mimic joints in SDF 1.11, judged by drake's libsdformat (it reads SDFormat 1.11 and 1.12).

drake's parser refuses an element the SDFormat schema does not know (a misspelt
``<multipler>``) and a ``<mimic>`` whose leader is no joint of the model. The URDF's
mimic factors are read from the file with lxml, not with our reader; Debian's libsdformat
12 (SDFormat 1.9) reads the 1.9 output, which has no mimic.
"""

from __future__ import annotations

import os
from pathlib import Path
import warnings

from click.testing import CliRunner
from helpers import CORPUS, corpus_cases, FIXTURES
from lxml import etree
import pytest
import test_sdf

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main

pytestmark = pytest.mark.engine  # drake and libsdformat

check_sdf = test_sdf.check_sdf  # the session fixture running Debian's libsdformat 12
NO_DRAKE = 'drake not installed: pip install -e ".[sdf-judge]" (PyPI drake, its libsdformat)'


def drake_loads(path: Path) -> list[str]:
    """Load an SDF with drake's parser; return its joints' names (it raises on an error)."""
    try:
        from pydrake.multibody.parsing import Parser
        from pydrake.multibody.plant import MultibodyPlant
    except ImportError:  # an extra of its own: README's set-up leaves it out, CI adds it
        if os.environ.get('URDFGENPY_REQUIRE_DRAKE'):
            pytest.fail(NO_DRAKE)
        pytest.skip(NO_DRAKE)
    plant = MultibodyPlant(0.001)
    Parser(plant).AddModels(str(path))
    return [plant.get_joint(index).name() for index in plant.GetJointIndices()]


def written_mimics(text: str) -> dict[str, tuple[str, float, float, float]]:
    """Return each joint's ``<axis><mimic>``: leader, multiplier, offset, reference."""
    model = etree.fromstring(text.encode()).find('model')
    return {joint.get('name'): (mimic.get('joint'), float(mimic.findtext('multiplier')),
                                float(mimic.findtext('offset')),
                                float(mimic.findtext('reference')))
            for joint in model.findall('joint')
            for mimic in joint.findall('axis/mimic')}


def source_mimics(path: Path) -> dict[str, tuple[str, float, float]]:
    """Return each URDF joint's mimic as the file writes it (leader, multiplier, offset)."""
    root = etree.parse(str(path)).getroot()
    return {joint.get('name'): (mimic.get('joint'), float(mimic.get('multiplier', 1)),
                                float(mimic.get('offset', 0)))
            for joint in root.iter('joint') for mimic in joint.findall('mimic')}


def _write(robot: Robot, path: Path, **options) -> tuple[str, list[str]]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        text = robot.to_sdf(path, **options)
    return text, [str(warning.message) for warning in caught]


def _mimic_files() -> list:
    from registry_robots import robot_id, robots
    fixtures = [path for path in sorted(FIXTURES.rglob('*.urdf')) if '<mimic' in path.read_text()]
    registry = [path for path in robots() if path.suffix == '.urdf'
                and '<mimic' in path.read_text(errors='replace')]
    corpus = [path for path in sorted(CORPUS.rglob('*.urdf'))
              if '<mimic' in path.read_text(errors='replace')] if CORPUS.is_dir() else []
    return [*[pytest.param(path, id=str(path.relative_to(FIXTURES))) for path in fixtures],
            *[pytest.param(path, id=robot_id(path)) for path in registry],
            *corpus_cases(corpus, [str(path.relative_to(CORPUS)) for path in corpus])]


@pytest.mark.parametrize('path', _mimic_files())
def test_mimic_joints_are_sdf_1_11_that_drake_reads(path: Path, tmp_path: Path) -> None:
    from urdfgenpy_ros import ParseError, Severity
    from urdfgenpy_ros.formats import load
    try:
        robot = load(path)
    except ParseError as error:
        pytest.skip(f'not a URDF we read: {error}')
    if any(f.severity is Severity.ERROR for f in robot.validate(check_meshes=False)):
        pytest.skip('validate() refuses it first')
    if any(joint.type.value == 'planar' for joint in robot.joints):
        pytest.skip('SDF has no planar joint')
    sdf = tmp_path / 'robot.sdf'
    text, lines = _write(robot, sdf)
    assert '<sdf version="1.11">' in text
    joints = drake_loads(sdf)  # drake's libsdformat refuses an unknown leader
    written = written_mimics(text)
    source = source_mimics(path)
    assert set(written) | {line.split("'")[1] for line in lines if 'is not written' in line} \
        == set(source)
    for name, (leader, multiplier, offset, reference) in written.items():
        assert leader in joints and name in joints and reference == 0.0
        # follower = m (m' leader + o') + o along the chain, as yourdfpy reads each link
        m, o, at = 1.0, 0.0, name
        while at in source:
            o += m * source[at][2]
            m *= source[at][1]
            at = source[at][0]
        assert (leader, multiplier, offset) == (at, pytest.approx(m), pytest.approx(o))
    assert any('DART' in line and 'Bullet-featherstone' in line for line in lines)


CHAIN = """<?xml version="1.0"?>
<robot name="chain">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01"
    iyz="0" izz="0.01"/></inertial></link>
  {links}
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="base"/><child link="l2"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
    <mimic joint="j1" multiplier="2" offset="0.1"/></joint>
  <joint name="j3" type="prismatic"><parent link="base"/><child link="l3"/><axis xyz="1 0 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
    <mimic joint="j2" multiplier="0.5" offset="0.2"/></joint>
  <joint name="jf" type="fixed"><parent link="base"/><child link="lf"/></joint>
  <joint name="j4" type="revolute"><parent link="lf"/><child link="l4"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/><mimic joint="jf"/></joint>
</robot>
"""
_BODY = ('<inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" '
         'izz="0.01"/></inertial>')


def _chain(tmp_path: Path) -> Path:
    path = tmp_path / 'chain.urdf'
    path.write_text(CHAIN.format(links=''.join(
        f'<link name="{name}">{_BODY}</link>' for name in ('l1', 'l2', 'l3', 'lf', 'l4'))))
    return path


def test_a_chain_of_mimics_and_a_leader_merged_away(tmp_path: Path) -> None:
    robot = Robot.from_urdf(_chain(tmp_path))
    sdf = tmp_path / 'chain.sdf'
    text, lines = _write(robot, sdf, lump_fixed=True)
    assert set(drake_loads(sdf)) >= {'j1', 'j2', 'j3', 'j4'}
    # j3 = 0.5 (2 j1 + 0.1) + 0.2 = j1 + 0.25: it follows j1 itself
    assert written_mimics(text) == {'j2': ('j1', 2.0, 0.1, 0.0), 'j3': ('j1', 1.0, 0.25, 0.0)}
    said = {line.split("'")[1]: line for line in lines if line.startswith('joint')}
    assert set(said) == {'j3', 'j4'}
    assert "'jf' is a fixed joint merged away" in said['j4']
    assert "written as following 'j1'" in said['j3']


def test_drake_refuses_what_is_not_sdf(tmp_path: Path) -> None:
    """The judge can fail: a misspelt element and an unknown leader are refused."""
    robot = Robot.from_urdf(_chain(tmp_path))
    text, _ = _write(robot, tmp_path / 'right.sdf', lump_fixed=True)
    drake_loads(tmp_path / 'right.sdf')  # skips without drake
    for wrong in (text.replace('<multiplier>', '<multipler>').replace(
            '</multiplier>', '</multipler>'), text.replace('joint="j1"', 'joint="j9"')):
        path = tmp_path / 'wrong.sdf'
        path.write_text(wrong)
        with pytest.raises(Exception, match='multipler|j9'):
            drake_loads(path)


def test_sdf_version_1_9_says_mimic_is_dropped(check_sdf, tmp_path: Path) -> None:
    source = _chain(tmp_path)
    result = CliRunner().invoke(main, ['convert', '--sdf-version', '1.9', '--lump-fixed',
                                       str(source), str(tmp_path / 'old.sdf')])
    assert result.exit_code == 0, result.output
    text = (tmp_path / 'old.sdf').read_text()
    assert '<sdf version="1.9">' in text and '<mimic' not in text
    said = [line for line in result.stderr.splitlines() if 'mimic' in line]
    assert len(said) == 1 and 'SDF 1.9 has no mimic joints' in said[0]
    assert '--sdf-version 1.11' in said[0]
    code, _, _, _, errors = check_sdf(tmp_path / 'old.sdf')  # Debian's libsdformat 12
    assert code == 0, errors
    newer = CliRunner().invoke(main, ['convert', '--sdf-version', '1.11', str(source),
                                      str(tmp_path / 'new.sdf')])
    assert newer.exit_code == 0, newer.output
    assert '<sdf version="1.11">' in (tmp_path / 'new.sdf').read_text()
    wrong = CliRunner().invoke(main, ['convert', '--sdf-version', '1.11', str(source),
                                      str(tmp_path / 'x.urdf')])
    assert wrong.exit_code == 2 and '--sdf-version applies to .sdf output only' in wrong.stderr
