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

"""check's SARIF (validated against the OASIS schema) and JUnit (read by junitparser)."""

from __future__ import annotations

import json
import os
from pathlib import Path

from click.testing import CliRunner
from helpers import FIXTURES, require_module
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.model.codes import CODES
from validation_fixtures import broken, defect_line, VALID

SCHEMA = FIXTURES / 'sarif' / 'sarif-schema-2.1.0.json'
SUPPRESSED = broken('J102').replace('  <joint name="shoulder"', '  <!-- urdfgenpy: ignore '
                                    'J106 -->\n  <joint name="shoulder"').replace(
    'effort="10" velocity="1"/>', 'effort="10" velocity="0"/>')


@pytest.fixture()
def files(tmp_path: Path) -> dict[str, Path]:
    """Write a clean file, one with an error, one with a warning and a suppressed one."""
    texts = {'clean.urdf': VALID, 'error.urdf': broken('J104'),
             'suppressed.urdf': SUPPRESSED, 'unreadable.urdf': VALID.replace('</robot>', '')}
    paths = {}
    for name, text in texts.items():
        paths[name] = tmp_path / 'robots' / name
        paths[name].parent.mkdir(exist_ok=True)
        paths[name].write_text(text)
    return paths


def _run(tmp_path: Path, *arguments: str):
    cwd = os.getcwd()
    os.chdir(tmp_path)  # SARIF paths are relative to the working directory
    try:
        return CliRunner().invoke(main, ['check', *arguments])
    finally:
        os.chdir(cwd)


def test_sarif_validates_against_the_sarif_2_1_0_schema(files, tmp_path: Path) -> None:
    jsonschema = require_module('jsonschema')
    schema = json.loads(SCHEMA.read_text())
    result = _run(tmp_path, '--format', 'sarif', *map(str, files.values()))
    assert result.exit_code == 2  # the unreadable file; the report is written all the same
    log = json.loads(result.stdout)
    jsonschema.Draft4Validator.check_schema(schema)
    jsonschema.Draft4Validator(schema).validate(log)
    # and a broken log does not validate: the check can fail
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.Draft4Validator(schema).validate({**log, 'version': '2.0'})
    run, = log['runs']
    rules = {rule['id']: rule for rule in run['tool']['driver']['rules']}
    assert set(rules) == {'J104', 'J102', 'J106'}
    assert rules['J104']['defaultConfiguration']['level'] == 'error'
    assert rules['J104']['shortDescription']['text'] == CODES['J104'][1]
    error = Robot.from_urdf(files['error.urdf']).validate()[0]
    assert rules['J104']['help']['text'] == error.hint
    # GitHub code scanning requires a full description (Microsoft's sarif-multitool
    # `validate --rule-kind Gh`: GH2012), and a name equal to the id is a warning (SARIF1001)
    assert all(rule['fullDescription']['text'] and rule.get('name', '') != rule['id']
               for rule in rules.values())
    by_rule = {result['ruleId']: result for result in run['results']}
    location = by_rule['J104']['locations'][0]
    physical = location['physicalLocation']
    assert physical['artifactLocation'] == {'uri': 'robots/error.urdf',
                                            'uriBaseId': '%SRCROOT%'}
    assert physical['region'] == {'startLine': defect_line(broken('J104')),
                                  'startColumn': error.location.column}
    assert location['logicalLocations'][0]['fullyQualifiedName'] == error.location.path
    assert by_rule['J106']['suppressions'] == [{'kind': 'inSource'}]
    assert 'suppressions' not in by_rule['J102']
    assert len(run['results']) == 3
    (notice,) = run['invocations'][0]['toolExecutionNotifications']
    assert 'unreadable.urdf' in notice['message']['text']
    assert run['invocations'][0]['executionSuccessful'] is False


def test_sarif_to_a_file_and_ignore_is_an_external_suppression(files, tmp_path: Path) -> None:
    report = tmp_path / 'check.sarif'
    result = _run(tmp_path, '--format', 'sarif', '-o', str(report), '--ignore', 'J104',
                  str(files['error.urdf']))
    assert result.exit_code == 0 and result.stdout == ''
    (finding,) = json.loads(report.read_text())['runs'][0]['results']
    assert finding['suppressions'] == [{'kind': 'external'}] and finding['level'] == 'error'


