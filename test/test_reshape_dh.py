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
DH tables from robots and back: judged by pinocchio and robotics-toolbox.

The URDF's forward kinematics comes from pinocchio, the extracted table's from
robotics-toolbox's own DH robots (where installed) and from pinocchio reading the table's
skeleton; robotics-toolbox's published Panda table is compared row by row.
"""

from __future__ import annotations

import difflib
from importlib import metadata, util
from pathlib import Path
import random

from click.testing import CliRunner
from helpers import assert_check_urdf_accepts, require_module
import pytest

from urdfgenpy_ros import JointMimic, ModelError, Origin, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.dh import DHTable
from urdfgenpy_ros.model.joint import Joint, JointLimit
from urdfgenpy_ros.model.link import Link

CONVENTIONS = ('standard', 'modified')


def example_robot(relative: str) -> Path:
    """Return a file of example-robot-data (PyPI), or skip when it is not installed."""
    try:
        share = metadata.distribution('example-robot-data').locate_file(
            'cmeel.prefix/share/example-robot-data/robots')
    except metadata.PackageNotFoundError:
        pytest.skip('example-robot-data not installed: pip install -e ".[test]"')
    return Path(str(share)) / relative


def _rtb_data(relative: str) -> Path:
    """Return a URDF robotics-toolbox's rtb-data ships, or skip when it is not installed."""
    spec = util.find_spec('rtbdata')
    if spec is None or not spec.submodule_search_locations:
        pytest.skip('rtb-data not installed (pip install rtb-data; too large for the extra)')
    return Path(list(spec.submodule_search_locations)[0]) / 'xacro' / relative


ARMS = {  # file, base, tip
    'panda': (lambda: example_robot('panda_description/urdf/panda.urdf'), 'panda_link0',
              'panda_link8'),
    'ur5': (lambda: example_robot('ur_description/urdf/ur5_robot.urdf'), 'base_link', 'tool0'),
    'puma560': (lambda: _rtb_data('unimation_puma560_description/urdf/puma560_robot.urdf'),
                'link1', 'link7'),
    'irb140': (lambda: _rtb_data('abb_irb140_description/urdf/irb140.urdf'), 'base_link',
               'tool0'),
    'iiwa14': (lambda: _rtb_data('kuka_description/kuka_lbr_iiwa/urdf/lbr_iiwa_14_r820.urdf'),
               'base_link', 'tool0'),
}


def pinocchio_fk(path: Path, base: str, tip: str, names: list[str], configurations):
    """Return the tip's pose in the base frame at each configuration (numpy 4x4)."""
    pin = require_module('pinocchio')
    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()
    slots = [model.joints[model.getJointId(name)].idx_q for name in names]
    poses = []
    for values in configurations:
        q = pin.neutral(model)
        for slot, value in zip(slots, values):
            q[slot] = value
        pin.framesForwardKinematics(model, data, q)
        poses.append((data.oMf[model.getFrameId(base)].inverse()
                      * data.oMf[model.getFrameId(tip)]).homogeneous)
    return poses


def _configurations(count: int, size: int, seed: int = 7) -> list[list[float]]:
    rng = random.Random(seed)
    return [[rng.uniform(-3.0, 3.0) for _ in range(size)] for _ in range(count)]


def _rtb_robot(table: DHTable):
    """Return robotics-toolbox's DHRobot of ``table`` (its own kinematics)."""
    rtb = require_module('roboticstoolbox')
    from spatialmath import SE3
    kind = rtb.RevoluteDH if table.convention.value == 'standard' else rtb.RevoluteMDH
    links = [kind(a=row.a, alpha=row.alpha, d=row.d, offset=row.theta_offset)
             for row in table.rows]

    def pose(origin):
        return SE3(*origin.xyz) * SE3.RPY(*origin.rpy, order='zyx')
    return rtb.DHRobot(links, base=pose(table.base), tool=pose(table.tool))


def _biggest(a, b) -> float:
    return max(float(abs(x - y).max()) for x, y in zip(a, b))


@pytest.mark.slow  # robotics-toolbox alone takes 2-3 s to import
@pytest.mark.parametrize('convention', CONVENTIONS)
@pytest.mark.parametrize('arm', sorted(ARMS))
def test_extracted_table_has_the_urdfs_forward_kinematics(arm: str, convention: str,
                                                          tmp_path: Path) -> None:
    find, base, tip = ARMS[arm]
    path = find()
    table = DHTable.from_robot(Robot.from_urdf(path), base, tip, convention)
    names = [row.name for row in table.rows]
    configurations = _configurations(100, len(names))
    urdf = pinocchio_fk(path, base, tip, names, configurations)
    # the table's skeleton, read by pinocchio, and saved to YAML and read back
    table.save(tmp_path / 'table.yaml')
    skeleton = tmp_path / 'skeleton.urdf'
    DHTable.from_file(tmp_path / 'table.yaml').to_robot(arm).to_urdf(skeleton)
    assert _biggest(urdf, pinocchio_fk(skeleton, 'base_link', 'flange', names,
                                       configurations)) < 1e-9
    assert_check_urdf_accepts(skeleton)
    robot = _rtb_robot(table)
    assert _biggest(urdf, [robot.fkine(q).A for q in configurations]) < 1e-9


