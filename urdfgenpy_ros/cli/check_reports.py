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

"""The reports of ``urdfgenpy check``: JSON, SARIF 2.1.0 (code scanning) and JUnit XML."""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING
from urllib.parse import quote

from urdfgenpy_ros.formats.xacro_source import EXPANDED
from urdfgenpy_ros.model.codes import CODES, PREFLIGHT_HINTS
from urdfgenpy_ros.model.errors import Severity, ValidationError
from urdfgenpy_ros.validation.checklist import Suppressed

if TYPE_CHECKING:
    from urdfgenpy_ros.validation.fix import Repair

SARIF_SCHEMA = 'https://json.schemastore.org/sarif-2.1.0.json'
_LEVEL = {Severity.ERROR: 'error', Severity.WARNING: 'warning'}


class FileReport:
    """
    What ``check`` found in one file: findings, silenced ones, repairs, or why unreadable.

    ``suppressed`` are the review's silenced findings (finding, reason: inSource or
    external, what said so); ``refused`` says why --fix left the file alone though it had
    repairs (Xacro, assembly, DH table); ``payload`` why --statics did not run (the
    --payload link is not one of this robot's). A plain class, not a dataclass: one less
    to build when ``check`` starts.
    """

    __slots__ = ('path', 'error', 'findings', 'suppressed', 'repairs', 'notes', 'refused',
                 'payload')

    def __init__(self, path: str, error: str | None = None,
                 findings: list[ValidationError] | None = None,
                 suppressed: list[Suppressed] | None = None,
                 repairs: list[Repair] | None = None, notes: list[str] | None = None,
                 refused: str | None = None, payload: str | None = None) -> None:
        self.path, self.error, self.refused, self.payload = path, error, refused, payload
        self.findings: list[ValidationError] = [] if findings is None else findings
        self.suppressed: list[Suppressed] = [] if suppressed is None else suppressed
        self.repairs: list[Repair] = [] if repairs is None else repairs
        self.notes: list[str] = [] if notes is None else notes


def json_report(reports: list[FileReport]) -> str:
    """Return the JSON document: per file its findings, suppressed findings and repairs."""
    import json  # each report's modules only when it is asked for (start-up)
    files = []
    for report in reports:
        entry: dict[str, object] = {'file': report.path, 'readable': report.error is None}
        if report.error is not None:
            entry['error'] = report.error
        entry['findings'] = [finding.as_dict() for finding in report.findings]
        entry['suppressed'] = [{**finding.as_dict(), 'suppression': kind, 'by': source}
                               for finding, kind, source in report.suppressed]
        entry['fixed'] = [repair.as_dict() for repair in report.repairs]
        entry['notes'] = report.notes
        entry['not_fixed'] = report.refused
        files.append(entry)
    every = [finding for report in reports for finding in report.findings]
    return json.dumps({
        'files': files,
        'errors': sum(f.severity is Severity.ERROR for f in every),
        'warnings': sum(f.severity is Severity.WARNING for f in every),
        'unreadable': sum(report.error is not None for report in reports),
        'suppressed': sum(len(report.suppressed) for report in reports),
        'fixed': sum(len(report.repairs) for report in reports),
        'not_fixed': sum(report.refused is not None for report in reports)}, indent=2)


def _uri(path: str) -> tuple[str, bool]:
    """Return a file's URI, relative to the working directory when it lies below it."""
    absolute = Path(path).resolve()
    try:
        relative = absolute.relative_to(Path(os.getcwd()).resolve())
    except ValueError:
        return absolute.as_uri(), False
    return quote(relative.as_posix()), True


def _location(finding: ValidationError, fallback: str) -> dict[str, object]:
    where = finding.location
    file = where.file or fallback
    expanded = file.endswith(EXPANDED)  # made by Xacro: no line of the file (xacro_source)
    uri, relative = _uri(file[:-len(EXPANDED)] if expanded else file)
    artifact: dict[str, object] = {'uri': uri}
    if relative:
        artifact['uriBaseId'] = '%SRCROOT%'
    region = {'startLine': 1 if expanded else where.line or 1}
    if where.line is not None and where.column is not None and not expanded:
        region['startColumn'] = where.column
    location: dict[str, object] = {
        'physicalLocation': {'artifactLocation': artifact, 'region': region}}
    if where.path:
        location['logicalLocations'] = [{'fullyQualifiedName': where.path,
                                         'kind': 'element'}]
    return location


def _related(finding: ValidationError) -> list[dict[str, object]]:
    """Return the SARIF related locations of a Xacro finding: calls, includes, properties."""
    related: list[dict[str, object]] = []
    for number, place in enumerate(finding.location.via, start=1):
        if place.file is None or place.line is None:
            continue
        uri, relative = _uri(place.file)
        artifact: dict[str, object] = {'uri': uri}
        if relative:
            artifact['uriBaseId'] = '%SRCROOT%'
        region: dict[str, object] = {'startLine': place.line}
        if place.column is not None:
            region['startColumn'] = place.column
        related.append({'id': number, 'message': {'text': place.path or 'via'},
                        'physicalLocation': {'artifactLocation': artifact, 'region': region}})
    return related


def _message(finding: ValidationError) -> str:
    made = (' (made by a Xacro macro or expression: line 1 stands for the file)'
            if (finding.location.file or '').endswith(EXPANDED) else '')
    via = ''.join(f' (via [{place.path}]({number}))'
                  for number, place in enumerate(finding.location.via, start=1)
                  if place.file is not None and place.line is not None)
    return f'{finding.element}: {finding.message} ({finding.hint}){made}{via}'


def _version() -> str:
    from importlib import metadata  # only for SARIF: a check without it starts sooner
    try:
        return metadata.version('urdfgenpy_ros')
    except metadata.PackageNotFoundError:
        return '0'


