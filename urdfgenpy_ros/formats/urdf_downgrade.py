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
A robot written for an earlier URDF version: what that version lacks, said another way.

Below 1.1, quaternions become rpy (the same rotation to rounding) and a capsule becomes a
cylinder and two spheres; below 1.2, a limit's acceleration, deceleration and jerk are
dropped. Each capsule and each dropped limit is a finding (V706, V707) at its place in the
robot given, so nothing changes without a line.
"""

from __future__ import annotations

import dataclasses
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.formats._xml import xml_bytes
from urdfgenpy_ros.formats.urdf import write_urdf
from urdfgenpy_ros.formats.urdf_read import read_urdf_bytes
from urdfgenpy_ros.model.errors import ModelError, ValidationError
from urdfgenpy_ros.model.findings import Findings
from urdfgenpy_ros.model.geometry import Capsule, Cylinder, Origin, Sphere
from urdfgenpy_ros.model.link import Shape
from urdfgenpy_ros.model.transforms import matrix_rpy, multiply, translation
from urdfgenpy_ros.model.urdf_versions import (
    features, needed_version, parse_version, version_text)

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

VERSIONS = ('1.0', '1.1', '1.2')
"""The URDF versions a robot can be written as."""


def as_version(robot: RobotModel, version: str) -> tuple[RobotModel, list[ValidationError]]:
    """
    Return a copy of ``robot`` that URDF ``version`` holds, and what changed (findings).

    The robot itself is left as it is. A robot that needs nothing later than ``version``
    comes back as a copy declaring it.

    :raises ModelError: for a version other than 1.0, 1.1 or 1.2.
    """
    wanted = parse_version(version)
    if version not in VERSIONS or isinstance(wanted, str):
        raise ModelError(f'URDF version {version!r}: write one of {", ".join(VERSIONS)}')
    findings = Findings(robot)
    for feature in features(robot):
        if feature.needs <= wanted:
            continue
        if isinstance(feature.item, Capsule):
            findings.add('V706', feature.item, feature.owner, feature.path,
                         f'{feature.what} written as a cylinder and two spheres (URDF '
                         f'{version} has no capsule)', 'the same outline; declare '
                         'version="1.1" to keep the capsule', 'capsule')
        elif feature.what.startswith('limit'):
            findings.add('V707', feature.item, feature.owner, feature.path,
                         f'{feature.what} dropped (URDF {version} has no such limit)',
                         'keep it in your controller configuration, or declare '
                         'version="1.2"', 'limit')
    copy = read_urdf_bytes(xml_bytes(write_urdf(robot), 'surrogateescape'),
                           robot.source.file if robot.source else None, type(robot))
    if wanted < (1, 1):
        _without_quaternions(copy)
        _without_capsules(copy)
    if wanted < (1, 2):
        for joint in copy.joints:
            if joint.limit is not None:
                joint.limit.acceleration = joint.limit.deceleration = joint.limit.jerk = None
    declared = robot.urdf_version is not None or needed_version(robot) > wanted
    copy.urdf_version = version_text(wanted) if declared or wanted > (1, 0) else None
    return copy, findings.items


def _as_rpy(origin: Origin) -> Origin:
    """Return ``origin`` as rpy, its source element no longer asking for a quaternion."""
    if origin.quat_xyzw is None:
        return origin
    if origin.extras is not None:
        origin.extras.node.attrib.pop('quat_xyzw', None)
    return origin.as_rpy()


def _without_quaternions(robot: RobotModel) -> None:
    for link in robot.links:
        if link.inertial is not None:
            link.inertial.origin = _as_rpy(link.inertial.origin)
        for visual in link.visuals:
            visual.origin = _as_rpy(visual.origin)
        for collision in link.collisions:
            collision.origin = _as_rpy(collision.origin)
    for joint in robot.joints:
        joint.origin = _as_rpy(joint.origin)


def _without_capsules(robot: RobotModel) -> None:
    for link in robot.links:
        link.visuals[:] = [part for item in link.visuals for part in _split(item)]
        link.collisions[:] = [part for item in link.collisions for part in _split(item)]


def _split(item: Shape) -> list[Any]:
    """Return a capsule visual or collision as a cylinder and two spheres, else itself."""
    shape = item.geometry
    if not isinstance(shape, Capsule):
        return [item]
    item.geometry = Cylinder(shape.radius, shape.length)
    parts: list[Shape] = [item]
    frame = item.origin.matrix()
    for end, z in (('top', shape.length / 2.0), ('bottom', -shape.length / 2.0)):
        placed = multiply(frame, translation(0.0, 0.0, z))
        origin = Origin((placed[0][3], placed[1][3], placed[2][3]), matrix_rpy(placed))
        name = f'{item.name}_{end}' if item.name else None
        parts.append(dataclasses.replace(item, geometry=Sphere(shape.radius), origin=origin,
                                         name=name, source=None, extras=None))
    return parts
