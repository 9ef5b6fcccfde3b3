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
from pathlib import Path
from typing import TYPE_CHECKING

from urdfgenpy_ros.errors import Severity, ValidationError
from urdfgenpy_ros.resources import PackageResolver
from urdfgenpy_ros.urdf_versions import DEFAULT_TARGET
from urdfgenpy_ros.validation.codes import CODES
from urdfgenpy_ros.validation.findings import Findings
from urdfgenpy_ros.validation.inertia import check_inertia
from urdfgenpy_ros.validation.joints import check_joints
from urdfgenpy_ros.validation.references import check_references
from urdfgenpy_ros.validation.topology import check_topology
from urdfgenpy_ros.validation.versions import check_versions
from urdfgenpy_ros.validation.xacro_source import in_source

if TYPE_CHECKING:
    from urdfgenpy_ros.robot import Robot

__all__ = ['CODES', 'validate', 'ValidationError']


def validate(robot: Robot, strict: bool = False, *, check_meshes: bool = True,
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

    :raises ValidationError: with ``strict=True``, the first finding of severity error.
    """
    findings = Findings(robot)
    for warning in robot.read_warnings:  # the reader's, as serious as CODES says
        findings.items.append(ValidationError(warning.code, CODES[warning.code][0],
                                              f'robot {robot.name!r}', warning.location,
                                              warning.message, 'see the message'))
    check_topology(robot, findings)
    check_joints(robot, findings)
    check_inertia(robot, findings)
    check_versions(robot, findings, target)
    resolver = PackageResolver(search_paths) if check_meshes else None
    source = robot.source.file if robot.source is not None else None
    base = Path(source).parent if source and Path(source).is_file() else None
    check_references(robot, findings, resolver, base)
    if statics:
        from urdfgenpy_ros.validation.efforts import check_efforts
        from urdfgenpy_ros.validation.statics import check_statics
        check_statics(robot, findings, payload, statics_margin)
        check_efforts(robot, findings, mjcf)
    found = in_source(findings.items, robot)  # Xacro: the source line, or none
    if strict:
        for finding in found:
            if finding.severity is Severity.ERROR:
                raise finding
    return found
