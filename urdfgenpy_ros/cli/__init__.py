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
The ``urdfgenpy`` command: one click group, one module per sub-command.

A sub-command's module is imported when the command is looked up (to run it or to list
its help), so ``urdfgenpy check`` loads what checking needs and nothing of the others.
"""

from __future__ import annotations

import atexit
from dataclasses import replace
import gc
import importlib
from typing import Any

import click

from urdfgenpy_ros.cli.words import CLI_WORDS
from urdfgenpy_ros.report import boundary

COMMANDS = ('example', 'tree', 'convert', 'check', 'inertia', 'init', 'graph', 'render',
            'view', 'attach', 'dh', 'mirror', 'srdf', 'collision')
"""The sub-commands, each the function of that name in ``urdfgenpy_ros.cli.<name>``."""


class _Commands(dict[str, click.Command]):
    """The group's commands by name; a command's module is imported on first look-up."""

    def __missing__(self, name: str) -> click.Command:
        if name not in COMMANDS:
            raise KeyError(name)
        command = getattr(importlib.import_module(f'urdfgenpy_ros.cli.{name}'), name)
        self[name] = command
        return command

    def get(self, name: str, default: Any = None) -> Any:
        """Return the command called ``name`` (imported now if need be), else ``default``."""
        return self[name] if name in self else default

    def __contains__(self, name: object) -> bool:
        return name in COMMANDS or dict.__contains__(self, name)

    def __iter__(self) -> Any:
        return iter(dict.fromkeys([*COMMANDS, *dict.keys(self)]))

    def __len__(self) -> int:
        return len(dict.fromkeys([*COMMANDS, *dict.keys(self)]))

    def keys(self) -> Any:
        """Return every command name, imported or not."""
        return list(self)

    def values(self) -> Any:
        """Return every command (each imported now)."""
        return [self[name] for name in self]

    def items(self) -> Any:
        """Return every (name, command) (each imported now)."""
        return [(name, self[name]) for name in self]


class _Group(click.Group):
    """A group inside the one boundary: a user's mistake is one line and exit 2."""

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        """
        Run the command line; as a process's own (no arguments given), skip exit's collection.

        The console script calls ``main()``: the process ends with the command, and its
        last garbage collection would walk every object only to free memory the exit frees
        anyway (a tenth of a one-file check's CPU). ``gc.freeze()`` at exit leaves them out;
        files, temporary folders and pools are closed by their own code and atexit hooks.
        ``main(args)`` and ``main.main(...)`` (CliRunner) leave the collector alone.
        """
        if not args and 'args' not in kwargs:
            atexit.register(gc.freeze)
        return super().__call__(*args, **kwargs)

    def invoke(self, ctx: click.Context) -> object:
        def verbose() -> bool:  # set by main() below, once the options are parsed
            return bool(ctx.obj and ctx.obj.get('verbose'))

        with boundary(replace(CLI_WORDS, say=_echo_error, verbose=verbose)):
            try:
                return super().invoke(ctx)
            except click.UsageError as error:  # one line, naming where the options are
                where = error.ctx.command_path if error.ctx is not None else 'urdfgenpy'
                raise click.UsageError(f'{error.format_message()} (see {where} --help)'
                                       ) from None


def _echo_error(line: str) -> None:
    click.echo(line, err=True)


@click.group(cls=_Group, context_settings={'help_option_names': ['-h', '--help']})
@click.option('--verbose', is_flag=True, help='Show tracebacks of known errors too.')
@click.version_option(package_name='urdfgenpy_ros')
@click.pass_context
def main(ctx: click.Context, verbose: bool) -> None:
    """Build, read, check and convert robot descriptions."""
    ctx.obj = {'verbose': verbose}


main.commands = _Commands()
