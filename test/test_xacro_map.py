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
The source map of a Xacro expansion changes nothing and names the lines the text is on.

The real xacro is the judge of the text (byte for byte); the source files themselves,
read line by line, are the judge of the places: each element's place holds its start tag,
each call site the macro's tag, each include site ``<xacro:include``.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
import re
import shutil
import subprocess
import sys

from click.testing import CliRunner
from helpers import ament_index, CORPUS, corpus_cases, CORPUS_PACKAGES, environment, FIXTURES
from helpers import require_module
from helpers import xacro_expand
from lxml import etree
import pytest
from test_formats_xacro_read import CORPUS_XACROS

from urdfgenpy_ros.cli import main
from urdfgenpy_ros.formats.xacro_read import expand_xacro
from urdfgenpy_ros.resources import PackageResolver

LINES = FIXTURES / 'xacro_lines' / 'robot.urdf.xacro'
SCHEMA = FIXTURES / 'sarif' / 'sarif-schema-2.1.0.json'


def _ids(cases: list) -> list[str]:
    return [f'{Path(n).name}{"".join(f" {k}:={v}" for k, v in m.items())}' for n, m in cases]


def test_the_fixture_expands_byte_for_byte_as_the_xacro_command_does() -> None:
    xacro = Path(sys.executable).with_name('xacro')
    if not xacro.exists():
        pytest.skip('the xacro command is not installed')
    printed = subprocess.run([str(xacro), str(LINES)], capture_output=True, text=True,
                             check=True, timeout=60).stdout
    maps: list = []
    assert expand_xacro(LINES, maps=maps)[0] == printed and maps[0].lines


def _assert_places_hold_their_tags(text: str, source_map) -> None:
    """Read each mapped place's line: it must hold the tag (and calls, includes theirs)."""
    root = etree.fromstring(text.encode())
    elements = {element.sourceline: element for element in root.iter(etree.Element)}
    assert set(source_map.lines) == set(elements)  # every element of the expansion
    for line, origin in source_map.lines.items():
        tag = etree.QName(elements[line]).localname
        row = Path(origin.where.file).read_text().splitlines()[origin.where.line - 1]
        assert re.match(rf'<(xacro:element\b|{re.escape(tag)}[\s/>])',
                        row[origin.where.column - 1:] + ' '), (tag, origin)
        for step in origin.via:
            row = Path(step.file).read_text().splitlines()[step.line - 1]
            assert row[step.column - 1:].startswith(step.path.rstrip('>')), (step, row)


@pytest.mark.parametrize('name, mappings', corpus_cases(CORPUS_XACROS, _ids(CORPUS_XACROS)))
def test_corpus_expansions_are_xacros_and_every_place_holds_the_tag(
        name: str, mappings: dict, tmp_path: Path) -> None:
    maps: list = []
    text, _ = expand_xacro(CORPUS / name, mappings, PackageResolver([CORPUS]), maps=maps)
    with environment(ament_index(tmp_path)):
        plain = xacro_expand(CORPUS / name, mappings)
    for package, folder in CORPUS_PACKAGES.items():  # $(find) answered by the index there
        plain = plain.replace(str(tmp_path / 'share' / package), str(CORPUS / folder))
    assert text == plain
    _assert_places_hold_their_tags(text, maps[0])


def test_fixture_places_hold_their_tags() -> None:
    maps: list = []
    text, _ = expand_xacro(LINES, maps=maps)
    _assert_places_hold_their_tags(text, maps[0])
    assert any(origin.via for origin in maps[0].lines.values())


COMMON = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="m" value="-0.01"/>
  <xacro:property name="h" value="0.1"/>
  <xacro:macro name="box_link" params="name size">
    <link name="${name}">
      <inertial>
        <mass value="${m}"/>
        <inertia ixx="${m*(h*h)/12}" ixy="0" ixz="0"
                 iyy="${m*(h*h)/12}" iyz="0" izz="${size}"/>
      </inertial>
    </link>
  </xacro:macro>
</robot>
"""
TOP = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="common.xacro"/>
  <link name="base_link"/>
  <xacro:box_link name="a" size="-1"/>
  <joint name="j" type="fixed"><parent link="base_link"/><child link="a"/></joint>
</robot>
"""


def _check(tmp_path: Path, *arguments: str) -> dict:
    (tmp_path / 'common.xacro').write_text(COMMON)
    (tmp_path / 'r.urdf.xacro').write_text(TOP)
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        result = CliRunner().invoke(main, ['check', '--no-meshes', *arguments, 'r.urdf.xacro'])
    finally:
        os.chdir(cwd)
    return result


