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
Edit the Xacro text at the line a finding names: exactly the findings made there go away.

Random robots of macros (called once or twice, in the file or an included one) whose mass
is a literal, a property or a macro parameter; some masses are negative (I210). One edit
of the value at the finding's line (or at a property or call site it names) is made and
the file checked again: the findings whose place or ``via`` is the edited line disappear,
every other stays where it was. A wrong place would fix the wrong findings.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
import re
import tempfile

from click.testing import CliRunner
from helpers import require_module

from urdfgenpy_ros.cli import main

hypothesis = require_module('hypothesis')  # its decorators are needed at import time
st = require_module('hypothesis.strategies')
given, HealthCheck, settings = hypothesis.given, hypothesis.HealthCheck, hypothesis.settings

NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
INERTIA = '<inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/>'
_PART = st.tuples(st.sampled_from(['literal', 'property', 'param']),
                  st.sampled_from(['top', 'included']),
                  st.lists(st.sampled_from(['-1.0', '1.0']), min_size=1, max_size=2))


def _macro(number: int, how: str, masses: list[str]) -> list[str]:
    value = {'literal': masses[0], 'property': f'${{mass_{number}}}',
             'param': '${mass}'}[how]
    lines = [f'  <xacro:property name="mass_{number}" value="{masses[0]}"/>'] \
        if how == 'property' else []
    return lines + [
        f'  <xacro:macro name="part{number}" params="n{" mass" if how == "param" else ""}">',
        '    <link name="${n}">',
        '      <inertial>',
        f'        <mass value="{value}"/>',
        f'        {INERTIA}',
        '      </inertial>',
        '    </link>',
        '    <joint name="${n}_joint" type="fixed">',
        '      <parent link="base_link"/><child link="${n}"/>',
        '    </joint>',
        '  </xacro:macro>']


def _write(folder: Path, parts: list[tuple[str, str, list[str]]]) -> None:
    top = ['<?xml version="1.0"?>', f'<robot name="r" {NS}>',
           '  <xacro:include filename="parts.xacro"/>',
           f'  <link name="base_link"><inertial><mass value="1"/>{INERTIA}</inertial></link>']
    included = ['<?xml version="1.0"?>', f'<robot {NS}>']
    for number, (how, where, masses) in enumerate(parts):
        (top if where == 'top' else included).extend(_macro(number, how, masses))
    for number, (how, _, masses) in enumerate(parts):
        calls = masses if how == 'param' else masses[:1] * len(masses)
        top += [f'  <xacro:part{number} n="p{number}_{index}"'
                f'{f" mass={chr(34)}{mass}{chr(34)}" if how == "param" else ""}/>'
                for index, mass in enumerate(calls)]
    (folder / 'r.urdf.xacro').write_text('\n'.join([*top, '</robot>', '']))
    (folder / 'parts.xacro').write_text('\n'.join([*included, '</robot>', '']))


def _negative_masses(folder: Path) -> list[dict]:
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        result = CliRunner().invoke(main, ['check', '--format', 'json', 'r.urdf.xacro'])
    finally:
        os.chdir(cwd)
    return [f for f in json.loads(result.stdout)['files'][0]['findings'] if f['code'] == 'I210']


def _places(finding: dict) -> set[tuple[str, int]]:
    return {(finding['file'], finding['line'])} | {
        (step['file'], step['line']) for step in finding['via']}


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(parts=st.lists(_PART, min_size=1, max_size=3), data=st.data())
def test_editing_the_cited_value_removes_exactly_the_findings_made_there(
        parts: list, data: st.DataObject) -> None:
    with tempfile.TemporaryDirectory() as temporary:
        folder = Path(temporary)
        _write(folder, parts)
        before = _negative_masses(folder)
        expected = sum(masses.count('-1.0') if how == 'param' else
                       len(masses) * (masses[0] == '-1.0') for how, _, masses in parts)
        assert len(before) == expected
        for one in before:  # a value from elsewhere names where it is written
            said = [(folder / one['file']).read_text().split('\n')[one['line'] - 1]] + [
                (folder / step['file']).read_text().split('\n')[step['line'] - 1]
                for step in one['via']]
            assert '${mass}' not in said[0] or any('mass="-1.0"' in row for row in said[1:])
            assert '${mass_' not in said[0] or any('<xacro:property' in row for row in said)
        if not before:
            return
        finding = data.draw(st.sampled_from(before))
        steps = [(finding['file'], finding['line'], finding['column'])] + [
            (step['file'], step['line'], step['column']) for step in finding['via']
            if 'property' in step['what'] or '=' in step['what']]  # a value's place
        file, line, column = data.draw(st.sampled_from(steps))
        rows = (folder / file).read_text().split('\n')
        value = re.compile(r'\b(value|mass)="[^"]*"')
        found = value.search(rows[line - 1], column - 1)
        assert found is not None, rows[line - 1]  # the line holds the value it names
        rows[line - 1] = value.sub(r'\1="2.0"', rows[line - 1], count=1)
        (folder / file).write_text('\n'.join(rows))
        after = _negative_masses(folder)
        assert after == [f for f in before if (file, line) not in _places(f)]
        assert len(after) < len(before)
