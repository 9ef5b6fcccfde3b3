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
``urdfgenpy convert SOURCE robot.xml``: the MJCF options and the loss report.

The report lists what the MJCF cannot carry, one finding per element, in ``check``'s
formats (``--report text|json|sarif`` on stderr, or stdout for JSON and SARIF); the
choices the writer made (the base, the gains) follow as notes. ``--strict`` makes any
loss an error: exit status 1, and nothing is written, as ``check --strict`` and
``convert`` refuse elsewhere.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
import functools
from pathlib import Path
from typing import Any

import click

from urdfgenpy_ros.cli.check_reports import FileReport, json_report, sarif_report
from urdfgenpy_ros.cli.collision import mjcf_collisions
from urdfgenpy_ros.collision.methods import METHODS
from urdfgenpy_ros.errors import ModelError, UrdfgenpyError
from urdfgenpy_ros.formats.mjcf import BASES, MjcfRefusedError, write_mjcf
from urdfgenpy_ros.formats.mjcf.actuators import ACTUATOR_TYPES
from urdfgenpy_ros.formats.mjcf.gains import GainOption, parse_gain_words
from urdfgenpy_ros.robot import Robot


@dataclass(frozen=True)
class MjcfOptions:
    """What the MJCF options of ``convert`` asked for."""

    fuse_fixed: bool = False
    base: str | None = None
    actuators: str | None = None
    kp: GainOption = None
    kv: GainOption = None
    scene: bool = False
    overlay: Path | None = None
    strict: bool = False
    report: str = 'text'
    collision: str | None = None

    def given(self) -> list[str]:
        """Return the MJCF flags in use: other output formats refuse them."""
        flags = {'--fuse-fixed': self.fuse_fixed, '--base': self.base is not None,
                 '--actuators': self.actuators is not None, '--kp': self.kp is not None,
                 '--kv': self.kv is not None, '--scene': self.scene,
                 '--overlay': self.overlay is not None, '--strict': self.strict,
                 '--report': self.report != 'text', '--collision': self.collision is not None}
        return [flag for flag, on in flags.items() if on]


def _gain(parameter: Any, words: tuple[str, ...], positive: bool) -> GainOption:
    """Return ``--kp 2000 --kp JOINT=500`` as a gain or a mapping; refuse a bad one."""
    try:
        return parse_gain_words(parameter.name, words, positive)
    except ModelError as error:
        raise click.BadParameter(str(error).removeprefix(f'--{parameter.name} '),
                                 param=parameter) from None


_OPTIONS = (
    click.option('--fuse-fixed', is_flag=True,
                 help='MJCF output: merge fixed-joint links into their parents (lumped '
                      'inertia); each merged link stays a <site>.'),
    click.option('--base', type=click.Choice(BASES),
                 help='MJCF output: weld the root to the world (fixed, the default) or give '
                      "it a free joint (floating). A root link named 'world' welds it."),
    click.option('--actuators', type=click.Choice(ACTUATOR_TYPES),
                 help='MJCF output: this actuator on every joint, instead of the ones '
                      '<ros2_control> declares.'),
    click.option('--kp', multiple=True, metavar='[JOINT=]GAIN',
                 callback=lambda c, p, v: _gain(p, v, True),
                 help="MJCF output: position actuators' gain (MuJoCo's default 1); "
                      'JOINT=GAIN for one joint, repeatable: --kp 2000 --kp wrist_3_joint=500.'),
    click.option('--kv', multiple=True, metavar='[JOINT=]GAIN',
                 callback=lambda c, p, v: _gain(p, v, False),
                 help="MJCF output: velocity actuators' gain (MuJoCo's default 1), and the "
                      "position actuators' damping; JOINT=GAIN for one joint, repeatable."),
    click.option('--scene', is_flag=True,
                 help='MJCF output: also write scene.xml (floor, light, the robot).'),
    click.option('--overlay', type=click.Path(exists=True, dir_okay=False, path_type=Path),
                 help='MJCF output: merge this MJCF file in by element name (gains, '
                      'contacts, sites, keyframes tuned by hand).'),
    click.option('--strict', is_flag=True,
                 help='MJCF output: what the MJCF cannot carry is an error: exit 1, '
                      'nothing written.'),
    click.option('--collision', type=click.Choice(METHODS),
                 help='MJCF output: make each collision mesh light first (hull, decompose, '
                      'primitive, decimate, auto; see urdfgenpy collision).'),
    click.option('--report', type=click.Choice(['text', 'json', 'sarif']), default='text',
                 show_default=True,
                 help="MJCF output: the loss report's format (JSON and SARIF on stdout)."),
)


def mjcf_options(function: Callable[..., Any]) -> Callable[..., Any]:
    """Add the MJCF options to ``convert``; they arrive as one ``mjcf`` argument."""
    names = ('fuse_fixed', 'base', 'actuators', 'kp', 'kv', 'scene', 'overlay', 'strict',
             'report', 'collision')

    def wrapped(*args: Any, **kwargs: Any) -> Any:
        kwargs['mjcf'] = MjcfOptions(**{name: kwargs.pop(name) for name in names})
        return function(*args, **kwargs)

    functools.update_wrapper(wrapped, function)  # keeps the options given below it
    for option in reversed(_OPTIONS):
        wrapped = option(wrapped)
    return wrapped


def write_mjcf_file(robot: Robot, target: Path, options: MjcfOptions,
                    search_paths: tuple[Path, ...], force: bool = False) -> int:
    """
    Write ``robot`` as MJCF to ``target``; print the report; return the exit status.

    Without ``force``, a mesh or scene file beside it with other content is refused.
    """
    scratch = mjcf_collisions(robot, options.collision, search_paths)  # noqa: F841 (kept)
    try:
        result = write_mjcf(robot, target, fuse_fixed=options.fuse_fixed, base=options.base,
                            actuators=options.actuators, kp=options.kp, kv=options.kv,
                            scene=options.scene, overlay=options.overlay,
                            search_paths=search_paths, overwrite=force,
                            strict=options.strict)
    except MjcfRefusedError as error:
        for finding in error.findings:
            click.echo(str(finding), err=True)
        raise UrdfgenpyError(f'{target} not written: {error}') from None
    report = FileReport(str(target), findings=result.findings, notes=result.notes)
    if options.report == 'json':
        click.echo(json_report([report]))
    elif options.report == 'sarif':
        click.echo(sarif_report([report]))
    else:
        for finding in result.findings:
            click.echo(str(finding), err=True)
    for note in result.notes:
        click.echo(f'{target}: note: {note}', err=True)
    if options.strict and result.findings:
        click.echo(f'{target} not written: {len(result.findings)} thing(s) the MJCF cannot '
                   'carry, errors under --strict (without it, they are warnings and the '
                   'model is written)', err=True)
        return 1
    meshes = len(result.files) - 1 - int(options.scene)
    click.echo(f'wrote {target}: {len(robot.links)} links, {len(robot.joints)} joints'
               + (f', {meshes} mesh file(s)' if meshes else '')
               + (', scene.xml' if options.scene else '')
               + f'; {len(result.findings)} thing(s) the MJCF cannot carry', err=True)
    return 0
