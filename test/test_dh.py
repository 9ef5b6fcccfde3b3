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

"""DH tables: skeletons whose forward kinematics equal the DH product, for real arms."""

from __future__ import annotations

import math
from math import pi
from pathlib import Path
import random

from click.testing import CliRunner
from helpers import (
    assert_check_urdf_accepts, load_yourdfpy, require_module, snapshot, xacro_expand)
import pytest

from urdfgenpy_ros import Origin, ParseError, Severity
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.dh import DHConvention, DHRow, DHTable

S, M = DHConvention.STANDARD, DHConvention.MODIFIED

# Published tables (metres, radians).
ARMS = {
    # Universal Robots' own UR5 parameters (standard DH).
    'ur5': DHTable(S, [DHRow(1, 0, pi / 2, 0.089159), DHRow(2, -0.425, 0, 0),
                       DHRow(3, -0.39225, 0, 0), DHRow(4, 0, pi / 2, 0.10915),
                       DHRow(5, 0, -pi / 2, 0.09465), DHRow(6, 0, 0, 0.0823)]),
    # Franka Emika Panda, Craig's convention, with the flange 0.107 m out.
    'panda': DHTable(M, [DHRow(1, 0, 0, 0.333), DHRow(2, 0, -pi / 2, 0),
                         DHRow(3, 0, pi / 2, 0.316), DHRow(4, 0.0825, pi / 2, 0),
                         DHRow(5, -0.0825, -pi / 2, 0.384), DHRow(6, 0, pi / 2, 0),
                         DHRow(7, 0.088, pi / 2, 0)], tool=Origin((0, 0, 0.107))),
    # Puma 560 (Corke's standard table).
    'puma560': DHTable(S, [DHRow(1, 0, pi / 2, 0), DHRow(2, 0.4318, 0, 0),
                           DHRow(3, 0.0203, -pi / 2, 0.15005), DHRow(4, 0, pi / 2, 0.4318),
                           DHRow(5, 0, -pi / 2, 0), DHRow(6, 0, 0, 0)]),
    # Stanford arm: joint 3 is prismatic.
    'stanford': DHTable(S, [DHRow(1, 0, -pi / 2, 0.412), DHRow(2, 0, pi / 2, 0.154),
                            DHRow(3, 0, 0, 0.3, -pi / 2, 'prismatic', lower=0, upper=0.6),
                            DHRow(4, 0, -pi / 2, 0), DHRow(5, 0, pi / 2, 0),
                            DHRow(6, 0, 0, 0.263)],
                        base=Origin((0, 0, 0.1), (0, 0, 0.5)), tool=Origin((0, 0, 0.05))),
    # ABB IRB 140, standard DH, theta offset on joint 2.
    'irb140': DHTable(S, [DHRow(1, 0.07, -pi / 2, 0.352), DHRow(2, 0.36, 0, 0, -pi / 2),
                          DHRow(3, 0, pi / 2, 0), DHRow(4, 0, -pi / 2, 0.38),
                          DHRow(5, 0, pi / 2, 0), DHRow(6, 0, 0, 0.065)]),
    # The seed's UR5 rows, run as written with the MODIFIED convention.
    'ur5_seed': DHTable(M, [DHRow(1, 0.0, pi / 2, 0.089159, 0.0, 'revolute'),
                            DHRow(2, -0.425, 0.0, 0.0, 0.0, 'revolute'),
                            DHRow(3, -0.39225, 0.0, 0.0, 0.0, 'revolute'),
                            DHRow(4, 0.0, pi / 2, 0.10915, 0.0, 'revolute'),
                            DHRow(5, 0.0, -pi / 2, 0.09465, 0.0, 'revolute'),
                            DHRow(6, 0.0, 0.0, 0.0823, 0.0, 'revolute')]),
}


def _configurations(table: DHTable, count: int, seed: int):
    rng = random.Random(seed)
    for _ in range(count):
        yield [rng.uniform(-pi, pi) if row.joint_type == 'revolute'
               else rng.uniform(row.lower or 0.0, row.upper or 1.0) for row in table.rows]


@pytest.mark.parametrize('name', ARMS)
def test_urdf_forward_kinematics_equals_the_dh_product(name: str, tmp_path: Path) -> None:
    table = ARMS[name]
    path = tmp_path / f'{name}.urdf'
    table.to_robot(name).save(path)
    yourdfpy = require_module('yourdfpy')
    numpy = require_module('numpy')
    model = yourdfpy.URDF.load(str(path), load_meshes=False, build_scene_graph=True)
    worst = 0.0
    for q in _configurations(table, 100, seed=len(name)):
        model.update_cfg({row.name: value for row, value in zip(table.rows, q)})
        expected = [*table.link_frames(q), table.flange(q)]
        names = [f'link_{n}' for n in range(1, len(table.rows) + 1)] + ['flange']
        for link, pose in zip(names, expected):
            got = model.get_transform(link, 'base_link')
            worst = max(worst, float(numpy.abs(got - numpy.array(pose)).max()))
    assert worst < 1e-9, worst


@pytest.mark.parametrize('name', ARMS)
def test_skeletons_are_valid_for_check_urdf_validate_and_mujoco(
        name: str, tmp_path: Path) -> None:
    robot = ARMS[name].to_robot(name)
    path = tmp_path / f'{name}.urdf'
    robot.save(path)
    assert_check_urdf_accepts(path)
    assert [str(f) for f in robot.validate() if f.severity is Severity.ERROR] == []
    mujoco = require_module('mujoco')
    model = mujoco.MjModel.from_xml_path(str(path))
    assert model.njnt == len(ARMS[name].rows)


