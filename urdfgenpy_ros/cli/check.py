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

from dataclasses import replace
import math
from pathlib import Path
from typing import Any, cast, Sequence, TYPE_CHECKING

import click

from urdfgenpy_ros.cli._options import ignore_option, input_options
from urdfgenpy_ros.cli._options import parse_mappings
from urdfgenpy_ros.cli.check_reports import FileReport, json_report, junit_report
from urdfgenpy_ros.cli.check_reports import sarif_report
from urdfgenpy_ros.cli.inputs import description_files
from urdfgenpy_ros.cli.words import CLI_WORDS
from urdfgenpy_ros.formats import DH_SUFFIXES, find_format, load
from urdfgenpy_ros.formats.xacro_source import EXPANDED
from urdfgenpy_ros.model.errors import ModelError, Severity, ValidationError
from urdfgenpy_ros.model.review import ENGINES
from urdfgenpy_ros.model.urdf_versions import DEFAULT_TARGET, TARGETS
from urdfgenpy_ros.report import KNOWN_ERRORS, one_line
from urdfgenpy_ros.robot import Robot
from urdfgenpy_ros.validation.checklist import Review, review, ReviewOptions

if TYPE_CHECKING:  # the fixer loads with --fix or --limit-default (start-up)
    from urdfgenpy_ros.validation.fix import Repair


class _Options:
    """What one ``check`` asks for: the review's options, --fix, --dry-run and --srdf."""

    __slots__ = ('review', 'fix', 'dry_run', 'srdf')

    def __init__(self, review: ReviewOptions, fix: bool, dry_run: bool,
                 srdf: Path | None = None) -> None:
        self.review, self.fix, self.dry_run, self.srdf = review, fix, dry_run, srdf


def _engines(ctx: click.Context, param: click.Parameter, value: str | None
             ) -> tuple[str, ...]:
    names = tuple(part.strip() for part in (value or '').split(',') if part.strip())
    unknown = [name for name in names if name not in ENGINES]
    if unknown:
        raise click.BadParameter(f'{", ".join(unknown)}: use {", ".join(ENGINES)} '
                                 '(comma-separated)')
    return names


def _limit_defaults(ctx: click.Context, param: click.Parameter, values: tuple[str, ...]
                    ) -> dict[str, float]:
    defaults: dict[str, float] = {}
    if not values:
        return defaults
    from urdfgenpy_ros.validation.fix import LIMIT_FIELDS
    for item in values:
        for part in item.split(','):
            name, _, text = part.partition('=')
            name = name.strip()
            try:
                if name not in LIMIT_FIELDS:
                    raise ValueError
                value = float(text)
                if not math.isfinite(value) or (name in ('effort', 'velocity') and value <= 0):
                    raise ValueError
                defaults[name] = value
            except ValueError:
                raise click.BadParameter(f'{part!r}: give NAME=NUMBER, NAME one of '
                                         f'{", ".join(LIMIT_FIELDS)} (effort and velocity '
                                         '> 0, e.g. effort=50)') from None
    return defaults


def _payload(ctx: click.Context, param: click.Parameter, value: str | None
             ) -> dict[str, object] | None:
    if value is None:
        return None
    mass, separator, link = value.partition('@')
    try:
        weight = float(mass)
        if not separator or not link or not 0.0 <= weight < float('inf'):
            raise ValueError
    except ValueError:
        raise click.BadParameter(f'{value!r}: give MASS@LINK, the mass in kg, e.g. '
                                 '2.0@tool0') from None
    return {'link': link, 'mass': weight}


def _margin(ctx: click.Context, param: click.Parameter, value: float | None
            ) -> float | None:
    if value is not None and not 0.0 < value < float('inf'):
        raise click.BadParameter(f'{value:g}: give a factor > 0, e.g. 1.5 for 50% spare')
    return value


@click.command()
@click.argument('inputs', nargs=-1, required=True, metavar='FILE... [NAME:=VALUE]...')
@click.option('--format', 'output', type=click.Choice(['text', 'json', 'sarif', 'junit']),
              default='text', show_default=True,
              help='One line per finding, JSON, SARIF 2.1.0 (code scanning) or JUnit XML.')
@click.option('--output', '-o', 'report_file', type=click.Path(dir_okay=False, path_type=Path),
              help='Write the report to this file instead of standard output.')
