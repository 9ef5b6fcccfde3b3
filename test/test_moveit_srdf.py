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
The SRDF and its collision matrix, judged by pinocchio, coal and lxml.

The matrix is recomputed independently (test/moveit_oracle.py: pinocchio's URDF reader and
forward kinematics, coal, plain loops) at the same states; pinocchio reads the SRDF we
write (``removeCollisionPairs``, ``loadReferenceConfigurations``); every name in it is
checked against the URDF read with lxml. Robots: example-robot-data's, which ship SRDFs.
"""

from __future__ import annotations

from importlib import metadata
import os
from pathlib import Path
import sys

from helpers import require_module
from lxml import etree
from moveit_oracle import oracle_matrix, rate, UrdfFacts
import pytest
from urdfgenpy_ros import Robot

# robot, URDF under example-robot-data/robots, samples of the slow comparison
ROBOTS = {
    'panda': 'panda_description/urdf/panda.urdf',
    'talos': 'talos_data/robots/talos_reduced.urdf',
    'a1': 'a1_description/urdf/a1.urdf',
    'go1': 'go1_description/urdf/go1.urdf',
    'anymal': 'anymal_b_simple_description/robots/anymal.urdf',
    'b1': 'b1_description/urdf/b1.urdf',
    'romeo': 'romeo_description/urdf/romeo.urdf',
    'baxter': 'baxter_description/urdf/baxter.urdf',
    'pr2': 'pr2_description/urdf/pr2.urdf',
    'xarm7': 'xarm_description/urdf/xarm7.urdf',
}


def _share() -> Path:
    """Return example-robot-data's share folder, or skip when it is not installed."""
    try:
        return Path(str(metadata.distribution('example-robot-data').locate_file(
            'cmeel.prefix/share')))
    except metadata.PackageNotFoundError:
        pytest.skip('example-robot-data is not installed (pip install example-robot-data)')


def _urdf(robot: str) -> Path:
    return _share() / 'example-robot-data' / 'robots' / ROBOTS[robot]


def _compare(robot: str, samples: int) -> None:
    """Assert our matrix equals the independent one (Never: but for rates under 3/N)."""
    require_module('pinocchio')
    require_module('coal')
    path = _urdf(robot)
    ours = Robot.from_urdf(path).to_srdf(samples=samples, seed=7, search_paths=[_share()])
    found = {tuple(sorted((e.get('link1'), e.get('link2')))): e.get('reason')
             for e in etree.fromstring(ours.encode()).iter('disable_collisions')}
    theirs, rows, world = oracle_matrix(path, [str(_share())], samples, seed=7)
    for reason in ('Adjacent', 'Default', 'Always'):
        assert {p for p, r in found.items() if r == reason} == \
            {p for p, r in theirs.items() if r == reason}, reason
    facts = UrdfFacts(path)
    for pair in set(found) ^ set(theirs):  # Never in one only: rare enough to be missed
        assert rate(world, facts, rows, pair) < 3 / samples, pair


@pytest.mark.engine
def test_panda_matrix_equals_pinocchio_recomputation() -> None:
    _compare('panda', 300)


# In CI: a humanoid, a quadruped, a mobile manipulator, another arm. The other five take
# about three minutes more (all ten were compared when this test was written).
EVERY_ROBOT = 'URDFGENPY_SRDF_ALL_ROBOTS'


@pytest.mark.engine
@pytest.mark.parametrize('robot', sorted(set(ROBOTS) - {'panda'}))
def test_matrix_equals_pinocchio_recomputation(robot: str) -> None:
    if robot not in ('talos', 'a1', 'pr2', 'xarm7') and not os.environ.get(EVERY_ROBOT):
        pytest.skip(f'set {EVERY_ROBOT}=1 to compare {robot} too (about 30 s)')
    _compare(robot, 500)


