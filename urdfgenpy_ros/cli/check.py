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

"""``urdfgenpy check``: validate descriptions; exit 0 clean, 1 on errors, 2 if unreadable."""

from __future__ import annotations

import json
from pathlib import Path

import click

from urdfgenpy_ros.cli._options import input_options, parse_mappings
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.report import KNOWN_ERRORS, one_line


@click.command()
@click.argument('inputs', nargs=-1, required=True, metavar='FILE... [NAME:=VALUE]...')
@click.option('--format', 'output', type=click.Choice(['text', 'json']), default='text',
              show_default=True, help='One line per finding, or a JSON document.')
@click.option('--strict', is_flag=True, help='Fail on warnings too.')
@click.option('--no-meshes', is_flag=True, help='Do not check that mesh files exist.')
@input_options
def check(inputs: tuple[str, ...], output: str, strict: bool, no_meshes: bool,
          package_paths: tuple[Path, ...]) -> None:
    """
    Validate URDF and Xacro FILEs (Xacro arguments as name:=value).

    Exit status: 0 clean, 1 errors found (or warnings, with --strict), 2 a file could not
    be read.
    """
    mappings = parse_mappings(tuple(item for item in inputs if ':=' in item))
    files = [Path(item) for item in inputs if ':=' not in item]
    report, counts, unreadable = [], {'error': 0, 'warning': 0}, 0
    for path in files:
        try:
            robot = load(path, mappings, package_paths)
        except KNOWN_ERRORS as error:
            unreadable += 1
            message = one_line(error)
            report.append({'file': str(path), 'readable': False, 'error': message,
                           'findings': []})
            if output == 'text':
                click.echo(message)
            continue
        findings = robot.validate(check_meshes=not no_meshes, search_paths=package_paths)
        for finding in findings:
            counts[str(finding.severity)] += 1
            if output == 'text':
                click.echo(str(finding))
        report.append({'file': str(path), 'readable': True,
                       'findings': [finding.as_dict() for finding in findings]})
    if output == 'json':
        click.echo(json.dumps({'files': report, 'errors': counts['error'],
                               'warnings': counts['warning'], 'unreadable': unreadable},
                              indent=2))
    elif len(files) > 1 or counts['error'] or counts['warning'] or unreadable:
        click.echo(f'{len(files)} file(s): {counts["error"]} error(s), '
                   f'{counts["warning"]} warning(s), {unreadable} unreadable', err=True)
    failed = counts['error'] or (strict and counts['warning'])
    raise SystemExit(2 if unreadable else 1 if failed else 0)
