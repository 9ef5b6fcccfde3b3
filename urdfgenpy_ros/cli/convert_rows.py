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
``urdfgenpy convert``'s side of the format rows: their flags as click options, and a run.

Every row's flagged :class:`~urdfgenpy_ros.formats.options.Option` becomes one click option
of ``convert`` (ordered by ``rank``); a flag given for output whose row does not take it is
refused in the words of the row that does. A row's write step is its ``convert`` hook
(``module:function``), else :func:`write_plain`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import click

from urdfgenpy_ros.formats.options import Option
from urdfgenpy_ros.formats.table import Format, FORMATS, save
from urdfgenpy_ros.model.errors import ModelError, UrdfgenpyError
from urdfgenpy_ros.report import counted
from urdfgenpy_ros.resources import rebase_meshes
from urdfgenpy_ros.robot import Robot


@dataclass(frozen=True)
class ConvertRun:
    """One ``convert``: its files, the rows' flags as given, and its own options."""

    source: Path
    target: Path
    values: Mapping[str, Any] = field(default_factory=dict)
    package_paths: tuple[Path, ...] = ()
    force: bool = False

    def taken(self, row: Format) -> list[Option]:
        """Return the flagged options ``row``'s output takes (its own, and others' ``also``)."""
        return [option for other in FORMATS for option in other.declared()
                if option.flag and (other is row or row.name in option.also)]

    def keywords(self, row: Format) -> dict[str, Any]:
        """Return the writer keywords of the flags (transforms apart) for ``row``."""
        return {option.keyword: self.values[option.name] for option in row.declared()
                if option.keyword and option.flag and option.transform is None}

    def transforms(self, row: Format) -> list[tuple[Option, Any]]:
        """Return the given options applied to the robot before writing ``row``."""
        return [(option, self.values[option.name]) for option in self.taken(row)
                if option.transform is not None and option.given(self.values[option.name])]


def refuse_misplaced(row: Format, run: ConvertRun) -> None:
    """Refuse, in one line, a flag given for output whose row does not take it."""
    taken = {option.flag for option in run.taken(row)}
    for other in reversed(FORMATS):
        flags = [option.flag for option in other.declared()
                 if option.flag and option.flag not in taken
                 and option.given(run.values[option.name])]
        if flags:
            raise UrdfgenpyError(f'{run.target}: ' + other.misplaced.format(
                flag=flags[0], flags=', '.join(flags), suffix=other.suffixes[0]))


def _click_option(option: Option) -> Callable[..., Any]:
    """Return the click option of ``option``'s flag."""
    settings: dict[str, Any] = {'help': option.help_text}
    if option.choices:
        settings['type'] = click.Choice(option.choices)
    if option.file:
        settings['type'] = click.Path(exists=True, dir_okay=False, path_type=Path)
    if option.is_flag or option.multiple:
        settings['is_flag' if option.is_flag else 'multiple'] = True
    if option.metavar:
        settings['metavar'] = option.metavar
    if option.default not in (None, False):
        settings.update(default=option.default, show_default=True)
    parse = option.parse
    if parse is not None:
        def parsed(context: Any, parameter: Any, words: tuple[str, ...]) -> Any:
            try:
                return parse(words)
            except ModelError as error:
                raise click.BadParameter(str(error).removeprefix(f'{option.flag} '),
                                         param=parameter) from None
        settings['callback'] = parsed
    assert option.flag is not None
    return click.option(option.flag, option.name, **settings)


def row_options(low: int, high: int) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Return a decorator adding the rows' flags of rank ``low`` to below ``high``."""
    def decorate(function: Callable[..., Any]) -> Callable[..., Any]:
        options = sorted((option for row in FORMATS for option in row.declared()
                          if option.flag and low <= option.rank < high),
                         key=lambda option: option.rank)
        for option in reversed(options):
            function = _click_option(option)(function)
        return function
    return decorate


def write_plain(robot: Robot, run: ConvertRun) -> int:
    """Write ``robot`` with its row's writer; say the links and joints written."""
    rebase_meshes(robot, run.source.parent, run.target.parent)  # relative meshes still found
    from urdfgenpy_ros.formats.table import writer_for
    save(robot, run.target, **run.keywords(writer_for(run.target)))
    click.echo(f"wrote {run.target}: {counted(len(robot.links), 'link')}, "
               f"{counted(len(robot.joints), 'joint')}")
    return 0