@pytest.fixture(scope='module')
def panda_srdf(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Return a Panda SRDF we wrote (few samples: the names and the form are judged)."""
    require_module('coal')
    path = tmp_path_factory.mktemp('srdf') / 'panda.srdf'
    Robot.from_urdf(_urdf('panda')).to_srdf(path, samples=200, search_paths=[_share()])
    return path


def test_every_name_is_the_urdfs(panda_srdf: Path) -> None:
    urdf = etree.parse(str(_urdf('panda'))).getroot()
    links = {link.get('name') for link in urdf.iter('link') if link.getparent() is urdf}
    joints = {joint.get('name') for joint in urdf.iter('joint') if joint.getparent() is urdf}
    srdf = etree.parse(str(panda_srdf)).getroot()
    named = [(element.tag, attribute, element.get(attribute)) for element in srdf.iter()
             for attribute in ('link1', 'link2', 'base_link', 'tip_link', 'parent_link',
                               'child_link') if element.get(attribute) is not None]
    named += [(e.tag, 'name', e.get('name')) for e in srdf.iter('link')]
    assert named and all(value in links for _, _, value in named), named
    used = [e.get('name') for e in srdf.iter('joint', 'passive_joint')]
    assert used and all(name in joints for name in used)


def test_chain_groups_are_chains(panda_srdf: Path) -> None:
    parent = {joint.find('child').get('link'): joint.find('parent').get('link')
              for joint in etree.parse(str(_urdf('panda'))).getroot().iter('joint')}
    chains = list(etree.parse(str(panda_srdf)).getroot().iter('chain'))
    assert chains
    for chain in chains:
        link = chain.get('tip_link')
        while link != chain.get('base_link'):
            link = parent[link]  # a KeyError: the base is not above the tip


def test_pinocchio_reads_the_srdf(panda_srdf: Path) -> None:
    pinocchio = require_module('pinocchio')
    model, geometry, _ = pinocchio.buildModelsFromUrdf(str(_urdf('panda')), [str(_share())])
    geometry.addAllCollisionPairs()
    link = [model.frames[thing.parentFrame].name for thing in geometry.geometryObjects]
    before = {(pair.first, pair.second) for pair in geometry.collisionPairs}
    pinocchio.removeCollisionPairs(model, geometry, str(panda_srdf))
    after = {(pair.first, pair.second) for pair in geometry.collisionPairs}
    disabled = {frozenset((e.get('link1'), e.get('link2')))
                for e in etree.parse(str(panda_srdf)).getroot().iter('disable_collisions')}
    assert disabled and after < before  # exactly the pairs of objects of disabled links go
    assert before - after == {(a, b) for a, b in before
                              if frozenset((link[a], link[b])) in disabled}
    pinocchio.loadReferenceConfigurations(model, str(panda_srdf))
    home = model.referenceConfigurations['home']
    assert home[model.joints[model.getJointId('panda_joint4')].idx_q] == pytest.approx(
        -1.5708)  # 0 is outside [-3.0718, -0.0698]: mid-range, as MoveIt's default


def test_same_seed_same_matrix_other_seed_same_steps() -> None:
    require_module('coal')
    robot = Robot.from_urdf(_urdf('panda'))
    first = robot.to_srdf(samples=100, seed=3, search_paths=[_share()])
    assert first == robot.to_srdf(samples=100, seed=3, search_paths=[_share()])


def test_srdf_command_writes_and_says_the_default_rates(tmp_path: Path) -> None:
    require_module('coal')
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main
    output = tmp_path / 'panda.srdf'
    result = CliRunner().invoke(main, ['srdf', str(_urdf('panda')), '-o', str(output),
                                       '--samples', '100', '-p', str(_share()),
                                       '--group', 'manipulator=panda_link0:panda_hand'])
    assert result.exit_code == 0, result.output
    groups = {g.get('name'): g for g in etree.parse(str(output)).getroot().iter('group')}
    assert groups['manipulator'].find('chain').get('tip_link') == 'panda_hand'
    defaults = [line for line in result.output.splitlines() if line.startswith('  Default')]
    srdf_defaults = list(etree.parse(str(output)).getroot().iterfind(
        "disable_collisions[@reason='Default']"))
    assert defaults and len(defaults) == len(srdf_defaults)


def test_srdf_command_missing_package_is_one_line(tmp_path: Path) -> None:
    require_module('coal')
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main
    result = CliRunner().invoke(main, ['srdf', str(_urdf('panda')), '-o',
                                       str(tmp_path / 'x.srdf')])
    assert result.exit_code == 2
    assert result.output.strip().splitlines() == [
        "urdfgenpy: link 'panda_link0': collision mesh package 'example-robot-data' of "
        "'package://example-robot-data/robots/panda_description/meshes/collision/link0.stl'"
        ' not found (give the folder holding its package: --package-path, or search_paths'
        ' in Python)']
    assert not (tmp_path / 'x.srdf').exists()


@pytest.mark.parametrize('group', ['manipulator=panda_link0:no_such_link',
                                   'manipulator=panda_lnk0:panda_hand'])
def test_a_group_naming_a_link_the_robot_lacks_is_one_line(group: str, tmp_path: Path) -> None:
    require_module('coal')
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main
    result = CliRunner().invoke(main, ['srdf', str(_urdf('panda')), '-o',
                                       str(tmp_path / 'x.srdf'), '--group', group])
    missing = group.partition('=')[2].split(':')
    missing_link = next(link for link in missing if link not in ('panda_link0', 'panda_hand'))
    assert result.exit_code == 2, result.output
    assert len(result.output.strip().splitlines()) == 1  # no traceback
    assert f"group 'manipulator': robot 'panda' has no link {missing_link!r}" in result.output
    assert not (tmp_path / 'x.srdf').exists()


def test_groups_of_panda_and_wheels_are_not_fingers() -> None:
    from urdfgenpy_ros.moveit.groups import find_groups
    panda = Robot.from_urdf(_urdf('panda'))
    groups, effectors = find_groups(panda)
    urdf = etree.parse(str(_urdf('panda'))).getroot()
    arm = [j.get('name') for j in urdf.iter('joint') if j.get('type') == 'revolute']
    chain = groups[0]
    assert [j.name for j in panda.chain(chain.tip, chain.base)
            if j.type.is_movable] == arm  # the seven arm joints, no finger
    assert effectors[0].parent_link == chain.tip and effectors[0].parent_group == chain.name
    rover = Robot.from_urdf_string(
        '<robot name="rover"><link name="base_link"/><link name="left"/><link name="right"/>'
        '<joint name="l" type="continuous"><parent link="base_link"/><child link="left"/>'
        '<axis xyz="0 1 0"/></joint><joint name="r" type="continuous">'
        '<parent link="base_link"/><child link="right"/><axis xyz="0 1 0"/></joint></robot>')
    assert find_groups(rover) == ([], [])  # two wheels are not a gripper


def test_without_coal_one_line_names_the_extra(tmp_path: Path,
                                               monkeypatch: pytest.MonkeyPatch) -> None:
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main
    monkeypatch.setitem(sys.modules, 'coal', None)  # import coal raises ImportError
    result = CliRunner().invoke(main, ['srdf', str(_urdf('panda')), '-o',
                                       str(tmp_path / 'x.srdf'), '-p', str(_share())])
    assert result.exit_code == 2
    assert result.output.strip().splitlines() == [
        "urdfgenpy: The collision matrix needs the Python package 'coal': "
        "pip install 'urdfgenpy_ros[moveit]'"]
