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

"""Reading Xacro: real xacros, expanded with their arguments, equal what xacro itself gives."""

from __future__ import annotations

from pathlib import Path

from helpers import (
    ament_index, canonical, check_urdf, CORPUS, corpus_cases, corpus_file, CORPUS_PACKAGES,
    environment, FIXTURE_PACKAGES, FIXTURES, load_yourdfpy, require_module, snapshot)
import pytest
from registry_robots import robot as registry_robot

from urdfgenpy_ros import ParseError, Robot

ARM = FIXTURES / 'packages/fixture_description/urdf/arm.urdf.xacro'

# file, xacro arguments: our own, then robots installed from PyPI
OWN_XACROS = [
    (ARM, {}),
    (ARM, {'dof': '5'}),
    (ARM, {'dof': '2', 'gripper': 'true'}),
]
REGISTRY_XACROS = [('cookie.xacro', {})]

# file in the corpus, xacro arguments (as the corpus README gives them)
CORPUS_XACROS = [
    ('urdf_tutorial/urdf/08-macroed.urdf.xacro', {}),
    ('robot_state_publisher/urdf/test-desc.urdf.xacro', {}),
    ('turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf', {}),
    ('turtlebot3/turtlebot3_description/urdf/turtlebot3_waffle.urdf',
     {'namespace': 'tb3_0/'}),
    *[('ur_description/urdf/ur.urdf.xacro', {'name': 'ur', 'ur_type': kind})
      for kind in ('ur3', 'ur3e', 'ur5e', 'ur10', 'ur10e', 'ur16e', 'ur20', 'ur30')],
    ('ur_description/urdf/ur_mocked.urdf.xacro', {'name': 'ur', 'ur_type': 'ur5e'}),
    ('ur_description/urdf/ur.urdf.xacro',
     {'name': 'ur', 'ur_type': 'ur5e', 'tf_prefix': 'left_', 'safety_limits': 'true'}),
    ('husky/husky_description/urdf/husky.urdf.xacro', {}),
    ('husky/husky_description/urdf/husky.urdf.xacro', {'is_sim': 'true'}),
    ('kortex/kortex_description/robots/gen3.xacro', {'dof': '7'}),
    ('kortex/kortex_description/robots/gen3.xacro', {'dof': '6'}),
    ('kortex/kortex_description/robots/gen3.xacro',
     {'dof': '7', 'vision': 'true', 'prefix': 'arm_'}),
    ('kortex/kortex_description/robots/gen3.xacro', {'dof': '7', 'sim_gazebo': 'true'}),
    ('kortex/kortex_description/robots/kinova.urdf.xacro',
     {'name': 'kinova', 'arm': 'gen3', 'dof': '7'}),
]


def _ids(cases: list) -> list[str]:
    return [f'{Path(n).name}{"".join(f" {k}:={v}" for k, v in m.items())}' for n, m in cases]


@pytest.fixture(scope='module')
def real_xacro(tmp_path_factory: pytest.TempPathFactory):
    """Expand with plain xacro, $(find) answered by a real ament index of the packages."""
    xacro = require_module('xacro')
    prefix = tmp_path_factory.mktemp('ament')
    packages = dict(FIXTURE_PACKAGES)
    if CORPUS.is_dir():
        packages.update({name: CORPUS / folder for name, folder in CORPUS_PACKAGES.items()})
    index = ament_index(prefix, packages)

    def expand(path: Path, mappings: dict[str, str]) -> str:
        with environment(index):
            text = xacro.process_file(str(path), mappings=dict(mappings)).toprettyxml()
            # Paths xacro writes in point into the index; ours into the packages themselves.
            for package, folder in packages.items():
                text = text.replace(str(prefix / 'share' / package), str(folder))
        return text
    return expand


