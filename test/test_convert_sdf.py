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

"""``urdfgenpy convert`` to SDF: what libsdformat would refuse is named, not written."""

from __future__ import annotations

from importlib import metadata
from pathlib import Path
import re
import subprocess

from click.testing import CliRunner
from helpers import build_sdf_checker
import pytest

from urdfgenpy_ros import Inertial, Joint, JointType, Link, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.formats.sdf_inertia import sdformat_refuses

pytestmark = pytest.mark.engine  # libsdformat's checker

FIXTURE = Path(__file__).parent / 'fixtures' / 'sdf' / 'refused_inertia.urdf'


@pytest.fixture(scope='session')
def sdformat_refused(tmp_path_factory: pytest.TempPathFactory):
    """Return a function: SDF file -> (exit code, links libsdformat says have bad inertia)."""
    binary = build_sdf_checker(tmp_path_factory.mktemp('checker'))

    def run(path: Path) -> tuple[int, set[str]]:
        result = subprocess.run([str(binary), str(path)], capture_output=True, text=True,
                                timeout=120)
        return result.returncode, set(re.findall(
            r'A link named (\S+) has invalid inertia', result.stderr))
    return run


def _named(stderr: str) -> set[str]:
    """Return the links the per-link lines of ``convert`` name."""
    return set(re.findall(r"error I20[23] link '([^']+)'", stderr))


@pytest.mark.parametrize('tensor', [
    (1.0, 0.01, 0.0, 0.0, 0.02, 0.0, 0.03),   # fine
    (1.0, 0.0, 0.0, 0.0, 0.01, 0.0, 0.01),    # a zero moment: MuJoCo refuses, SDFormat not
    (1.0, 1e-20, 0.0, 0.0, 1.0, 0.0, 1.0),
    (1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),      # a point mass
    (1.0, 1.0, 0.0, 0.0, 1.0, 0.0, 3.0),      # triangle inequality broken
    (1.0, -1e-3, 0.0, 0.0, 1.0, 0.0, 1.0),    # a negative moment
    (1.0, 1e-3, 1e-3, 1e-3, 1e-3, 1e-3, 1e-3),  # rank one
    (1.0, 2.0, 0.0, 0.0, 1.0, 0.0, 1.0 + 1e-15),  # triangle inequality within rounding
])
def test_sdformat_refuses_exactly_what_libsdformat_refuses(
        tensor: tuple[float, ...], sdformat_refused, tmp_path: Path) -> None:
    robot = Robot('one')
    robot.add_link(Link('base', inertial=Inertial(1.0, 0.01, 0.0, 0.0, 0.01, 0.0, 0.01)))
    robot.add_link(Link('body', inertial=Inertial(*tensor)))
    robot.add_joint(Joint('hinge', JointType.CONTINUOUS, 'base', 'body', axis=(0, 0, 1)))
    sdf = tmp_path / 'one.sdf'
    robot.to_sdf(sdf)
    _, refused = sdformat_refused(sdf)
    assert ('body' in refused) == sdformat_refuses(robot.get_link('body').inertial)


def test_convert_names_each_link_libsdformat_refuses_and_writes_nothing(
        sdformat_refused, tmp_path: Path) -> None:
    target = tmp_path / 'robot.sdf'
    result = CliRunner().invoke(main, ['convert', str(FIXTURE), str(target)])
    assert result.exit_code == 2 and not target.exists()
    Robot.from_urdf(FIXTURE).to_sdf(tmp_path / 'direct.sdf')
    code, refused = sdformat_refused(tmp_path / 'direct.sdf')
    assert code == 1 and refused == {'camera', 'flap'}  # 'rod' has a zero moment: accepted
    lines = result.stderr.splitlines()
    assert _named(result.stderr) == refused and len(lines) == len(refused) + 1
    assert all(line.startswith(f'{FIXTURE}:') and '--lump-fixed' in line
               for line in lines[:-1])
    assert lines[-1].startswith('urdfgenpy: ') and lines[-1].endswith('pass --lump-fixed')
    lumped = CliRunner().invoke(main, ['convert', str(FIXTURE), str(target), '--lump-fixed'])
    assert lumped.exit_code == 0, lumped.output
    assert sdformat_refused(target) == (0, set())


