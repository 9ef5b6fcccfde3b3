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

"""A DH table in CSV without the limit columns converts (issue 28 item 18, a regression)."""

from __future__ import annotations

from pathlib import Path
import random

from click.testing import CliRunner
from helpers import load_yourdfpy, require_module
import pytest

from urdfgenpy_ros.cli import main
from urdfgenpy_ros.dh import DHTable

TABLE = """# convention: standard
# degrees: true
joint,a,alpha,d,type
1,0,90,0.3,revolute
2,0.4,0,0,revolute
3,0,0,0.1,prismatic
"""


def test_a_csv_without_limit_columns_converts_with_the_tables_kinematics(
        tmp_path: Path) -> None:
    numpy = require_module('numpy')
    table_file = tmp_path / 'arm.csv'
    table_file.write_text(TABLE)
    result = CliRunner().invoke(main, ['convert', str(table_file), str(tmp_path / 'arm.urdf')])
    assert result.exit_code == 0, result.output
    table = DHTable.from_file(table_file)
    assert [row.lower for row in table.rows] == [None] * 3
    yourdfpy = require_module('yourdfpy')
    model = yourdfpy.URDF.load(str(tmp_path / 'arm.urdf'), load_meshes=False)
    assert load_yourdfpy(tmp_path / 'arm.urdf').name == 'arm'
    rng = random.Random(28)
    for _ in range(5):
        q = [rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(0, 0.1)]
        model.update_cfg(dict(zip(model.actuated_joint_names, q)))
        want = numpy.array(table.link_frames(q)[-1])
        got = model.get_transform(f'link_{len(q)}', model.base_link)
        assert got == pytest.approx(want, abs=1e-9)
