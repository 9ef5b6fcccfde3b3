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

"""URDF versions: a version the target ROS cannot read, features the version lacks."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.findings import Findings
from urdfgenpy_ros.model.geometry import Origin
from urdfgenpy_ros.model.urdf_versions import (
    DEFAULT_TARGET, features, needed_version, parse_version, TARGETS, version_text)

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

_ROBOT = '/robot'


def check_versions(robot: RobotModel, findings: Findings, target: str | None = DEFAULT_TARGET
                   ) -> None:
    """
    Check the robot's URDF version against its features and the ``target`` ROS.

    :raises ModelError: for a target this package does not know.
    """
    if target is not None and target not in TARGETS:
        raise ModelError(f'unknown target {target!r} (use one of {", ".join(TARGETS)})')
    element = f'robot {robot.name!r}'
    declared = parse_version(robot.urdf_version)
    needed = needed_version(robot)
    if isinstance(declared, str):
        findings.add('V703', robot, element, _ROBOT,
                     f'version {robot.urdf_version!r}: {declared} (urdfdom refuses the file)',
                     f'write version="{version_text(needed)}"', 'robot')
        declared = (1, 0)
    elif target is not None:
        lowest, highest = TARGETS[target]
        if not lowest <= declared <= highest:
            readable = version_text(highest) if lowest == highest else \
                f'{version_text(lowest)} to {version_text(highest)}'
            findings.add('V701', robot, element, _ROBOT,
                         f"URDF version {robot.urdf_version} cannot be read by {target}'s "
                         f'urdfdom (it reads {readable}): robot_state_publisher refuses the '
                         'whole file', _fix(robot, target, needed), 'robot')
    for feature in features(robot):
        if feature.needs > declared:
            findings.add('V702', feature.item, feature.owner, feature.path,
                         f'{feature.what} needs URDF {version_text(feature.needs)} but the '
                         f'file declares {version_text(declared)}: urdfdom 6 ignores it, and '
                         "Jazzy's urdfdom does not know it", _feature_fix(feature.needs),
                         feature.tag)
    _check_quaternions(robot, findings)


def _fix(robot: RobotModel, target: str, needed: tuple[int, int]) -> str:
    if target == 'jazzy' and needed > (1, 0):
        return ('write a URDF 1.0 file for Jazzy: urdfgenpy convert IN OUT --urdf-version 1.0 '
                '(quaternions become rpy, capsules a cylinder and two spheres)')
    if target == 'jazzy':
        return 'write version="1.0" (the file uses nothing later) or leave version out'
    return f'write version="{version_text(max(needed, (1, 0)))}"'


def _feature_fix(needs: tuple[int, int]) -> str:
    return (f'declare <robot version="{version_text(needs)}"> for ROS Rolling, or for Jazzy '
            'write it the 1.0 way: urdfgenpy convert IN OUT --urdf-version 1.0')


def _origins(robot: RobotModel) -> list[tuple[str, str, Origin]]:
    found = []
    for link in robot.links:
        path = f"/robot/link[@name='{link.name}']"
        if link.inertial is not None:
            found.append((f'link {link.name!r}', path + '/inertial/origin',
                          link.inertial.origin))
        for kind, items in (('visual', link.visuals), ('collision', link.collisions)):
            found += [(f'link {link.name!r}', f'{path}/{kind}/origin', item.origin)
                      for item in items]
    found += [(f'joint {joint.name!r}', f"/robot/joint[@name='{joint.name}']/origin",
               joint.origin) for joint in robot.joints]
    return found


def _check_quaternions(robot: RobotModel, findings: Findings) -> None:
    for owner, path, origin in _origins(robot):
        quat = origin.quat_xyzw
        if quat is None:
            continue
        norm = math.sqrt(sum(value * value for value in quat))
        if norm == 0.0 or not math.isfinite(norm):
            findings.add('V705', origin, owner, path,
                         f'quat_xyzw {" ".join(f"{v:g}" for v in quat)} is no rotation '
                         '(zero length): read as none',
                         'write quat_xyzw="0 0 0 1" for no rotation', 'origin')
        elif abs(norm - 1.0) > 1e-6:
            unit = ' '.join(f'{value / norm:.9g}' for value in quat)
            findings.add('V704', origin, owner, path, f'quat_xyzw has length {norm:.6g} '
                         '(normalised when read, as urdfdom 6 does)',
                         f'write quat_xyzw="{unit}"', 'origin')
