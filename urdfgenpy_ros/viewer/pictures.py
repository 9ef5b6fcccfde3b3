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


"""The pictures ``urdfgenpy init`` puts in a package's README: the robot and its tree."""

from __future__ import annotations

from collections.abc import Iterable
from os import PathLike

from urdfgenpy_ros.model.errors import MissingDependencyError, UrdfgenpyError
from urdfgenpy_ros.robot import Robot

ROBOT_PICTURE = 'doc/robot.png'
TREE_DIAGRAM = 'doc/tree.svg'


def package_pictures(robot: Robot, search_paths: Iterable[str | PathLike[str]] = ()
                     ) -> tuple[dict[str, bytes], list[str]]:
    """
    Return the pictures the installed extras can make (path in the package: bytes).

    Also returns a note for each picture that failed for another reason than a missing
    extra (the README says how to draw them); nothing here stops the package being created.
    """
    pictures: dict[str, bytes] = {}
    notes: list[str] = []
    try:
        from urdfgenpy_ros.viewer.render import picture_png, render
        picture = render(robot, {}, 'iso', (640, 480), search_paths=search_paths)
        pictures[ROBOT_PICTURE] = picture_png(picture)
        notes += [f'{ROBOT_PICTURE} leaves out what cannot be drawn: {problem}'
                  for problem in picture.problems]
    except MissingDependencyError:  # the README says how to draw it
        pass
    except (UrdfgenpyError, OSError) as error:
        notes.append(f'no {ROBOT_PICTURE} in the README: {error}')
    try:
        from urdfgenpy_ros.viewer.graph import diagram
        pictures[TREE_DIAGRAM] = diagram(robot, 'svg')
    except MissingDependencyError:
        pass
    except (UrdfgenpyError, OSError) as error:
        notes.append(f'no {TREE_DIAGRAM} in the README: {error}')
    return pictures, notes