def test_prismatic_row_moves_along_z_and_keeps_theta_fixed() -> None:
    table = ARMS['stanford']
    joint = table.to_robot('s').get_joint('joint_3')
    assert joint.type.value == 'prismatic' and joint.axis == (0.0, 0.0, 1.0)
    near, far = table.frames([0, 0, 0.1, 0, 0, 0])[3], table.frames([0, 0, 0.4, 0, 0, 0])[3]
    moved = [far[i][3] - near[i][3] for i in range(3)]
    axis = table.frames([0, 0, 0.1, 0, 0, 0])[2]  # frame 2's z is joint 3's axis
    assert moved == pytest.approx([0.3 * axis[i][2] for i in range(3)], abs=1e-12)


def test_joint_origins_are_exact_where_the_math_is() -> None:
    robot = ARMS['ur5_seed'].to_robot('ur5')
    joint = robot.get_joint('joint_1')
    assert joint.origin.rpy == (pi / 2, 0.0, 0.0)
    # Craig: Rx(alpha) then Tz(d), so d lies along the turned z: (0, -d, d cos(pi/2) -> 0)
    assert joint.origin.xyz == (0.0, -0.089159, 0.0)
    assert robot.get_joint('joint_2').origin.xyz == (-0.425, 0.0, 0.0)


def test_the_getting_started_calls_write_a_skeleton_xacro_expands_to_the_same_model(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    # The public calls the DH guide walks through, with keyword arguments, in order.
    table = DHTable(convention=DHConvention.MODIFIED, rows=[
        DHRow(1, 0.0, pi / 2, 0.089159, 0.0, 'revolute'),
        DHRow(2, -0.425, 0.0, 0.0, 0.0, 'revolute'),
        DHRow(3, -0.39225, 0.0, 0.0, 0.0, 'revolute'),
    ])
    robot = table.to_robot(name='arm', link_mass=1.0, link_geometry='cylinder')
    monkeypatch.chdir(tmp_path)
    robot.save('arm_skeleton.urdf')
    robot.save('arm_skeleton.xacro')
    robot.print_tree()
    assert 'joint_3 [revolute]' in capsys.readouterr().out
    assert_check_urdf_accepts(tmp_path / 'arm_skeleton.urdf')
    expanded = tmp_path / 'expanded.urdf'
    expanded.write_text(xacro_expand(tmp_path / 'arm_skeleton.xacro'))
    assert snapshot(load_yourdfpy(expanded)) == snapshot(
        load_yourdfpy(tmp_path / 'arm_skeleton.urdf'))
    assert all(link.inertial.mass == 1.0 for link in robot.links if link.inertial)


@pytest.mark.parametrize('suffix', ['.yaml', '.csv'])
@pytest.mark.parametrize('degrees', [False, True])
def test_tables_round_trip_through_files(suffix: str, degrees: bool, tmp_path: Path) -> None:
    table = DHTable(M, list(ARMS['panda'].rows))
    path = tmp_path / f'panda{suffix}'
    table.save(path, degrees=degrees)
    again = DHTable.from_file(path)
    assert again.convention is M
    for mine, theirs in zip(table.rows, again.rows, strict=True):
        for field in ('a', 'alpha', 'd', 'theta_offset'):
            assert getattr(theirs, field) == pytest.approx(getattr(mine, field), abs=1e-15)


def test_degrees_option_reads_textbook_tables(tmp_path: Path) -> None:
    path = tmp_path / 'arm.csv'
    path.write_text('# convention: standard\n# degrees: true\n'
                    'joint,a,alpha,d,theta_offset,type,lower,upper\n'
                    'shoulder,0,90,0.1,0,revolute,-170,170\n'
                    'slide,0,0,0.2,0,prismatic,0,0.5\n')
    table = DHTable.from_file(path)
    assert table.rows[0].alpha == pytest.approx(pi / 2)
    assert table.rows[0].upper == pytest.approx(math.radians(170))
    assert table.rows[1].upper == 0.5  # metres, not converted
    robot = table.to_robot('arm')
    assert [j.name for j in robot.joints] == ['shoulder', 'slide', 'flange_joint']


@pytest.mark.parametrize('text, where, words', [
    ('convention: sideways\nrows: []\n', ':1:1:', "'sideways' is neither"),
    ('convention: modified\nrows:\n  - {joint: 1, a: x}\n', ':3:1:', "a 'x' is not a number"),
    ('convention: modified\nrows:\n  - {joint: 1, b: 0}\n', ':3:1:', 'unknown column(s) b'),
    ('convention: [modified\n', ':2:1:', 'YAML syntax'),
])
def test_bad_tables_give_one_located_line(text: str, where: str, words: str,
                                          tmp_path: Path) -> None:
    path = tmp_path / 'bad.yaml'
    path.write_text(text)
    with pytest.raises(ParseError) as raised:
        DHTable.from_file(path)
    assert str(raised.value).startswith(f'{path}{where}') and words in str(raised.value)


def test_cli_converts_a_table_to_urdf_and_xacro(tmp_path: Path) -> None:
    table = tmp_path / 'puma.yaml'
    ARMS['puma560'].save(table, degrees=True)
    for target in ('puma.urdf', 'puma.urdf.xacro'):
        result = CliRunner().invoke(main, ['convert', str(table), str(tmp_path / target)])
        assert result.exit_code == 0, result.output
    assert_check_urdf_accepts(tmp_path / 'puma.urdf')
    expanded = tmp_path / 'expanded.urdf'
    expanded.write_text(xacro_expand(tmp_path / 'puma.urdf.xacro'))
    assert snapshot(load_yourdfpy(expanded)) == snapshot(load_yourdfpy(tmp_path / 'puma.urdf'))