@click.option('--strict', is_flag=True, help='Fail on warnings too.')
@click.option('--no-meshes', is_flag=True, help='Do not check that mesh files exist.')
@ignore_option
@click.option('--engines', callback=_engines, metavar='mujoco,gazebo',
              help='Also report what these engines change or drop when they load the file.')
@click.option('--fix', 'repair', is_flag=True,
              help='Repair what has one right answer, changing only the repaired lines '
                   '(J102-J104, J106, I202, I203, and I205 by adding a base_footprint root); '
                   '--ignore CODE keeps a repair out, e.g. --ignore I205.')
@click.option('--dry-run', is_flag=True, help='With --fix: print the diff, write nothing.')
@click.option('--limit-default', 'limit_defaults', multiple=True, callback=_limit_defaults,
              metavar='NAME=VALUE',
              help='With --fix: values for a missing <limit> (lower, upper, effort, velocity) '
                   'or a zero effort/velocity, e.g. effort=10,velocity=1.')
@click.option('--target', type=click.Choice(sorted(TARGETS)), default=DEFAULT_TARGET,
              show_default=True,
              help='The ROS 2 distribution the description is for: its urdfdom decides '
                   'which URDF versions it reads (jazzy: 1.0; rolling: 1.0 to 1.2).')
@click.option('--statics', is_flag=True,
              help='Judge each effort against the worst gravity torque over the range of '
                   'motion (T801) and against its ros2_control and Gazebo limits (T802).')
@click.option('--payload', callback=_payload, metavar='MASS@LINK',
              help='With --statics: a payload held at a link, e.g. 2.0@tool0.')
@click.option('--statics-margin', type=float, callback=_margin, metavar='X',
              help='With --statics: the effort must reach X times the worst torque '
                   '(default 1.0).')
@click.option('--mjcf', type=click.Path(exists=True, dir_okay=False, path_type=Path),
              metavar='FILE',
              help='With --statics: an MJCF file made from the robot, whose joint and '
                   'actuator force limits T802 compares too (needs mujoco).')
@click.option('--srdf', type=click.Path(exists=True, dir_okay=False, path_type=Path),
              metavar='FILE',
              help='Check a MoveIt SRDF against the robot: names it lacks, chains, states '
                   'outside the limits, pairs disabled as never colliding that collide '
                   '(K901-K905; needs coal, the moveit extra).')
@input_options
def check(inputs: tuple[str, ...], output: str, report_file: Path | None, strict: bool,
          no_meshes: bool, ignored: frozenset[str], engines: tuple[str, ...], repair: bool,
          dry_run: bool, limit_defaults: dict[str, float], target: str, statics: bool,
          payload: dict[str, object] | None, statics_margin: float | None,
          mjcf: Path | None, srdf: Path | None, package_paths: tuple[Path, ...]) -> None:
    """
    Validate URDF and Xacro FILEs (Xacro arguments as name:=value).

    Exit status: 0 clean, 1 errors found (or warnings, with --strict), 2 a file could not
    be read, or --fix had repairs for a file it does not rewrite (Xacro, an assembly file,
    a DH table: the line after its findings says what to do).
    `<!-- urdfgenpy: ignore CODE -->` before an element silences CODE for it,
    `<!-- urdfgenpy: ignore-file CODE -->` at the top for the whole file.
    """
    if dry_run and not repair:
        raise click.UsageError('--dry-run previews --fix: give both')
    if (payload is not None or statics_margin is not None or mjcf is not None) \
            and not statics:
        raise click.UsageError('--payload, --statics-margin and --mjcf go with --statics: '
                               'give it')
    if srdf is not None:  # not an SRDF: one line before any robot is read
        from urdfgenpy_ros.moveit.srdf_check import read_srdf
        read_srdf(srdf)
    mappings = parse_mappings(tuple(item for item in inputs if ':=' in item))
    files = description_files([item for item in inputs if ':=' not in item])
    # a checked folder (a colcon src/) resolves the packages under it, after -p's
    package_paths += tuple(Path(item) for item in inputs
                           if ':=' not in item and Path(item).is_dir())
    options = _Options(ReviewOptions(
        search_paths=package_paths, check_meshes=not no_meshes, target=target,
        engines=engines, ignore=ignored, statics=statics, payload=payload,
        statics_margin=1.0 if statics_margin is None else statics_margin, mjcf=mjcf,
        limit_defaults=limit_defaults, strict=strict), repair, dry_run, srdf)
    reports = _check_files(files, mappings, options, output == 'text' and report_file is None)
    if output != 'text':
        document = {'json': json_report, 'sarif': sarif_report}[output](reports) \
            if output != 'junit' else junit_report(reports, strict)
        lines = [CLI_WORDS.worded(document.rstrip('\n'))]
    else:
        lines = [CLI_WORDS.worded(line) for report in reports
                 for line in _lines(report, dry_run)]
    if report_file is not None:
        report_file.write_text(''.join(f'{line}\n' for line in lines), encoding='utf-8')
    elif output != 'text':
        click.echo(lines[0], err=dry_run)
    raise SystemExit(_summary(reports, output == 'text', strict, dry_run))