@pytest.mark.slow  # robotics-toolbox
def test_panda_modified_table_is_robotics_toolboxs_own() -> None:
    rtb = require_module('roboticstoolbox')
    find, base, tip = ARMS['panda']
    path = find()
    table = DHTable.from_robot(Robot.from_urdf(path), base, tip, 'modified')
    theirs = rtb.models.DH.Panda()
    for row, link in zip(table.rows, theirs.links, strict=True):
        assert (row.a, row.alpha, row.d, row.theta_offset) == pytest.approx(
            (link.a, link.alpha, link.d, link.offset), abs=1e-12)
    # and their frames are the URDF's: their kinematics without the hand is pinocchio's
    from spatialmath import SE3
    theirs.tool = SE3()
    configurations = _configurations(100, 7)
    urdf = pinocchio_fk(path, base, tip, [row.name for row in table.rows], configurations)
    assert _biggest(urdf, [theirs.fkine(q).A for q in configurations]) < 1e-9


def _with_joint(kind: str, **options) -> Robot:
    robot = Robot('odd')
    for name in ('base_link', 'a', 'b'):
        robot.add_link(Link(name))
    robot.add_joint(Joint('j1', 'revolute', 'base_link', 'a', axis=(0, 0, 1),
                          limit=JointLimit(-1, 1)))
    robot.add_joint(Joint('j2', kind, 'a', 'b', **options))
    return robot


@pytest.mark.parametrize('kind, options, message', [
    ('floating', {}, "joint 'j2' is floating: a DH table holds revolute and prismatic"),
    ('planar', {'axis': (0, 0, 1)}, "joint 'j2' is planar"),
    ('revolute', {'axis': (0, 1, 0), 'limit': JointLimit(-1, 1),
                  'mimic': JointMimic('j1')},
     "joint 'j2' mimics 'j1'"),
])
def test_a_chain_dh_cannot_describe_is_refused_naming_the_joint(kind, options, message,
                                                                tmp_path: Path) -> None:
    robot = _with_joint(kind, **options)
    with pytest.raises(ModelError, match=message):
        DHTable.from_robot(robot, 'base_link', 'b')
    robot.to_urdf(tmp_path / 'odd.urdf')
    result = CliRunner().invoke(main, ['dh', str(tmp_path / 'odd.urdf'), '--base', 'base_link',
                                       '--tip', 'b', '-o', str(tmp_path / 't.yaml')])
    assert result.exit_code == 2 and message.split(':')[0] in result.output
    assert 'Traceback' not in result.output and not (tmp_path / 't.yaml').exists()


def test_dh_command_writes_the_table(tmp_path: Path) -> None:
    find, base, tip = ARMS['ur5']
    target = tmp_path / 'ur5.yaml'
    result = CliRunner().invoke(main, ['dh', str(find()), '--base', base, '--tip', tip,
                                       '--convention', 'modified', '-o', str(target)])
    assert result.exit_code == 0, result.output
    table = DHTable.from_file(target)
    assert table.convention.value == 'modified' and len(table.rows) == 6
    configurations = _configurations(10, 6)
    names = [row.name for row in table.rows]
    skeleton = tmp_path / 's.urdf'
    table.to_robot('ur5').to_urdf(skeleton)
    assert _biggest(pinocchio_fk(find(), base, tip, names, configurations),
                    pinocchio_fk(skeleton, 'base_link', 'flange', names, configurations)) < 1e-9


@pytest.mark.parametrize('convention', CONVENTIONS)
@pytest.mark.parametrize('arm', ['panda', 'ur5'])
def test_apply_dh_changes_one_line_per_chain_joint_and_gives_the_tables_kinematics(
        arm: str, convention: str, tmp_path: Path) -> None:
    find, base, tip = ARMS[arm]
    path = find()
    original = path.read_text()
    robot = Robot.from_urdf(path)
    table = DHTable.from_robot(robot, base, tip, convention)
    assert robot.apply_dh(table, base, tip) == []  # its own table changes nothing
    assert robot.to_urdf() == original
    for row in table.rows:
        row.a += 1e-3
        row.alpha += 1e-3
        row.d += 1e-3
        row.theta_offset += 1e-3
    changed = robot.apply_dh(table, base, tip)
    chain = [joint.name for joint in robot.chain(tip, base)]
    # every movable joint; the fixed joint into the tip when the table's flange moved it
    movable = [joint.name for joint in robot.chain(tip, base) if joint.is_movable]
    assert set(movable) <= set(changed) <= set(chain)
    written = tmp_path / 'calibrated.urdf'
    robot.to_urdf(written)
    diff = list(difflib.unified_diff(original.splitlines(), written.read_text().splitlines(),
                                     lineterm='', n=0))
    removed = [line for line in diff if line.startswith('-') and not line.startswith('---')]
    added = [line for line in diff if line.startswith('+') and not line.startswith('+++')]
    assert len(removed) == len(added) == len(changed)
    assert all('<origin' in line for line in removed + added)
    lines = original.splitlines()
    for joint in changed:  # each changed line is inside that joint's element
        start = next(i for i, line in enumerate(lines) if f'<joint name="{joint}"' in line)
        end = next(i for i in range(start, len(lines)) if '</joint>' in lines[i])
        assert sum(1 for i in range(start, end) if lines[i] != written.read_text()
                   .splitlines()[i]) == 1, joint
    names = [row.name for row in table.rows]
    configurations = _configurations(100, len(names))
    flange = [table.flange(q) for q in configurations]
    import numpy
    assert _biggest(pinocchio_fk(written, base, tip, names, configurations),
                    [numpy.array(pose) for pose in flange]) < 1e-9