def _assert_same_as_xacro(path: Path, mappings: dict[str, str], search_paths: list[Path],
                          real_xacro, tmp_path: Path) -> Robot:
    expected = tmp_path / 'expected.urdf'
    expected.write_text(real_xacro(path, mappings))
    robot = Robot.from_xacro(path, mappings, search_paths=search_paths)
    written = tmp_path / 'written.urdf'
    robot.to_urdf(written)
    assert canonical(written.read_bytes()) == canonical(expected.read_bytes())
    assert check_urdf(written).returncode == 0
    assert snapshot(load_yourdfpy(written)) == snapshot(load_yourdfpy(expected))
    assert str(path.resolve()) in robot.included_files
    return robot


@pytest.mark.parametrize('path, mappings', OWN_XACROS, ids=_ids(OWN_XACROS))
def test_own_xacro_round_trips(path: Path, mappings: dict[str, str], real_xacro,
                               tmp_path: Path) -> None:
    robot = _assert_same_as_xacro(path, mappings, [FIXTURES / 'packages'], real_xacro,
                                  tmp_path)
    assert len(robot.joints) == int(mappings.get('dof', 3)) + ('gripper' in mappings)


@pytest.mark.parametrize('name, mappings', REGISTRY_XACROS, ids=_ids(REGISTRY_XACROS))
def test_registry_xacro_round_trips(name: str, mappings: dict[str, str], real_xacro,
                                    tmp_path: Path) -> None:
    _assert_same_as_xacro(registry_robot(name), mappings, [], real_xacro, tmp_path)


@pytest.mark.parametrize('name, mappings', corpus_cases(CORPUS_XACROS, _ids(CORPUS_XACROS)))
def test_corpus_xacro_round_trips(name: str, mappings: dict[str, str], real_xacro,
                                  tmp_path: Path) -> None:
    _assert_same_as_xacro(corpus_file(name), mappings, [CORPUS], real_xacro, tmp_path)


def test_included_files_are_listed() -> None:
    robot = Robot.from_xacro(ARM, {'dof': '2'}, search_paths=[FIXTURES / 'packages'])
    assert {'arm.urdf.xacro', 'arm_parts.xacro'} <= {
        Path(file).name for file in robot.included_files}


def test_included_files_of_a_corpus_robot_are_listed() -> None:
    robot = Robot.from_xacro(corpus_file('ur_description/urdf/ur.urdf.xacro'),
                             {'name': 'ur', 'ur_type': 'ur5e'}, search_paths=[CORPUS])
    names = {Path(file).name for file in robot.included_files}
    assert {'ur.urdf.xacro', 'ur_macro.xacro', 'ur_common.xacro'} <= names


@pytest.mark.parametrize('mappings, words', [
    ({'dof': 'three'}, ["'index < count'"]),
    ({'gripper': 'perhaps'}, ['perhaps']),
])
def test_broken_own_xacros_give_one_line(mappings: dict[str, str], words: list[str]) -> None:
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(ARM, mappings, search_paths=[FIXTURES / 'packages'])
    message = str(raised.value)
    assert message.startswith(f'{ARM}: error X001 xacro: ')
    assert '\n' not in message
    for word in words:
        assert word in message


def test_a_missing_package_gives_one_line() -> None:
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(ARM, {}, search_paths=[])
    assert 'fixture_description' in str(raised.value) and '\n' not in str(raised.value)


MACRO_WITH = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="typo">
  <xacro:macro name="leg" {attributes}><link name="${{side}}_leg"/></xacro:macro>
  <xacro:leg side="left"/>
