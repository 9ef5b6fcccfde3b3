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
Check the robot before scaffolding it, as the new package's own test will.

The package's ``test/test_description.py`` fails on any error of ``validate(check_meshes=
False)``; ``init`` finds the same errors first and refuses unless told to repair them
(``--fix``: check's repairs, written into the package, never into the source) or to
scaffold them as they are (``--allow-errors``).
"""

from __future__ import annotations

from collections.abc import Sequence
from os import PathLike

from urdfgenpy_ros.model.errors import UrdfgenpyError, ValidationError
from urdfgenpy_ros.robot import Robot
from urdfgenpy_ros.validation.checklist import review, ReviewOptions
from urdfgenpy_ros.validation.fix_output import DEFAULT_RADIUS, fix_for_output


def preflight(robot: Robot, *, repair: bool = False, allow_errors: bool = False,
              radius: float = DEFAULT_RADIUS,
              search_paths: Sequence[str | PathLike[str]] = ()) -> list[str]:
    """
    Return the lines to print about ``robot``'s errors (repairs and findings kept).

    With ``repair`` the fixable errors are repaired in ``robot`` (give it a copy): a
    tensor from the link's shapes (meshes found through ``search_paths``), else a solid
    sphere's of ``radius``, as ``convert --fix`` does.

    :raises UrdfgenpyError: when errors remain and ``allow_errors`` is not set.
    """
    errors = _errors(robot)
    lines = []
    if errors and repair:  # as convert --fix: a link without shapes gets a sphere's tensor
        lines += fix_for_output(robot, radius, search_paths)
        errors = _errors(robot)
    lines += [str(error) for error in errors]
    if errors and not allow_errors:
        count = f'{len(errors)} error{"s" if len(errors) != 1 else ""}'
        how = ('pass --allow-errors to scaffold it as it is'
               if repair else 'pass --fix to repair what urdfgenpy check --fix can, or '
               '--allow-errors to scaffold it as it is')
        raise ScaffoldRefused(lines, f"the robot has {count} (above), which the new package's "
                              f'colcon test would report: {how}')
    return lines


class ScaffoldRefused(UrdfgenpyError):
    """The robot has errors; ``lines`` are the findings to print before the message."""

    def __init__(self, lines: list[str], message: str) -> None:
        super().__init__(message)
        self.lines = lines


def _errors(robot: Robot) -> list[ValidationError]:
    """Return the errors the package's test reports: validate(check_meshes=False)'s."""
    return review(robot, ReviewOptions(check_meshes=False, suppressions=False)).errors
