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

"""``urdfgenpy init``: create a ROS 2 description package."""

from __future__ import annotations

import sys

import click

from urdfgenpy_ros.scaffold.command import main as scaffold_main


@click.command(context_settings={'ignore_unknown_options': True,
                                 'help_option_names': []})
@click.argument('arguments', nargs=-1, type=click.UNPROCESSED)
def init(arguments: tuple[str, ...]) -> None:
    """Create a ROS 2 description package NAME (run 'urdfgenpy init --help' for options)."""
    if '--moveit' in arguments:  # a moveit_config package instead (urdfgenpy init --moveit -h)
        from urdfgenpy_ros.scaffold.moveit_package import main as moveit_main
        sys.exit(moveit_main([item for item in arguments if item != '--moveit']))
    sys.exit(scaffold_main(list(arguments)))
