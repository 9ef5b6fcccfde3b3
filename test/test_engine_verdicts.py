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

import math
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
    # urdfdom drops the inertial; MuJoCo refuses the model (read, kept, reported);
    # libsdformat keeps its mass (test_sdf_massless.py), so no I207 says Gazebo drops it.
    'inertial_without_inertia.urdf': {('P106', 'warning')},
    # urdfdom ignores a visual's own material whose colour is not 4 numbers; MuJoCo
    # refuses the model. No link has mass: libsdformat keeps none (I209).
    'five_number_colour.urdf': {('P107', 'warning'), ('I209', 'warning')},
    # urdfdom drops a visual whose own material has no name; MuJoCo reads it.
    'unnamed_visual_material.urdf': {('P107', 'warning'), ('I209', 'warning')},
    'urdfdom_sensor.urdf': {('I209', 'warning')},
    'moving_sensor_without_inertial.urdf': {('I207', 'warning'), ('I209', 'warning')},
    # A massless wheel whose fixed child carries the mass, and a massless mount carrying a
    # plate: both engines merge the mass in, nothing is dropped.
    'wheel_mass_in_fixed_child.urdf': set(),
    'massless_mount_with_plate.urdf': set(),
    # Merged into its parent or not, MuJoCo refuses a link's impossible tensor.
    'impossible_tensor_on_fixed_link.urdf': {('I203', 'error')},
}

DROPS = ('I201', 'I206', 'I207')  # "Gazebo's URDF conversion drops ..."


@pytest.mark.parametrize('name', sorted(EXPECTED))
def test_findings_match_what_the_engines_do(name: str) -> None:
    path = PROBLEMS / name
    found = Robot.from_urdf(path).validate()
    findings = {(finding.code, str(finding.severity)) for finding in found}
    assert findings == EXPECTED[name]
    errors = {code for code, severity in findings if severity == 'error'}
    urdfdom, mujoco = check_urdf_verdict(path), mujoco_accepts(path)
    if urdfdom and mujoco:
        assert not errors, 'both consumers accept it: an error would be a false alarm'
    if not urdfdom:
        assert errors, 'urdfdom refuses it: validate() must report an error'
    if not mujoco:
        # An error when it also breaks ROS tools; what only a simulator refuses (RViz and
        # robot_state_publisher read it) is a warning that names the simulator.
        said = ' '.join(str(finding) for finding in found)
        assert errors or 'MuJoCo' in said, said


@pytest.fixture(scope='module')
def check_sdf(tmp_path_factory: pytest.TempPathFactory) -> Path:
    from helpers import build_sdf_checker
    return build_sdf_checker(tmp_path_factory.mktemp('check_sdf'))


@pytest.mark.parametrize('name', sorted(EXPECTED))
@pytest.mark.engine
def test_links_said_to_be_dropped_are_the_ones_libsdformat_drops(
        name: str, check_sdf: Path, tmp_path: Path) -> None:
    import subprocess
    from urdfgenpy_ros import Inertial
    from urdfgenpy_ros.reshape.lumping import lumps
    robot = Robot.from_urdf(PROBLEMS / name)
    if len(robot.roots) != 1 or any(note.code == 'P106' for note in robot.read_warnings):
        # No tree; or an <inertial> without <inertia>, which urdfdom drops but libsdformat
        # keeps (with zero moments): the two converters disagree.
        pytest.skip(f'{name}: not one tree, or urdfdom and libsdformat disagree')
    if robot.root.inertial is None:
        # libsdformat leaves out a massless root and, with it, the model; give it a mass
        # so that what happens to the links below shows.
        robot.root.set_inertial(Inertial.from_sphere(1.0, 0.1))
    path = tmp_path / name
    robot.to_urdf(path)
    result = subprocess.run([str(check_sdf), str(path)], capture_output=True, text=True,
                            timeout=60)
    if result.returncode != 0:
        pytest.skip(f'libsdformat refuses {name}: {result.stderr.strip()[:80]}')
    kept = {line.split()[1] for line in result.stdout.splitlines() if line.startswith('link ')}
    lumped = {joint.child for joint in robot.joints if lumps(joint)}
    dropped = {link.name for link in robot.links} - kept - lumped
    said = {finding.element.split("'")[1] for finding in robot.validate()
            if finding.code in DROPS}
    # Every link said to be dropped loses itself or what hangs below it ...
    for link in said:
        assert {link, *(below.name for below in robot.subtree(link))} & dropped, link
    # ... and every dropped link is named, or hangs below one that is.
    for link in dropped:
        assert said & {link, *(joint.parent for joint in robot.chain(link))}, link