@pytest.mark.parametrize('convention', CONVENTIONS)
@pytest.mark.parametrize('arm', ['ur5', 'panda', 'puma560', 'stanford', 'irb140'])
def test_published_tables_come_back_from_their_skeletons(arm: str, convention: str,
                                                         tmp_path: Path) -> None:
    from test_dh import ARMS as PUBLISHED
    source = tmp_path / 'source.urdf'
    PUBLISHED[arm].to_robot(arm).to_urdf(source)  # the Stanford arm's joint 3 slides
    table = DHTable.from_robot(Robot.from_urdf(source), 'base_link', 'flange', convention)
    assert [row.joint_type for row in table.rows] == [
        row.joint_type for row in PUBLISHED[arm].rows]
    names = [row.name for row in table.rows]
    configurations = _configurations(100, len(names))
    again = tmp_path / 'again.urdf'
    table.to_robot(arm).to_urdf(again)
    assert _biggest(pinocchio_fk(source, 'base_link', 'flange', names, configurations),
                    pinocchio_fk(again, 'base_link', 'flange', names, configurations)) < 1e-9


def test_apply_dh_refuses_a_tool_it_cannot_place_and_a_table_of_another_chain() -> None:
    from test_dh import ARMS as PUBLISHED
    robot = PUBLISHED['ur5'].to_robot('ur5')
    table = DHTable.from_robot(robot, 'base_link', 'link_6')
    table.tool = Origin((0.0, 0.0, 0.1))  # nothing can move link_6 off its joint's frame
    with pytest.raises(ModelError, match="tip 'link_6' is the link of joint 'joint_6'"):
        robot.apply_dh(table, 'base_link', 'link_6')
    short = DHTable.from_robot(robot, 'base_link', 'link_3')
    with pytest.raises(ModelError, match='the table has 3 rows, the chain from'):
        robot.apply_dh(short, 'base_link', 'flange')


def test_unknown_links_are_one_line_with_a_suggestion(tmp_path: Path) -> None:
    from test_dh import ARMS as PUBLISHED
    source = tmp_path / 'ur5.urdf'
    PUBLISHED['ur5'].to_robot('ur5').to_urdf(source)
    for options, message in (
            (['--base', 'base_lnk', '--tip', 'flange'],
             "DH chain base: robot 'ur5' has no link 'base_lnk' (did you mean 'base_link'?)"),
            (['--base', 'link_3', '--tip', 'link_1'], "link 'link_1' is not below 'link_3'")):
        result = CliRunner().invoke(main, ['dh', str(source), *options, '-o',
                                           str(tmp_path / 't.yaml')])
        assert result.exit_code == 2 and message in result.output
        assert 'Traceback' not in result.output


def test_apply_dh_keeps_quaternion_origins_quaternions(tmp_path: Path) -> None:
    import numpy
    from test_dh import ARMS as PUBLISHED
    base, tip = 'base_link', 'flange'
    robot = PUBLISHED['panda'].to_robot('panda')
    for joint in robot.joints:
        joint.origin = joint.origin.as_quaternion()
    source = tmp_path / 'panda_quat.urdf'
    robot.to_urdf(source)  # URDF 1.1: every origin a quat_xyzw
    assert source.read_text().count('quat_xyzw=') == len(robot.joints)
    robot = Robot.from_urdf(source)
    table = DHTable.from_robot(robot, base, tip, 'modified')
    for row in table.rows:
        row.d += 1e-3
    changed = robot.apply_dh(table, base, tip)
    written = tmp_path / 'calibrated.urdf'
    robot.to_urdf(written)
    new_lines = set(written.read_text().splitlines()) - set(source.read_text().splitlines())
    assert len(new_lines) == len(changed)
    assert all('quat_xyzw=' in line and 'rpy' not in line for line in new_lines)
    names = [row.name for row in table.rows]
    configurations = _configurations(20, len(names))
    assert _biggest(pinocchio_fk(written, base, tip, names, configurations),
                    [numpy.array(table.flange(q)) for q in configurations]) < 1e-9
