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

"""The ``urdfgenpy`` command: one click group, one module per sub-command."""

from __future__ import annotations

import click

from urdfgenpy_ros.cli.attach import attach
from urdfgenpy_ros.cli.check import check
from urdfgenpy_ros.cli.collision import collision
from urdfgenpy_ros.cli.convert import convert
from urdfgenpy_ros.cli.dh import dh
from urdfgenpy_ros.cli.example import example
from urdfgenpy_ros.cli.graph import graph
from urdfgenpy_ros.cli.inertia import inertia
from urdfgenpy_ros.cli.init import init
from urdfgenpy_ros.cli.mirror import mirror
from urdfgenpy_ros.cli.render import render
from urdfgenpy_ros.cli.tree import tree
from urdfgenpy_ros.cli.view import view
from urdfgenpy_ros.report import boundary, FrontEnd


class _Group(click.Group):
    """A group inside the one boundary: a user's mistake is one line and exit 2."""

    def invoke(self, ctx: click.Context) -> object:
        def verbose() -> bool:  # set by main() below, once the options are parsed
            return bool(ctx.obj and ctx.obj.get('verbose'))

        with boundary(FrontEnd('urdfgenpy', say=_echo_error, verbose=verbose,
                               package_paths='with -p/--package-path',
                               usage_errors=(click.UsageError,))):
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


for command in (example, tree, convert, check, inertia, init, graph, render, view, attach,
                dh, mirror, collision):
    main.add_command(command)