@pytest.mark.parametrize('name, tag', [('inertial_without_inertia.urdf', 'inertial'),
                                       ('five_number_colour.urdf', 'material'),
                                       ('unnamed_visual_material.urdf', 'material')])
def test_what_urdfdom_ignores_is_kept_until_replaced(name: str, tag: str) -> None:
    from urdfgenpy_ros import Box, Inertial, Material, Visual
    path = PROBLEMS / name
    robot = Robot.from_urdf(path)
    assert robot.to_urdf() == path.read_text()
    link = robot.links[-1]
    link.add_visual(Visual(Box(0.1, 0.1, 0.1)))  # an unrelated edit keeps it
    assert robot.to_urdf().count(f'<{tag}') == path.read_text().count(f'<{tag}')
    if tag == 'inertial':  # a value given takes its place, once
        link.set_inertial(Inertial.from_sphere(1.0, 0.1))
    else:
        link.visuals[0].material = Material('grey', rgba=(0.5, 0.5, 0.5, 1.0))
    written = robot.to_urdf()
    assert written.count(f'<{tag}') == path.read_text().count(f'<{tag}')
    again = Robot.from_urdf_string(written)
    assert not again.read_warnings
    if tag == 'inertial':
        assert again.links[-1].inertial == link.inertial
    else:
        assert again.links[-1].visuals[0].material.rgba == (0.5, 0.5, 0.5, 1.0)


def test_a_sensor_gazebo_would_drop_is_named() -> None:
    found = Robot.from_urdf(PROBLEMS / 'moving_sensor_without_inertial.urdf').validate()
    (finding,) = [finding for finding in found if finding.code == 'I207']
    assert "its sensor(s) 'cam'" in finding.hint


def test_a_robot_without_links_fails_check(tmp_path: Path) -> None:
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main
    result = CliRunner().invoke(main, ['check', str(PROBLEMS / 'no_links.urdf')])
    assert result.exit_code == 1 and ' error S001 ' in result.stdout


@pytest.mark.parametrize('lump_fixed', [False, True])
def test_sdf_export_refuses_a_dangling_joint_with_the_finding(lump_fixed: bool) -> None:
    from urdfgenpy_ros import ModelError
    robot = Robot.from_urdf(PROBLEMS / 'missing_parent.urdf')
    with pytest.raises(ModelError, match="joint 'shoulder': parent link 'torso' does not "
                                         'exist .*S004'):
        robot.to_sdf(lump_fixed=lump_fixed)


def _every_description() -> list:
    from helpers import CORPUS, corpus_cases
    from registry_robots import robot_id, robots
    own = sorted(path for path in FIXTURES.rglob('*') if path.suffix in ('.urdf', '.xacro'))
    corpus = sorted(path for path in CORPUS.rglob('*')
                    if path.suffix in ('.urdf', '.xacro')) if CORPUS.is_dir() else []
    return [*[pytest.param(path, id=str(path.relative_to(FIXTURES))) for path in own],
            *[pytest.param(path, id=robot_id(path)) for path in robots()],
            *corpus_cases(corpus, [str(path.relative_to(CORPUS)) for path in corpus])]


@pytest.mark.parametrize('path', _every_description())
def test_no_command_ends_in_a_traceback(path: Path, tmp_path: Path) -> None:
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main
    for arguments in (['tree', str(path)], ['check', '--no-meshes', str(path)],
                      ['convert', str(path), str(tmp_path / 'out.urdf')],
                      ['convert', str(path), str(tmp_path / 'out.sdf')]):
        result = CliRunner().invoke(main, arguments)
        if result.exception is not None and not isinstance(result.exception, SystemExit):
            raise result.exception
        assert result.exit_code in (0, 1, 2), result.output


def test_rename_link_follows_urdfdoms_sensor_parent() -> None:
    from lxml import etree
    robot = Robot.from_urdf(PROBLEMS / 'urdfdom_sensor.urdf')
    robot.rename_link('head', 'camera_head')
    root = etree.fromstring(robot.to_urdf().encode())
    assert [parent.get('link') for parent in root.iter('parent')] == [
        'base_link', 'camera_head']


@pytest.mark.parametrize('name', ['tiny_moment.urdf', 'missing_parent.urdf'])
def test_findings_on_a_crlf_file_carry_the_same_lines(name: str, tmp_path: Path) -> None:
    source = PROBLEMS / name
    crlf = tmp_path / name
    crlf.write_bytes(source.read_bytes().replace(b'\n', b'\r\n'))

    def located(path: Path) -> list[tuple[str, int | None, int | None]]:
        return [(finding.code, finding.location.line, finding.location.column)
                for finding in Robot.from_urdf(path).validate()]
    assert located(crlf) == located(source)
    assert all(line is not None for _, line, _ in located(crlf))


