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


"""``urdfgenpy render``: a still picture of the robot, without a display or GPU."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import click

from urdfgenpy_ros.cli._options import input_options, read_robot
from urdfgenpy_ros.cli.words import CLI_WORDS

if TYPE_CHECKING:
    from urdfgenpy_ros.robot import Robot


def _joint_value(text: str) -> tuple[str, float]:
    name, separator, value = text.partition('=')
    try:
        if not separator or not name:
            raise ValueError
        return name, float(value)
    except ValueError:
        raise click.BadParameter(f'{text!r} is not name=value (radians or metres)',
                                 param_hint='--joints') from None


def _inside_limits(robot: Robot, values: dict[str, float]) -> dict[str, float]:
    """Return ``values`` clamped to the joints' limits, as the publisher does; say each."""
    from urdfgenpy_ros.publisher.joint_states import JointStates
    states = JointStates(robot)
    inside = dict(values)
    for name, value in values.items():
        free = states.free.get(name)
        if free is None or free.continuous:
            continue
        inside[name] = states.clamp(name, value)
        if inside[name] != value:
            click.echo(f'warning: joint {name!r}: {value:g} is outside its limits '
                       f'[{free.lower:g}, {free.upper:g}]: drawn at {inside[name]:g} '
                       '(clamped, as the publisher does)', err=True)
    return inside


@click.command()
@click.argument('path', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@click.option('--output', '-o', required=True, type=click.Path(dir_okay=False, path_type=Path),
              help='The PNG to write.')
@click.option('--joints', '-j', 'joints', multiple=True, metavar='NAME=VALUE',
              help='A joint position in radians or metres (repeatable; others at 0).')
@click.option('--view', type=click.Choice(['iso', 'front', 'side', 'top']), default='iso',
              show_default=True, help='Where the camera looks from.')
@click.option('--size', default='800x600', show_default=True, metavar='WxH',
              help='Image size in pixels.')
@click.option('--collision', is_flag=True, help='Draw the collision geometry instead.')
@input_options
def render(path: Path, arguments: tuple[str, ...], output: Path, joints: tuple[str, ...],
           view: str, size: str, collision: bool, package_paths: tuple[Path, ...]) -> None:
    """Draw the URDF or Xacro PATH posed at --joints values to a PNG (headless)."""
    from urdfgenpy_ros.viewer.render import render as draw, save_picture
    try:
        width, height = (int(v) for v in size.lower().split('x'))
    except ValueError:
        raise click.BadParameter(f'{size!r} is not WxH, e.g. 800x600',
                                 param_hint='--size') from None
    values = dict(_joint_value(text) for text in joints)
    for text in arguments:  # "-j a=1 b=2": the second value lands among the Xacro arguments
        if '=' in text and ':=' not in text:
            raise click.BadParameter(f'{text!r}: give each joint its own --joints (-j {text}); '
                                     'Xacro arguments are written name:=value',
                                     param_hint='--joints')
    robot = read_robot(path, arguments, package_paths)
    picture = draw(robot, _inside_limits(robot, values), view, (width, height), collision,
                   package_paths)
    for problem in picture.problems:
        click.echo(CLI_WORDS.worded(f'warning: {problem} (not drawn)'), err=True)
    click.echo(save_picture(picture, output))