def test_convert_says_so_when_lumping_cannot_help(sdformat_refused, tmp_path: Path) -> None:
    source = tmp_path / 'moving.urdf'
    source.write_text(FIXTURE.read_text().replace(
        '<joint name="camera_joint" type="fixed">',
        '<joint name="camera_joint" type="continuous"><axis xyz="0 0 1"/>'))
    target = tmp_path / 'moving.sdf'
    result = CliRunner().invoke(main, ['convert', str(source), str(target), '--lump-fixed'])
    assert result.exit_code == 2 and not target.exists()
    Robot.from_urdf(source).to_sdf(tmp_path / 'direct.sdf', lump_fixed=True)
    _, refused = sdformat_refused(tmp_path / 'direct.sdf')
    assert _named(result.stderr) == refused == {'camera'}
    assert 'pass --fix (a tensor from its shape)' in result.stderr
    assert result.stderr.splitlines()[-1].endswith('fix them and convert again')


def test_a_refused_link_the_validator_passes_over_is_named_too(
        sdformat_refused, tmp_path: Path) -> None:
    # A massless link that a lumped child gives mass: the validator does not judge its tensor.
    source = tmp_path / 'massless.urdf'
    source.write_text(FIXTURE.read_text().replace('<mass value="0.5"/>', '<mass value="0"/>')
                      .replace('ixx="0" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"',
                               'ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.01"'))
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'out.sdf')])
    assert result.exit_code == 2
    Robot.from_urdf(source).to_sdf(tmp_path / 'direct.sdf')
    _, refused = sdformat_refused(tmp_path / 'direct.sdf')
    assert _named(result.stderr) == refused == {'camera', 'rod', 'flap'}
    assert f"{source}:22:1: error I203 link 'rod': principal moments 0.001, 0.001, 0.01 " \
        'break the triangle inequality' in result.stderr


def test_anymal_converts_only_with_lump_fixed(sdformat_refused, tmp_path: Path) -> None:
    try:
        robots = metadata.distribution('example-robot-data').locate_file(
            'cmeel.prefix/share/example-robot-data/robots')
    except metadata.PackageNotFoundError:
        pytest.skip('example-robot-data is not installed (pip install example-robot-data)')
    source = Path(str(robots)) / 'anymal_c_simple_description/urdf/anymal.urdf'
    target = tmp_path / 'anymal.sdf'
    result = CliRunner().invoke(main, ['convert', str(source), str(target)])
    assert result.exit_code == 2 and not target.exists()
    Robot.from_urdf(source).to_sdf(tmp_path / 'direct.sdf')
    _, refused = sdformat_refused(tmp_path / 'direct.sdf')
    assert len(refused) == 5 and _named(result.stderr) == refused
    lumped = CliRunner().invoke(main, ['convert', str(source), str(target), '--lump-fixed'])
    assert lumped.exit_code == 0, lumped.output
    assert sdformat_refused(target) == (0, set())


def test_lump_fixed_is_for_sdf_and_help_names_every_format(tmp_path: Path) -> None:
    result = CliRunner().invoke(main, ['convert', str(FIXTURE), str(tmp_path / 'x.urdf'),
                                       '--lump-fixed'])
    assert result.exit_code == 2
    assert '--lump-fixed applies to .sdf output only' in result.stderr
    assert not (tmp_path / 'x.urdf').exists()
    text = ' '.join(CliRunner().invoke(main, ['convert', '--help']).output.split())
    assert 'TARGET is .urdf, .xacro or .sdf' in text and 'DH table (.yaml, .yml, .csv)' in text