@pytest.mark.parametrize('macro', [False, True])
def test_sarif_of_a_xacro_cites_the_source_line_and_the_macro_call(
        macro: bool, tmp_path: Path) -> None:
    text = broken('J104').replace('<robot name="fixture">', '<robot name="fixture" '
                                  'xmlns:xacro="http://www.ros.org/wiki/xacro">')
    if macro:  # the joint is made by a macro: its limit's line in the macro, and the call
        text = text.replace('<joint name="wrist"', '<xacro:macro name="m" params="n">\n'
                            '  <joint name="${n}"').replace('</robot>', '')
        end = text.rindex('</joint>') + len('</joint>')
        text = text[:end] + '\n</xacro:macro>\n<xacro:m n="wrist"/>\n</robot>\n'
    path = tmp_path / 'arm.urdf.xacro'
    path.write_text(text)
    log = json.loads(_run(tmp_path, '--format', 'sarif', str(path)).stdout)
    jsonschema = require_module('jsonschema')
    jsonschema.Draft4Validator(json.loads(SCHEMA.read_text())).validate(log)
    (result,) = log['runs'][0]['results']
    physical = result['locations'][0]['physicalLocation']
    assert physical['artifactLocation']['uri'] == 'arm.urdf.xacro'
    lines = text.splitlines()
    opening = next(number for number, row in enumerate(lines)
                   if '<joint name="wrist"' in row or '<joint name="${n}"' in row)
    line = next(number for number in range(opening, len(lines))
                if '<limit' in lines[number]) + 1
    assert lines[line - 1][physical['region']['startColumn'] - 1:].startswith('<limit')
    assert physical['region']['startLine'] == line
    related = result.get('relatedLocations', [])
    if macro:
        call = lines.index('<xacro:m n="wrist"/>') + 1
        assert [place['physicalLocation']['region'] for place in related] == [
            {'startLine': call, 'startColumn': 1}]
        assert related[0]['message']['text'] == '<xacro:m>'
        assert '[<xacro:m>](1)' in result['message']['text']
    else:
        assert related == []
    assert 'line 1 stands for the file' not in result['message']['text']


def test_junit_parses_with_junitparser(files, tmp_path: Path) -> None:
    junitparser = require_module('junitparser')
    report = tmp_path / 'check.xml'
    result = _run(tmp_path, '--format', 'junit', '-o', str(report), *map(str, files.values()))
    assert result.exit_code == 2
    xml = junitparser.JUnitXml.fromfile(str(report))
    suites = {Path(suite.name).name: suite for suite in xml}
    assert set(suites) == set(files)
    assert (xml.tests, xml.failures, xml.errors, xml.skipped) == (5, 1, 1, 1)

    def outcome(case) -> list[str]:
        return [type(item).__name__ for item in case.result]
    clean, = suites['clean.urdf']
    assert clean.is_passed and clean.name == 'no findings'
    error, = suites['error.urdf']
    assert outcome(error) == ['Failure'] and error.result[0].type == 'error'
    assert 'J104' in error.name and f'line {defect_line(broken("J104"))}' in error.name
    cases = {case.name.split()[0]: case for case in suites['suppressed.urdf']}
    assert cases['J102'].is_passed and 'warning J102' in cases['J102'].system_out
    assert outcome(cases['J106']) == ['Skipped']
    unreadable, = suites['unreadable.urdf']
    assert outcome(unreadable) == ['Error']
    strict = tmp_path / 'strict.xml'
    _run(tmp_path, '--format', 'junit', '-o', str(strict), '--strict',
         str(files['suppressed.urdf']))
    xml = junitparser.JUnitXml.fromfile(str(strict))
    assert (xml.tests, xml.failures, xml.skipped) == (2, 1, 1)


def test_json_counts_suppressed_and_fixed(files, tmp_path: Path) -> None:
    result = _run(tmp_path, '--format', 'json', '--fix', str(files['suppressed.urdf']))
    report = json.loads(result.stdout)
    assert (report['warnings'], report['suppressed'], report['fixed']) == (0, 1, 1)
    entry, = report['files']
    assert entry['suppressed'][0]['suppression'] == 'inSource'
    assert entry['fixed'][0]['code'] == 'J102'


def test_pre_commit_hooks_run_check(tmp_path: Path) -> None:
    import re
    import shlex
    yaml = require_module('yaml')
    hooks = {hook['id']: hook for hook in yaml.safe_load(
        (Path(__file__).parents[1] / '.pre-commit-hooks.yaml').read_text())}
    assert set(hooks) == {'urdfgenpy-check', 'urdfgenpy-fix'}
    assert re.search(hooks['urdfgenpy-check']['files'], 'urdf/arm.urdf.xacro')
    assert not re.search(hooks['urdfgenpy-check']['files'], 'urdf/macros.xacro')
    assert 'urdfgenpy = ' in (Path(__file__).parents[1] / 'setup.py').read_text()
    path = tmp_path / 'arm.urdf'
    for hook_id, status, text in (('urdfgenpy-check', 1, broken('J104')),
                                  ('urdfgenpy-fix', 0, broken('J104'))):
        hook = hooks[hook_id]
        assert re.search(hook['files'], path.name) and hook['language'] == 'python'
        path.write_text(text)
        program, *arguments = shlex.split(hook['entry'])
        assert program == 'urdfgenpy'
        result = CliRunner().invoke(main, [*arguments, str(path)])  # pre-commit adds files
        assert result.exit_code == status, result.output
    assert path.read_text() != broken('J104')  # the fix hook repaired it


def test_text_report_to_a_file(files, tmp_path: Path) -> None:
    report = tmp_path / 'check.txt'
    result = _run(tmp_path, '-o', str(report), str(files['error.urdf']))
    assert result.exit_code == 1 and result.stdout == ''
    (line,) = report.read_text().splitlines()
    assert ' error J104 ' in line and result.stderr.startswith('1 file(s): 1 error(s)')
