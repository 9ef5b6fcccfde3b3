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


"""The source text as the record of a read robot, on every fixture, registry and corpus file."""

import difflib
from pathlib import Path

from helpers import CORPUS
import pytest
from registry_robots import robots as registry_robots

from urdfgenpy_ros import ParseError, Robot

FIXTURES = Path(__file__).parent / 'fixtures'
REAL = [*(path for path in sorted(FIXTURES.rglob('*.urdf')) if path.parent.name != 'broken'),
        *registry_robots(), *(sorted(CORPUS.rglob('*.urdf')) if CORPUS.is_dir() else [])]
MENDED = ('P101', 'P102')  # a <robot> wrapped in another element, a malformed declaration


def _read(path: Path) -> Robot:
    try:
        return Robot.from_urdf(path)
    except (ParseError, OSError) as error:
        pytest.skip(f'not a readable URDF: {error}')


def _changed(before: str, after: str) -> tuple[list[str], list[str]]:
    diff = list(difflib.ndiff(before.splitlines(), after.splitlines()))
    return ([line[2:] for line in diff if line.startswith('- ')],
            [line[2:] for line in diff if line.startswith('+ ')])


@pytest.mark.parametrize('path', REAL, ids=[str(path) for path in REAL])
def test_an_unedited_file_is_written_back_byte_for_byte(path: Path, tmp_path: Path) -> None:
    """The file's own bytes are the judge; a file the reader mends is mended, nothing else."""
    robot = _read(path)
    robot.to_urdf(tmp_path / 'out.urdf')
    written = (tmp_path / 'out.urdf').read_bytes()
    if any(warning.code in MENDED for warning in robot.read_warnings):
        from lxml import etree
        source = etree.fromstring(path.read_bytes().split(b'?>', 1)[-1]
                                  if b'<?xml' in path.read_bytes()[:200] else path.read_bytes())
        inner = source if source.tag == 'robot' else source.find('robot')
        assert etree.tostring(etree.fromstring(written), method='c14n', exclusive=True) == \
            etree.tostring(inner, method='c14n', exclusive=True)
        return
    assert written == path.read_bytes().rstrip(b'\0')


@pytest.mark.parametrize('path', REAL, ids=[str(path) for path in REAL])
def test_one_mass_edited_is_one_changed_line(path: Path) -> None:
    """The first link with a mass gets another: that line alone changes in the text."""
    robot = _read(path)
    before = robot.to_urdf()
    link = next((link for link in robot.links if link.inertial is not None), None)
    if link is None:
        pytest.skip('no link has a mass')
    link.inertial.mass = link.inertial.mass + 0.125  # type: ignore[union-attr]
    removed, added = _changed(before, robot.to_urdf())
    assert len(removed) == len(added) == 1, (removed, added)
    assert 'value' in removed[0] and 'value' in added[0]


def test_the_record_is_the_text_read_not_the_file_now(tmp_path: Path) -> None:
    """Writing a read robot does not read its file again: the file may be gone."""
    source = FIXTURES / 'io' / 'two_space.urdf'
    path = tmp_path / 'arm.urdf'
    path.write_bytes(source.read_bytes())
    robot = Robot.from_urdf(path)
    path.unlink()
    assert robot.to_urdf().encode() == source.read_bytes()
    robot.links[0].inertial.mass = 3.5
    removed, added = _changed(source.read_text(), robot.to_urdf())
    assert len(removed) == len(added) == 1 and '3.5' in added[0]


def test_comments_and_instructions_in_a_block_keep_their_text_or_their_edit() -> None:
    """A comment's text is as written (``&amp;`` is no reference there); an edit is written."""
    from lxml import etree
    source = ('<robot name="r">\n  <link name="a"/>\n  <gazebo reference="a">\n'
              '    <!-- a &amp; b -->\n    <?pi x  y?>\n    <p>1</p>\n  </gazebo>\n</robot>\n')
    robot = Robot.from_urdf_string(source)
    block = robot.get_link('a').extensions[0].element
    block[2].text = '2'
    assert _changed(source, robot.to_urdf()) == (['    <p>1</p>'], ['    <p>2</p>'])
    block[0].text = ' c '
    block[1].text = 'z'
    written = etree.fromstring(robot.to_urdf().encode()).find('gazebo')
    assert [written[0].text, written[1].text, written[2].text] == [' c ', 'z', '2']