def test_a_value_from_a_property_names_the_expression_and_the_property(
        tmp_path: Path) -> None:
    data = json.loads(_check(tmp_path, '--format', 'json').stdout)
    (mass,) = [f for f in data['files'][0]['findings'] if f['code'] == 'I210']
    lines = COMMON.splitlines()
    assert (mass['file'], mass['line']) == ('common.xacro', 8)
    assert lines[7][mass['column'] - 1:].startswith('value="${m}"')
    assert [(step['file'], step['line'], step['what']) for step in mass['via']] == [
        ('common.xacro', 3, "<xacro:property name='m'>"),
        ('r.urdf.xacro', 5, '<xacro:box_link>')]


def test_sarif_with_macro_calls_validates_and_relates_the_call(tmp_path: Path) -> None:
    jsonschema = require_module('jsonschema')
    log = json.loads(_check(tmp_path, '--format', 'sarif').stdout)
    jsonschema.Draft4Validator(json.loads(SCHEMA.read_text())).validate(log)
    related = [[(place['physicalLocation']['artifactLocation']['uri'],
                 place['physicalLocation']['region']['startLine'])
                for place in result.get('relatedLocations', [])]
               for result in log['runs'][0]['results']]
    assert [('common.xacro', 3), ('r.urdf.xacro', 5)] in related


def test_an_error_in_a_macro_body_is_placed_in_it(tmp_path: Path) -> None:
    (tmp_path / 'common.xacro').write_text(COMMON.replace('<mass value="${m}"/>', '<mass/>'))
    (tmp_path / 'r.urdf.xacro').write_text(TOP)
    from urdfgenpy_ros import ParseError, Robot
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(tmp_path / 'r.urdf.xacro')
    where = raised.value.location
    assert (Path(where.file).name, where.line) == ('common.xacro', 8)
    assert [Path(step.file).name for step in where.via] == ['r.urdf.xacro']
    assert 'via <xacro:box_link>' in str(raised.value)


def test_a_copy_of_the_tree_expands_the_same(tmp_path: Path) -> None:
    """The map reads no file xacro does not: a copied tree maps to the copy's files."""
    copy = tmp_path / 'copy'
    shutil.copytree(LINES.parent, copy)
    maps: list = []
    expand_xacro(copy / LINES.name, maps=maps)
    files = {Path(origin.where.file).resolve().parent for origin in maps[0].lines.values()}
    assert files == {copy.resolve()}


@pytest.mark.parametrize('name', corpus_cases(['husky/husky_description/urdf/husky.urdf.xacro']))
def test_mjcf_losses_of_a_xacro_cite_the_lines_that_hold_the_elements(name: str) -> None:
    from urdfgenpy_ros import Robot
    from urdfgenpy_ros.formats.mjcf import write_mjcf
    robot = Robot.from_xacro(CORPUS / name, {'is_sim': 'true'}, search_paths=[CORPUS])
    findings = write_mjcf(robot, search_paths=[CORPUS]).findings
    assert findings and all(f.location.line is not None for f in findings)
    for finding in findings:
        tag = finding.location.path.rsplit('/', 1)[-1].split('[', 1)[0]
        row = Path(finding.location.file).read_text().splitlines()[finding.location.line - 1]
        assert row[finding.location.column - 1:].startswith(f'<{tag}'), (finding, row)
    assert any(place.path == '<xacro:husky_wheel>' for f in findings for place in f.location.via)


def test_junit_cases_name_the_macro_call(tmp_path: Path) -> None:
    report = _check(tmp_path, '--format', 'junit').stdout
    cases = etree.fromstring(report.encode()).iter('testcase')
    failures = [case.find('failure').text for case in cases if case.find('failure') is not None]
    assert any(text.startswith('common.xacro:8:') and '(via <xacro:property name=' in text
               and '<xacro:box_link> r.urdf.xacro:5:3' in text for text in failures)


@pytest.mark.slow  # starts the viewer's server
def test_the_viewer_names_the_xacro_line_and_the_macro_call(tmp_path: Path) -> None:
    pytest.importorskip('viser')
    from browser import free_port
    from urdfgenpy_ros.formats import load
    from urdfgenpy_ros.viewer.web import RobotViewer
    _check(tmp_path)  # writes the files
    path = tmp_path / 'r.urdf.xacro'
    viewer = RobotViewer(lambda: load(path, {}, ()), port=free_port())
    try:
        (finding,) = [f for f in viewer.findings if f.code == 'I210']
        viewer.select(finding)
        shown = viewer._selection.content
        assert f'`{tmp_path / "common.xacro"}:8:' in shown or '`common.xacro:8:' in shown
        assert '*via* <xacro:box_link>' in shown
    finally:
        viewer.close()