</robot>
"""


def test_what_xacro_prints_while_failing_ends_the_one_line(tmp_path: Path, capfd) -> None:
    path = tmp_path / 'typo.urdf.xacro'
    path.write_text(MACRO_WITH.format(attributes='p0arams="side"'))
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(path)
    assert str(raised.value) == (f'{path}: error X001 xacro: Invalid parameter "side" (when '
                                 f'instantiating macro leg ({path})) (xacro warned: '
                                 'xacro:macro: unknown attribute(s): p0arams)')
    assert capfd.readouterr().err == ''


def test_xacro_warnings_become_read_warnings_not_stderr(tmp_path: Path, capfd) -> None:
    path = tmp_path / 'odd.urdf.xacro'
    path.write_text(MACRO_WITH.format(attributes='params="side" colour="red"'))
    robot = Robot.from_xacro(path)
    assert capfd.readouterr().err == ''
    assert [(w.code, w.message) for w in robot.read_warnings] == [
        ('X102', 'xacro: xacro:macro: unknown attribute(s): colour')]
    assert [link.name for link in robot.links] == ['left_leg']


BROKEN_CORPUS_XACROS = [
    ('ur_description/urdf/ur.urdf.xacro', {}, ['Undefined substitution argument name']),
    ('ur_description/urdf/ur.urdf.xacro', {'name': 'ur'}, ['ur5x', 'No such file']),
    ('kortex/kortex_description/robots/gen3_lite_gen3_lite_2f.xacro', {},
     ['Invalid parameter "gripper"']),
]


@pytest.mark.parametrize('name, mappings, words', corpus_cases(
    BROKEN_CORPUS_XACROS, [case[0] for case in BROKEN_CORPUS_XACROS]))
def test_broken_corpus_xacros_give_one_line(name: str, mappings: dict[str, str],
                                            words: list[str]) -> None:
    path = corpus_file(name)
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(path, mappings, search_paths=[CORPUS])
    message = str(raised.value)
    assert message.startswith(f'{path}: error X001 xacro: ')
    assert '\n' not in message
    for word in words:
        assert word in message


def test_a_missing_xacro_file_is_said_once(tmp_path: Path) -> None:
    """The message names the missing file; the OSError xacro appends is not repeated."""
    missing = tmp_path / 'absent.urdf.xacro'
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(missing)
    message = str(raised.value)
    assert message.count(str(missing)) == 2  # where, and what is missing
    assert message.count('No such file') == 1


def test_a_file_of_macros_read_as_a_robot_says_so(tmp_path: Path) -> None:
    """A macro library (ROS-Industrial's ``*_macro.xacro``) is not a robot: say which to read."""
    library = tmp_path / 'arm_macro.xacro'
    library.write_text('<?xml version="1.0"?>\n<robot xmlns:xacro="http://ros.org/wiki/xacro">\n'
                       '  <xacro:macro name="arm" params="prefix">\n'
                       '    <link name="${prefix}base"/>\n  </xacro:macro>\n</robot>\n')
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(library)
    assert str(raised.value) == (
        f'{library}: error X003 defines macros (arm) and no robot: read a robot file that '
        'includes it and calls <xacro:arm .../>')
    named = tmp_path / 'fr3.xacro'  # franka_description's: a robot name, still no robot
    named.write_text(library.read_text().replace('<robot ', '<robot name="fr3" '))
    with pytest.raises(ParseError, match='X003 defines macros .arm. and no robot'):
        Robot.from_xacro(named)


def test_an_error_inside_a_macro_names_the_macros_as_xacro_does(tmp_path: Path) -> None:
    """X001 keeps xacro's context: which macro, called from which, in which file."""
    (tmp_path / 'lib.xacro').write_text(
        '<robot xmlns:xacro="http://ros.org/wiki/xacro">\n'
        '  <xacro:macro name="inner" params="a"><link name="${b}"/></xacro:macro>\n'
        '  <xacro:macro name="outer" params=""><xacro:inner a="1"/></xacro:macro>\n'
        '</robot>\n')
    top = tmp_path / 'top.urdf.xacro'
    top.write_text('<robot name="r" xmlns:xacro="http://ros.org/wiki/xacro">\n'
                   '  <xacro:include filename="lib.xacro"/>\n  <xacro:outer/>\n</robot>\n')
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(top)
    message = str(raised.value)
    assert message.startswith(f'{top}: error X001 xacro: name ') and '\n' not in message
    assert message.endswith(f"(when instantiating macro inner ({tmp_path / 'lib.xacro'}), "
                            f"from outer ({tmp_path / 'lib.xacro'}))")
