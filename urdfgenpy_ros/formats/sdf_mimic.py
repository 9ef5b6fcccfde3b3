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
Mimic joints in SDF: SDFormat 1.11's ``<axis><mimic joint=...>``, or none in 1.9.

SDF 1.11 reads follower = multiplier * (leader - reference) + offset; URDF's mimic is the
same with reference 0. Gazebo Harmonic (libsdformat 14) reads it, as libsdformat's own URDF
conversion writes it. A chain (a follower's leader is itself a follower) is written as
following the first leader that follows no joint, its multiplier and offset composed; a
leader the SDF has no axis for (a fixed joint, merged away by lumping) leaves the follower
without ``<mimic>``. Each such change, and a mimic 1.9 cannot hold, is one line.
"""

from __future__ import annotations

from typing import NamedTuple, TYPE_CHECKING

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.joint import JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

VERSIONS = ('1.9', '1.11')
"""The SDFormat versions SDF output writes: 1.9 (libsdformat 12), 1.11 (mimic joints)."""
MIMIC_VERSION = '1.11'
_AXIS_TYPES = (JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC)


class Follow(NamedTuple):
    """The leader a follower's ``<mimic>`` names, with the multiplier and offset."""

    leader: str
    multiplier: float
    offset: float


def sdf_version(robot: RobotModel, version: str | None) -> str:
    """
    Return the SDFormat version to write: ``version``, else 1.11 with mimic joints, else 1.9.

    :raises ModelError: for a version SDF output does not write.
    """
    if version is None:
        return MIMIC_VERSION if any(joint.mimic for joint in robot.joints) else VERSIONS[0]
    if version not in VERSIONS:
        raise ModelError(f'SDF version {version!r} is not written (choose one of '
                         f"{', '.join(VERSIONS)}: 1.11 holds mimic joints)")
    return version


def follows(robot: RobotModel, original: RobotModel | None = None
            ) -> tuple[dict[str, Follow], list[str]]:
    """
    Return each follower's resolved leader in ``robot`` and one line per change made.

    ``original`` is the robot before lumping, to say which leader was merged away.
    """
    resolved: dict[str, Follow] = {}
    notes = [f'joint {joint.name!r} is a fixed joint merged away: its <mimic> of '
             f'{joint.mimic.joint!r} is not written' for joint in
             (original.joints if original is not None else ())
             if joint.mimic is not None and not robot.has_joint(joint.name)]
    for joint in robot.joints:
        if joint.mimic is None:
            continue
        if joint.type not in _AXIS_TYPES:
            notes.append(f'joint {joint.name!r} is {joint.type.value}: its <mimic> of '
                         f'{joint.mimic.joint!r} is not written (SDF mimics an axis)')
            continue
        follow, chain = _resolve(robot, joint.name)
        if follow is None:
            notes.append(_lost(robot, original, joint.name, chain))
            continue
        if len(chain) > 2:
            notes.append(f"joint {joint.name!r} follows {' -> '.join(map(repr, chain[1:]))}: "
                         f'written as following {follow.leader!r} with multiplier '
                         f'{follow.multiplier:g} and offset {follow.offset:g}')
        resolved[joint.name] = follow
    return resolved, notes


def _resolve(robot: RobotModel, name: str) -> tuple[Follow | None, list[str]]:
    """Follow the chain of leaders from ``name``; None when it ends nowhere or loops."""
    multiplier, offset, chain = 1.0, 0.0, [name]
    joint = robot.get_joint(name)
    while joint.mimic is not None:
        leader = joint.mimic.joint
        # this = m * leader + o, leader = m' * next + o': this = m m' next + (m o' + o)
        offset += multiplier * joint.mimic.offset
        multiplier *= joint.mimic.multiplier
        chain.append(leader)
        if leader in chain[:-1] or not robot.has_joint(leader):
            return None, chain
        joint = robot.get_joint(leader)
    if joint.type not in _AXIS_TYPES:
        return None, chain
    return Follow(chain[-1], multiplier, offset), chain


def _lost(robot: RobotModel, original: RobotModel | None, name: str, chain: list[str]) -> str:
    leader = chain[-1]
    if leader in chain[:-1]:
        why = f"the leaders loop ({' -> '.join(map(repr, chain))})"
    elif robot.has_joint(leader):
        why = f'{leader!r} is a {robot.get_joint(leader).type.value} joint, which has no axis'
    elif original is not None and original.has_joint(leader):
        why = f'{leader!r} is a fixed joint merged away'
    else:
        why = f'there is no joint {leader!r}'
    return (f'joint {name!r} mimics {chain[1]!r}, but {why}: its <mimic> is not written '
            '(it moves on its own)')


def mimic_notes(robot: RobotModel, version: str) -> list[str]:
    """Return the line saying what happens to the robot's mimic joints in ``version``."""
    followers = [joint.name for joint in robot.joints if joint.mimic is not None]
    if not followers:
        return []
    listed = ', '.join(map(repr, followers))
    if version != MIMIC_VERSION:
        return [f'SDF {version} has no mimic joints: {listed} move on their own (write SDF '
                f"{MIMIC_VERSION}: --sdf-version {MIMIC_VERSION}, to_sdf(version='"
                f"{MIMIC_VERSION}'))"]
    return [f"mimic joints {listed}: Gazebo's default physics engine, DART, ignores "
            '<mimic>; Bullet-featherstone honours it (gz sim --physics-engine '
            'gz-physics-bullet-featherstone-plugin)']
