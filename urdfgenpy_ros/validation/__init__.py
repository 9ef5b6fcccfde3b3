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

"""``robot.validate()``: everything that breaks RViz, Gazebo or controllers, found early."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from os import PathLike
from typing import TYPE_CHECKING

from urdfgenpy_ros.model.codes import CODES
from urdfgenpy_ros.model.errors import Severity, ValidationError
from urdfgenpy_ros.model.urdf_versions import DEFAULT_TARGET
from urdfgenpy_ros.validation.checklist import (
    Check, CHECKS, Review, review, ReviewOptions, run_checks, Suppressed)

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

__all__ = ['Check', 'CHECKS', 'CODES', 'review', 'Review', 'ReviewOptions', 'Suppressed',
           'validate', 'ValidationError']


def validate(robot: RobotModel, strict: bool = False, *, check_meshes: bool = True,
             search_paths: Iterable[str | PathLike[str]] = (),
             target: str | None = DEFAULT_TARGET, statics: bool = False,
             payload: Mapping[str, object] | None = None,
             statics_margin: float = 1.0,
             mjcf: str | PathLike[str] | None = None) -> list[ValidationError]:
    """
    Return every finding about ``robot``; with ``strict``, raise the first error instead.

    Mesh files are resolved through ``search_paths``, the ament index and
    ``ROS_PACKAGE_PATH`` (relative paths from the file the robot was read from); pass
    ``check_meshes=False`` to skip them. The URDF version is judged for the ROS
    distribution ``target`` (``'jazzy'``, ``'rolling'``; None: only against the robot's
    own features). Reader warnings come first. With ``statics``, each joint's effort is
    judged against the worst gravity torque over its range (T801, carrying ``payload``,
    e.g. ``{'link': 'tool0', 'mass': 2.0}``, times ``statics_margin``) and against its
    other force limits (T802; with ``mjcf``, also those MuJoCo compiles from that file).
    Nothing is silenced: :func:`review` applies ``--ignore`` codes and suppression comments.

    :raises ValidationError: with ``strict=True``, the first finding of severity error.
    """
    found, _ = run_checks(robot, ReviewOptions(
        search_paths=tuple(search_paths), check_meshes=check_meshes, target=target,
        statics=statics, payload=payload, statics_margin=statics_margin, mjcf=mjcf))
    if strict:
        for finding in found:
            if finding.severity is Severity.ERROR:
                raise finding
    return found