def sarif_report(reports: list[FileReport]) -> str:
    """
    Return a SARIF 2.1.0 log, as GitHub code scanning reads it.

    Rule ids are the finding codes (short description: the title; full description, which
    GitHub requires: the title and the hint; help: the hint), results carry file, line and
    column (the element path as logical location); suppressed findings are results with a
    suppression (``inSource`` for a comment, ``external`` for ``--ignore``), and a file
    that could not be read (or that --fix did not rewrite) is a tool notification.
    """
    import json  # each report's modules only when it is asked for (start-up)
    everything = [finding for report in reports for finding in report.findings]
    everything += [item.finding for report in reports for item in report.suppressed]
    codes = sorted({finding.code for finding in everything})
    hints: dict[str, str] = {}
    for finding in everything:
        hints.setdefault(finding.code, PREFLIGHT_HINTS.get(finding.code, finding.hint))
    titles = {code: CODES[code][1] if code in CODES else code for code in codes}
    rules = [{'id': code,  # no 'name': SARIF wants it unlike the id, or absent
              'shortDescription': {'text': titles[code]},
              'fullDescription': {'text': f'{titles[code]} ({hints[code]})'},
              'help': {'text': hints[code]},
              'defaultConfiguration': {'level': _LEVEL[CODES[code][0]]
                                       if code in CODES else 'warning'}}
             for code in codes]
    results = _results(reports, {code: number for number, code in enumerate(codes)})
    notifications = []
    for report in reports:
        for text in (report.error, report.refused):
            if text is None:
                continue
            uri, relative = _uri(report.path)
            artifact: dict[str, object] = {'uri': uri}
            if relative:
                artifact['uriBaseId'] = '%SRCROOT%'
            notifications.append({'level': 'error', 'message': {'text': text},
                                  'locations': [{'physicalLocation': {
                                      'artifactLocation': artifact}}]})
    invocation = {'executionSuccessful': not notifications,
                  'toolExecutionNotifications': notifications}
    root = Path(os.getcwd()).resolve().as_uri() + '/'
    log = {'$schema': SARIF_SCHEMA, 'version': '2.1.0', 'runs': [{
        'tool': {'driver': {'name': 'urdfgenpy', 'version': _version(),
                            'semanticVersion': _version(), 'rules': rules}},
        'originalUriBaseIds': {'%SRCROOT%': {'uri': root}},
        'invocations': [invocation],
        'results': results}]}
    return json.dumps(log, indent=2)


def _results(reports: list[FileReport], index: dict[str, int]) -> list[dict[str, object]]:
    """Return the SARIF results: each finding, and each suppressed one with its reason."""
    results = []
    for report in reports:
        pairs = [(f, None) for f in report.findings] + [
            (item.finding, item.reason) for item in report.suppressed]
        for finding, kind in pairs:
            result: dict[str, object] = {
                'ruleId': finding.code, 'ruleIndex': index[finding.code],
                'level': _LEVEL[finding.severity],
                'message': {'text': _message(finding)},
                'locations': [_location(finding, report.path)]}
            related = _related(finding)
            if related:
                result['relatedLocations'] = related
            if kind is not None:
                result['suppressions'] = [{'kind': kind}]
            results.append(result)
    return results


def junit_report(reports: list[FileReport], strict: bool) -> str:
    """
    Return JUnit XML: a test suite per file, a test case per finding.

    An error is a failure (a warning too with ``strict``; otherwise a passing case whose
    output is the warning), a suppressed finding is skipped, an unreadable file (or one
    --fix did not rewrite) is an error, and a clean file is one passing case.
    """
    from xml.etree import ElementTree  # only when asked for (start-up)
    suites = ElementTree.Element('testsuites', name='urdfgenpy check')
    totals = {'tests': 0, 'failures': 0, 'errors': 0, 'skipped': 0}
    for report in reports:
        counts = {'tests': 0, 'failures': 0, 'errors': 0, 'skipped': 0}
        suite = ElementTree.SubElement(suites, 'testsuite', name=report.path)
        cases: list[tuple[str, str | None, str, str]] = []  # name, kind, type, text
        if report.error is not None:
            cases.append(('read', 'error', 'unreadable', report.error))
        for finding in report.findings:
            failed = finding.severity is Severity.ERROR or strict
            cases.append((_case_name(finding), 'failure' if failed else None,
                          str(finding.severity), str(finding)))
        for finding, kind, _ in report.suppressed:
            cases.append((_case_name(finding), 'skipped', kind, str(finding)))
        if report.refused is not None:
            cases.append(('fix', 'error', 'not fixed', report.refused))
        if not cases:
            cases.append(('no findings', None, '', ''))
        for name, outcome, outcome_type, text in cases:
            case = ElementTree.SubElement(suite, 'testcase', name=name, classname=report.path)
            counts['tests'] += 1
            if outcome is None:
                if text:
                    ElementTree.SubElement(case, 'system-out').text = text
                continue
            detail = ElementTree.SubElement(case, outcome, message=text.split(': ', 1)[-1])
            if outcome != 'skipped':
                detail.set('type', outcome_type)
                detail.text = text
            counts[{'failure': 'failures', 'error': 'errors', 'skipped': 'skipped'}[outcome]] += 1
        for key, value in counts.items():
            suite.set(key, str(value))
            totals[key] += value
    for key, value in totals.items():
        suites.set(key, str(value))
    ElementTree.indent(suites)
    return '<?xml version="1.0" encoding="utf-8"?>\n' + ElementTree.tostring(
        suites, encoding='unicode') + '\n'


def _case_name(finding: ValidationError) -> str:
    where = f' (line {finding.location.line})' if finding.location.line else ''
    return f'{finding.code} {finding.element}{where}'
