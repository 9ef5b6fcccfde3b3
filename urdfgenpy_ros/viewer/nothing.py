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

"""Why a picture of a robot has nothing in it, and what to do about it."""

from __future__ import annotations

from urdfgenpy_ros.robot import Robot


def nothing_to_draw(robot: Robot, collision: bool, problems: list[str]) -> str:
    """Return the one line for a robot none of whose geometry of the kind asked can be drawn."""
    kind = 'collision' if collision else 'visual'
    other = 'visual' if collision else 'collision'
    has_other = any(link.visuals if collision else link.collisions for link in robot.links)
    option = f'{"without " if collision else ""}--collision'
    switch = f', or draw its {other} geometry ({option})' if has_other else ''
    if problems:
        more = f' (and {len(problems) - 1} more)' if len(problems) > 1 else ''
        return (f'robot {robot.name!r}: none of its {kind} geometry can be drawn: '
                f'{problems[0]}{more}: give the folder holding its packages (--package-path)'
                f'{switch}')
    return f'robot {robot.name!r} has no {kind} geometry to draw' + (
        f' (draw its {other} geometry: {option})' if has_other else '')
