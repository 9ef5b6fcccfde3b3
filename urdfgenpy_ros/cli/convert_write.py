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


"""``urdfgenpy convert``'s write step for SDF: its warnings said, what it holds counted."""

from __future__ import annotations

import warnings

import click

from urdfgenpy_ros.cli.convert_rows import ConvertRun
from urdfgenpy_ros.formats.table import save, writer_for
from urdfgenpy_ros.report import counted
from urdfgenpy_ros.resources import rebase_meshes
from urdfgenpy_ros.robot import Robot


def write_sdf_file(robot: Robot, run: ConvertRun) -> int:
    """Write the SDF; say each thing it does not carry in one line (the writer's warnings)."""
    target = run.target
    rebase_meshes(robot, run.source.parent, target.parent)  # relative meshes still found
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        save(robot, target, **run.keywords(writer_for(target)))
    for warning in caught:
        line = str(warning.message)
        click.echo(line if ': warning: ' in line else f'warning: {line}', err=True)
    text = target.read_text(encoding='utf-8')  # what the SDF holds, counted
    click.echo(f"wrote {target}: {counted(text.count('<link '), 'link')}, "
               f"{counted(text.count('<joint '), 'joint')}, "
               f"{counted(text.count('<frame '), 'frame')}")
    return 0
