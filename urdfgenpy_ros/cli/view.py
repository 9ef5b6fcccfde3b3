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


"""``urdfgenpy view``: the robot in the browser, with joint sliders and its findings."""

from __future__ import annotations

from pathlib import Path
import sys
import threading
from typing import cast

import click

from urdfgenpy_ros.cli._options import ignore_option, input_options, parse_mappings
from urdfgenpy_ros.cli.words import CLI_WORDS


@click.command()
@click.argument('path', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@click.option('--port', default=8080, show_default=True, help='The port to serve on.')
@click.option('--host', default='127.0.0.1', show_default=True,
              help='The address to serve on (0.0.0.0: every interface).')
@ignore_option
@input_options
def view(path: Path, arguments: tuple[str, ...], port: int, host: str,
         package_paths: tuple[Path, ...], ignored: frozenset[str] = frozenset()) -> None:
    """
    Show PATH on a local web page; reload when it or a file it includes changes.

    The findings are those of urdfgenpy check with the same --ignore and -p, the file's
    suppression comments included.
    """
    from urdfgenpy_ros.formats import open_description
    from urdfgenpy_ros.robot import Robot
    from urdfgenpy_ros.validation.checklist import ReviewOptions
    from urdfgenpy_ros.viewer.web import RobotViewer
    mappings = parse_mappings(arguments)

    def read() -> Robot:
        return cast(Robot, open_description(path, mappings, package_paths))

    def watched(robot: Robot) -> list[str]:
        return sorted({str(path.resolve()), *robot.included_files})

    viewer = RobotViewer(read, host=host, port=port, search_paths=package_paths,
                         watched=watched, review_options=ReviewOptions(
                             search_paths=package_paths, ignore=ignored),
                         words=CLI_WORDS.worded)
    viewer.watch()
    click.echo(f'urdfgenpy view: {viewer.url} shows {viewer.robot.name!r} '
               f'({len(viewer.findings)} findings); Ctrl-C stops')
    sys.stdout.flush()  # the address shows at once when the output is a pipe or a file
    try:
        threading.Event().wait()
    except KeyboardInterrupt:
        pass
    finally:
        viewer.close()
