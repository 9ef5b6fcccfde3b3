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

"""Reading Xacro: the corpus xacros, expanded with their arguments, round-trip losslessly."""

from __future__ import annotations

from pathlib import Path

from helpers import (
    ament_index, canonical, check_urdf, CORPUS, CORPUS_PACKAGES, environment, load_yourdfpy,
    require_module, snapshot)
import pytest

from urdfgenpy_ros import ParseError, Robot

# file, xacro arguments (as the corpus README gives them)
XACROS = [
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


@pytest.fixture(scope='module')
def real_xacro(tmp_path_factory: pytest.TempPathFactory):
    """Expand with plain xacro, $(find) answered by a real ament index of the corpus."""
    xacro = require_module('xacro')
    prefix = tmp_path_factory.mktemp('ament')
    index = ament_index(prefix)

    def expand(path: Path, mappings: dict[str, str]) -> str:
        with environment(index):
            text = xacro.process_file(str(path), mappings=dict(mappings)).toprettyxml()
            # Paths xacro writes in point into the index; ours into the corpus itself.
            for package, folder in CORPUS_PACKAGES.items():
                text = text.replace(str(prefix / 'share' / package), str(CORPUS / folder))
        return text
    return expand


@pytest.mark.parametrize('name, mappings', XACROS,
                         ids=[f'{n}{"".join(f" {k}:={v}" for k, v in m.items())}'
                              for n, m in XACROS])
def test_corpus_xacro_round_trips(name: str, mappings: dict[str, str], real_xacro,
                                  tmp_path: Path) -> None:
    path = CORPUS / name
    expected = tmp_path / 'expected.urdf'
    expected.write_text(real_xacro(path, mappings))
    robot = Robot.from_xacro(path, mappings, search_paths=[CORPUS])
    written = tmp_path / 'written.urdf'
    robot.to_urdf(written)
    assert canonical(written.read_bytes()) == canonical(expected.read_bytes())
    assert check_urdf(written).returncode == 0
    assert snapshot(load_yourdfpy(written)) == snapshot(load_yourdfpy(expected))
    assert str(path.resolve()) in robot.included_files


def test_included_files_are_listed() -> None:
    robot = Robot.from_xacro(CORPUS / 'ur_description/urdf/ur.urdf.xacro',
                             {'name': 'ur', 'ur_type': 'ur5e'}, search_paths=[CORPUS])
    names = {Path(file).name for file in robot.included_files}
    assert {'ur.urdf.xacro', 'ur_macro.xacro', 'ur_common.xacro'} <= names


@pytest.mark.parametrize('name, mappings, words', [
    ('ur_description/urdf/ur.urdf.xacro', {}, ['Undefined substitution argument name']),
    ('ur_description/urdf/ur.urdf.xacro', {'name': 'ur'}, ['ur5x', 'No such file']),
    ('kortex/kortex_description/robots/gen3_lite_gen3_lite_2f.xacro', {},
     ['Invalid parameter "gripper"']),
])
def test_broken_xacros_give_one_line(name: str, mappings: dict[str, str],
                                     words: list[str]) -> None:
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(CORPUS / name, mappings, search_paths=[CORPUS])
    message = str(raised.value)
    assert message.startswith(f'{CORPUS / name}: error X001 xacro: ')
    assert '\n' not in message
    for word in words:
        assert word in message
