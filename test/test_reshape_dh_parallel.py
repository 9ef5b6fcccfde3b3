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
Nearly parallel axes (a URDF's 1.5708 and -3.1416 for pi/2 and pi) give a usable DH table.

Kinova's Gen3 lite writes them so: its joints 2 and 3 are 7.3e-6 rad from parallel, and
their common normal lies 19 km away; the table had d = -38 km and a tip 38 km off. Such
axes are taken as parallel, with a warning giving what it costs; axes further apart keep an
exact table. Judged by yourdfpy's forward kinematics of the source and of the table's URDF.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
import random
import warnings

from helpers import require_module
import pytest

from urdfgenpy_ros import Joint, JointLimit, Link, Origin, Robot
from urdfgenpy_ros.dh import DHTable


def _arm(tilt: float) -> Robot:
    """Return a three-joint arm whose joints 2 and 3 are ``2 tilt`` from parallel."""
    robot = Robot('arm')
    for name in ('base_link', 'shoulder', 'upper', 'fore', 'tip'):
        robot.add_link(Link(name))
    limit = JointLimit(-2.5, 2.5, effort=1.0, velocity=1.0)
    robot.add_joint(Joint('j1', 'revolute', 'base_link', 'shoulder', axis=(0, 0, 1),
                          origin=Origin((0, 0, 0.1)), limit=limit))
    robot.add_joint(Joint('j2', 'revolute', 'shoulder', 'upper', axis=(0, 0, 1),
                          origin=Origin((0, 0, 0.1), (math.pi / 2 + tilt, 0, 0)), limit=limit))
    robot.add_joint(Joint('j3', 'revolute', 'upper', 'fore', axis=(0, 0, 1),
                          origin=Origin((0, 0.28, 0), (-math.pi - 2 * tilt, 0, 0)),
                          limit=limit))
    return robot.add_joint(Joint('tip_joint', 'fixed', 'fore', 'tip',
                                 origin=Origin((0.1, 0.05, 0.02))))


def _worst(source: Path, table: DHTable, base: str, tip: str, tmp_path: Path
           ) -> tuple[float, float]:
    """Return yourdfpy's largest tip distance and matrix entry between source and table."""
    yourdfpy = require_module('yourdfpy')
    numpy = require_module('numpy')
    table.to_robot('table').to_urdf(tmp_path / 'table.urdf')
    theirs = yourdfpy.URDF.load(str(source), load_meshes=False)
    mine = yourdfpy.URDF.load(str(tmp_path / 'table.urdf'), load_meshes=False)
    rng = random.Random(4)
    distance = entry = 0.0
    for _ in range(30):
        q = {row.name: rng.uniform(-2.5, 2.5) for row in table.rows}
        theirs.update_cfg(q)
        mine.update_cfg(q)
        gap = theirs.get_transform(tip, base) - mine.get_transform('flange', 'base_link')
        distance = max(distance, float(numpy.linalg.norm(gap[:3, 3])))
        entry = max(entry, float(numpy.abs(gap).max()))
    return distance, entry


@pytest.mark.parametrize('convention', ['standard', 'modified'])
@pytest.mark.parametrize('tilt', [7.3e-6, 8e-4, 1e-9])
def test_nearly_parallel_axes_give_a_table_of_the_arms_size(tilt: float, convention: str,
                                                            tmp_path: Path) -> None:
    robot = _arm(tilt)
    robot.to_urdf(tmp_path / 'arm.urdf')
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        table = DHTable.from_robot(robot, 'base_link', 'tip', convention)
    assert all(abs(row.a) < 1.0 and abs(row.d) < 1.0 for row in table.rows)  # -19 km before
    assert max(abs(value) for value in (*table.tool.xyz, *table.base.xyz)) < 1.0
    distance, entry = _worst(tmp_path / 'arm.urdf', table, 'base_link', 'tip', tmp_path)
    assert distance < 2.0 * tilt * 0.5 + 1e-12  # the tilt over the arm's reach (< 0.5 m)
    lines = [str(item.message) for item in caught]
    if entry > 1e-9:  # what the table costs is said, in one line
        (line,) = lines
        assert line.startswith("dh: the axes of joints 'j2' and 'j3' (")
        assert 'rad) are taken as parallel' in line and '\n' not in line
    else:
        assert lines == []


@pytest.mark.parametrize('convention', ['standard', 'modified'])
def test_axes_further_apart_keep_an_exact_table(convention: str, tmp_path: Path) -> None:
    robot = _arm(0.01)
    robot.to_urdf(tmp_path / 'arm.urdf')
    with warnings.catch_warnings():
        warnings.simplefilter('error')
        table = DHTable.from_robot(robot, 'base_link', 'tip', convention)
    assert _worst(tmp_path / 'arm.urdf', table, 'base_link', 'tip', tmp_path)[1] < 1e-9


def test_kinovas_gen3_lite_table_is_the_arms(tmp_path: Path) -> None:
    corpus = os.environ.get('URDFGENPY_CORPUS')
    if not corpus:
        pytest.skip('URDFGENPY_CORPUS not set (the third-party robots)')
    source = Path(corpus) / 'kortex/kortex_description/robots/gen3_lite.urdf'
    with pytest.warns(UserWarning, match="joints 'joint_2' and 'joint_3'"):
        table = DHTable.from_robot(Robot.from_urdf(source), 'base_link', 'tool_frame')
    assert all(abs(row.a) < 1.0 and abs(row.d) < 1.0 for row in table.rows)
    assert _worst(source, table, 'base_link', 'tool_frame', tmp_path)[0] < 2e-5