def _check_files(files: list[Path], mappings: dict[str, str], options: _Options,
                 as_it_goes: bool) -> list[FileReport]:
    """Check each file; print its lines as it goes (``as_it_goes``) and return the reports."""
    reports = []
    for path in files:
        reports.append(_check_file(path, mappings, options))
        if as_it_goes:  # the diff of --dry-run owns stdout
            for line in _lines(reports[-1], options.dry_run):
                click.echo(CLI_WORDS.worded(line), err=options.dry_run)
    return reports


def _lines(report: FileReport, dry_run: bool) -> list[str]:
    """Return the text lines of one file's report."""
    done = 'to fix' if dry_run else 'fixed'
    lines = [str(repair).replace(': fixed ', f': {done} ', 1) for repair in report.repairs]
    lines += [*(_line(finding) for finding in report.findings), *report.notes]
    lines += [report.error] if report.error is not None else []
    lines += [report.payload] if report.payload is not None else []
    lines += [report.refused] if report.refused is not None else []  # after its findings
    return lines


def _summary(reports: list[FileReport], text: bool, strict: bool, dry_run: bool) -> int:
    """Print the count line (text output); return the exit status."""
    every = [finding for report in reports for finding in report.findings]
    errors = sum(finding.severity is Severity.ERROR for finding in every)
    warnings, unreadable = len(every) - errors, sum(r.error is not None for r in reports)
    suppressed = sum(len(report.suppressed) for report in reports)
    fixed = sum(len(report.repairs) for report in reports)
    refused = sum(report.refused is not None for report in reports)
    unmatched = sum(report.payload is not None for report in reports)
    if text:
        extra = (f', {suppressed} suppressed' if suppressed else '') + (
            f", {fixed} {'to fix' if dry_run else 'fixed'}" if fixed else '') + (
            f', {refused} not fixable by --fix' if refused else '') + (
            f', {unmatched} without the --payload link' if unmatched else '')
        click.echo(f'{len(reports)} file(s): {errors} error(s), {warnings} warning(s), '
                   f'{unreadable} unreadable{extra}', err=True)
    failed = errors or (strict and warnings)
    return 2 if unreadable or refused or unmatched else 1 if failed else 0


def _line(finding: ValidationError) -> str:
    """Return the finding's line, led by its file also when it has no line number."""
    text, where = str(finding), finding.location
    if where.line is None and where.file and where.path:  # made by a Xacro macro
        return f'{where.file}: {text.removeprefix(f"{where}: ")}'
    return text


def _review(robot: Robot, path: Path, options: ReviewOptions, report: FileReport) -> Review:
    """Review ``robot``; without the --payload link, say so and review it without statics."""
    try:
        return review(robot, options)
    except ModelError:
        if options.payload is None or any(link.name == options.payload['link']
                                          for link in robot.links):
            raise
        report.payload = (f'{path}: error: --payload: {options.payload["link"]!r} is not '
                          'a link of this robot: its statics were not checked')
        return review(robot, replace(options, statics=False))


def _render(report: FileReport, found: Review, srdf: Path | None = None,
            robot: Robot | None = None, search_paths: Sequence[Any] = ()) -> None:
    report.findings = found.findings
    report.suppressed = found.suppressed
    if srdf is not None and robot is not None:  # findings at the SRDF's lines
        from urdfgenpy_ros.moveit.srdf_check import check_srdf
        report.findings = [*report.findings, *check_srdf(robot, srdf,
                                                         search_paths=search_paths)]


