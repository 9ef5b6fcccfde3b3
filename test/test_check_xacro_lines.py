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
from test_formats_xacro_read import CORPUS_XACROS

from urdfgenpy_ros.cli import main

SOURCE = FIXTURES / 'xacro_lines'
MAIN = SOURCE / 'robot.urdf.xacro'


def _findings(*arguments: str) -> list[dict]:
    result = CliRunner().invoke(main, ['check', '--format', 'json', *(arguments or [str(MAIN)])])
    return json.loads(result.stdout)['files'][0]['findings']


def _element(finding: dict) -> tuple[str, str]:
    kind, name = re.match(r"^/robot/(\w+)\[@name='(.*?)'\]", finding['path']).groups()
    return kind, name


def test_macro_made_names_get_no_line_and_literal_ones_do() -> None:
    cited = {_element(f): (Path(f['file']).name, f['line']) for f in _findings()}
    assert cited == {('joint', 'j'): ('robot.urdf.xacro', 28),
                     ('joint', 'b_joint'): ('robot.urdf.xacro (expanded)', None),
                     ('link', 'base_link'): ('robot.urdf.xacro', 19),
                     ('link', 'a1'): ('robot.urdf.xacro (expanded)', None),
                     ('link', 'tool'): ('robot.urdf.xacro', 17),  # in a macro called once
                     ('link', 'camera'): ('parts.xacro', 4)}  # in an included file


def _probe(finding: dict, file: Path) -> None:
    """Put an attribute into the tag ``finding`` cites in ``file`` (a copy)."""
    lines = file.read_text().splitlines(keepends=True)
    kind, _ = _element(finding)
    row, start = finding['line'] - 1, finding['column'] - 1
    assert lines[row][start:].startswith(f'<{kind}')
    cut = start + 1 + len(kind)
    lines[row] = f'{lines[row][:cut]} urdfgenpy_probe="1"{lines[row][cut:]}'
    if file.is_symlink():
        file.unlink()
    file.write_text(''.join(lines))


def _probed(text: str) -> list[tuple[str, str]]:
    """Return (kind, name) of the elements of an expansion that carry the probe."""
    return [(element.tag, element.get('name')) for element in etree.fromstring(
        text.encode()).iter() if element.get('urdfgenpy_probe')]


@pytest.mark.parametrize('finding', [f for f in _findings() if f['line'] is not None],
                         ids=lambda finding: f"{finding['code']}-{_element(finding)[1]}")
def test_the_cited_tag_is_the_one_xacro_expands_into_the_element(
        finding: dict, tmp_path: Path) -> None:
    copy = tmp_path / 'source'
    shutil.copytree(SOURCE, copy)
    _probe(finding, copy / Path(finding['file']).name)
    assert _probed(xacro_expand(copy / MAIN.name)) == [_element(finding)]


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
    cited = [f for f in _findings(*arguments) if f['line'] is not None
             and not f['file'].endswith(' (expanded)') and f['code'] != 'X101']
    for finding in cited:
        file = Path(finding['file'])
        if not file.is_relative_to(mirror):  # an included file: resolved into the corpus
            file = mirror / file.resolve().relative_to(CORPUS.resolve())
        _probe(finding, file)
        with environment(index):
            assert _probed(xacro_expand(mirror / name, mappings)) == [_element(finding)]
        file.unlink()
        file.symlink_to(CORPUS / file.relative_to(mirror))


def test_text_lines_of_macro_made_elements_name_the_file_without_a_number() -> None:
    result = CliRunner().invoke(main, ['check', str(MAIN)])
    lines = [line for line in result.stdout.splitlines() if "'b_joint'" in line]
    assert lines and all(line.startswith(f'{MAIN} (expanded): warning ') for line in lines)
    assert not re.search(r'\(expanded\):\d', result.stdout)
