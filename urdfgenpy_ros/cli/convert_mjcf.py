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
``urdfgenpy convert SOURCE robot.xml``: the MJCF write step and its loss report.

The report lists what the MJCF cannot carry, one finding per element, in ``check``'s
formats (``--report text|json|sarif`` on stderr, or stdout for JSON and SARIF); the
choices the writer made (the base, the gains) follow as notes. ``--strict`` makes any
loss an error: exit status 1, and nothing is written, as ``check --strict`` and
``convert`` refuse elsewhere.
"""

from __future__ import annotations

import click

from urdfgenpy_ros.cli.check_reports import FileReport, json_report, sarif_report
from urdfgenpy_ros.cli.collision import mjcf_collisions
from urdfgenpy_ros.cli.convert_rows import ConvertRun
from urdfgenpy_ros.formats.mjcf import MjcfRefusedError, write_mjcf
from urdfgenpy_ros.formats.table import writer_for
from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.report import counted
from urdfgenpy_ros.robot import Robot


def write_mjcf_file(robot: Robot, run: ConvertRun) -> int:
    """
    Write ``robot`` as MJCF to the target; print the report; return the exit status.

    Without ``--force``, a mesh or scene file beside it with other content is refused.
    """
    target, values = run.target, run.values
    scratch = mjcf_collisions(robot, values['collision'], run.package_paths)  # noqa: F841
    try:
        result = write_mjcf(robot, target, **run.keywords(writer_for(target)),
                            search_paths=run.package_paths, overwrite=run.force)
    except MjcfRefusedError as error:
        for finding in error.findings:
            click.echo(str(finding), err=True)
        raise UrdfgenpyError(f'{target} not written: {error}') from None
    report = FileReport(str(target), findings=result.findings, notes=result.notes)
    if values['report'] == 'json':
        click.echo(json_report([report]))
    elif values['report'] == 'sarif':
        click.echo(sarif_report([report]))
    else:
        for finding in result.findings:
            click.echo(str(finding), err=True)
    for note in result.notes:
        click.echo(f'{target}: note: {note}', err=True)
    if values['strict'] and result.findings:
        click.echo(f'{target} not written: {len(result.findings)} thing(s) the MJCF cannot '
                   'carry, errors under --strict (without it, they are warnings and the '
                   'model is written)', err=True)
        return 1
    meshes = len(result.files) - 1 - int(values['scene'])
    click.echo(f'wrote {target}: {counted(len(robot.links), "link")}, '
               f'{counted(len(robot.joints), "joint")}'
               + (f', {meshes} mesh file(s)' if meshes else '')
               + (', scene.xml' if values['scene'] else '')
               + f'; {len(result.findings)} thing(s) the MJCF cannot carry', err=True)
    return 0