def _prepared(report: FileReport, path: Path, robot: Robot) -> None:
    """Add what the file's own format refuses (its row's ``prepare``; URDF and Xacro: none)."""
    row = find_format(path)
    if row is not None and row.prepare is not None:
        found = row.prepare(robot, {})
        report.findings = [*report.findings, *found.findings]
        report.notes += [*found.lines, *([f'{path}: {found.refusal}'] if found.refusal else [])]


def _check_file(path: Path, mappings: dict[str, str], options: _Options) -> FileReport:
    """Read and review one file; with --fix, apply the review's repairs and review again."""
    report = FileReport(str(path))
    try:
        robot = cast(Robot, load(path, mappings, options.review.search_paths))
        found = _review(robot, path, options.review, report)
        expanded = robot.source is not None and (robot.source.file or '').endswith(EXPANDED)
        report.notes += [f'{path}{"" if expanded else f":{line}"}: warning: the suppression '
                         f'comment names {word!r}, which is not a finding code: it silences '
                         'nothing (codes look like I205)'
                         for line, word in found.unknown_suppressions]
        _render(report, found, options.srdf, robot, options.review.search_paths)
        _prepared(report, path, robot)
        if not options.fix:
            return report
        if robot.source_map is not None:  # Xacro: its values are edited where written
            from urdfgenpy_ros.cli.check_xacro import fix_xacro
            from urdfgenpy_ros.validation.rewrite import replace_file
            if fix_xacro(path, robot, found, mappings, options.review.search_paths,
                         options.dry_run, report, replace_file):
                _render(report, review(load(path, mappings, options.review.search_paths),
                                       options.review))
            return report
        repairs = found.fix()
        refusal = _not_rewritable(path, robot, _repairable(len(repairs), len(found.findings)),
                                  found.repairable)
        if refusal is not None:  # nothing is written: no word on missing defaults either
            report.refused = refusal if repairs else None
            return report
        report.notes += [f'{path}: {line}' for line in found.needs]
        if repairs:
            _apply(found, path, repairs, report, options.dry_run)
    except KNOWN_ERRORS as error:
        said = str(getattr(error, 'message', error))
        if getattr(error, 'code', None) == 'X003':  # a macro library: checked where included
            what = 'materials' if said.startswith('defines materials') else 'Xacro macros'
            report.notes.append(f'{path}: note: skipped, it holds {what} only (the '
                                f'files that include it are checked): X003 {said}')
        else:
            report.error = one_line(error)
        report.findings, report.suppressed, report.repairs = [], [], []
    return report


def _apply(found: Review, path: Path, repairs: list[Repair], report: FileReport,
           dry_run: bool) -> None:
    """Write the repaired file (or print the diff, with ``dry_run``); review what is written."""
    if dry_run:
        diff = found.diff(path)
        if diff:
            report.repairs = repairs
            click.echo(diff, nl=False)
        return
    written = found.apply(path)
    if written is not None:
        report.repairs = repairs
        _render(report, written)


def _repairable(count: int, listed: int) -> str:
    """Return which of the ``listed`` findings above ``--fix`` repairs: ``count`` of them."""
    plural = 's' if listed != 1 else ''
    return (f'the {listed} repairable finding{plural} above' if count == listed else
            f'the {count} of the {listed} finding{plural} above that --fix repairs')


def _not_rewritable(path: Path, robot: Robot, count: str,
                    repairable: Sequence[ValidationError]) -> str | None:
    """Return why ``path`` is not a file --fix can write back (None when it is plain URDF)."""
    if path.suffix.lower() in DH_SUFFIXES:
        from urdfgenpy_ros.formats.assembly_file import is_assembly
        if is_assembly(path):
            return (f'{path}: not fixed: it is an assembly file, which only names its parts: '
                    f"{count} are in the parts' files: run "
                    'urdfgenpy check --fix on those (Xacro parts by hand)')
        return (f'{path}: not fixed: it is a DH table, from which the robot is generated: '
                f'change the table for {count}')
    if path.suffix.lower() == '.xacro' or any(
            warning.code == 'X101' for warning in robot.read_warnings):
        from urdfgenpy_ros.cli.check_xacro import repaired_copy
        copy = repaired_copy(path, repairable)
        return (f'{path}: not fixed: it is Xacro, and writing the expanded robot back would '
                f'lose its macros and properties: repair {count} by '
                f'hand (their lines say how), or {copy}'
                + (' (or OUT.sdf)' if copy.endswith('--fix') else ''))
    return None