_TENSOR_ROBOT = """<robot name="tensor">
  <link name="base_link">
    <inertial><mass value="{root_mass}"/><inertia {root}/></inertial>
  </link>
  <link name="arm">
    <inertial><mass value="{mass}"/><inertia {arm}/></inertial>
  </link>
  <joint name="shoulder" type="{joint}">
    <parent link="base_link"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
</robot>
"""


def _tensor(ixx: float, iyy: float, izz: float, ixy: float = 0.0, iyz: float = 0.0) -> str:
    return (f'ixx="{ixx!r}" ixy="{ixy!r}" ixz="0.0" iyy="{iyy!r}" iyz="{iyz!r}" '
            f'izz="{izz!r}"')


def _turned_disc(degrees: int, a: float = 0.25e-3) -> str:
    """Return a disc's tensor (moments a, a, 2a) turned about x: on the triangle limit."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return _tensor(a, a * c * c + 2 * a * s * s, a * s * s + 2 * a * c * c, iyz=a * c * s)


_EVEN = _tensor(0.01, 0.01, 0.01)
_A = 1e-3  # ixx = iyy = a, izz = 2a, ixy = a - d: eigenvalues d, 2a - d, 2a
# (part, joint, mass, tensor): just above and just below MuJoCo's limits
TENSORS = {
    'cube_1e-14': ('arm', 'revolute', 1e-3, _tensor(1e-14, 1e-14, 1e-14)),
    'cube_0.99e-14': ('arm', 'revolute', 1e-3, _tensor(0.99e-14, 0.99e-14, 0.99e-14)),
    'cube_5e-15': ('arm', 'revolute', 1e-3, _tensor(5e-15, 5e-15, 5e-15)),
    'cube_5e-15_fixed': ('arm', 'fixed', 1e-3, _tensor(5e-15, 5e-15, 5e-15)),
    'cube_5e-15_root': ('root', 'revolute', 1.0, _tensor(5e-15, 5e-15, 5e-15)),
    'needle_1.01e-14': ('arm', 'revolute', 1.0, _tensor(1e-3, 1e-3, 1.01e-14)),
    'needle_0.99e-14': ('arm', 'revolute', 1.0, _tensor(1e-3, 1e-3, 0.99e-14)),
    'turned_1.1e-14': ('arm', 'revolute', 1.0, _tensor(_A, _A, 2 * _A, _A - 1.1e-14)),
    'turned_0.9e-14': ('arm', 'revolute', 1.0, _tensor(_A, _A, 2 * _A, _A - 0.9e-14)),
    # the triangle inequality, as MuJoCo adds the moments (flat plates: ixx + iyy = izz)
    'disc_exact': ('arm', 'revolute', 1.0, _tensor(0.25e-3, 0.25e-3, 0.5e-3)),
    'disc_over': ('arm', 'revolute', 1.0, _tensor(0.25e-3, 0.25e-3, 0.5e-3 * (1 + 1e-15))),
    'plate_rounded_in': ('arm', 'fixed', 1.0, _tensor(
        0.0016333333333333336, 0.0008333333333333335, 0.002466666666666667)),
    'plate_rounded_out': ('arm', 'fixed', 1.0, _tensor(
        0.010208333333333335, 0.0008333333333333335, 0.01104166666666667)),
    # discs turned about x: on the limit, MuJoCo's rounding decides (7: it refuses, 8: not)
    'disc_turned_7': ('arm', 'revolute', 1.0, _turned_disc(7)),
    'disc_turned_8': ('arm', 'revolute', 1.0, _turned_disc(8)),
    'zeros_moving': ('arm', 'revolute', 1.0, _tensor(0.0, 0.0, 0.0)),
    'zeros_fixed': ('arm', 'fixed', 1.0, _tensor(0.0, 0.0, 0.0)),
    'mass_1e-15': ('arm', 'revolute', 1e-15, _EVEN),
    'mass_0.99e-15': ('arm', 'revolute', 0.99e-15, _EVEN),
}


@pytest.mark.parametrize('name', sorted(TENSORS))
def test_inertia_errors_are_exactly_what_mujoco_refuses(name: str, tmp_path: Path) -> None:
    part, joint, mass, tensor = TENSORS[name]
    path = tmp_path / f'{name}.urdf'
    path.write_text(_TENSOR_ROBOT.format(
        root_mass=mass if part == 'root' else 1.0, root=tensor if part == 'root' else _EVEN,
        mass=1.0 if part == 'root' else mass, arm=_EVEN if part == 'root' else tensor,
        joint=joint))
    errors = [finding for finding in Robot.from_urdf(path).validate()
              if finding.code in ('I201', 'I202', 'I203')]
    assert bool(errors) == (not mujoco_accepts(path)), errors
