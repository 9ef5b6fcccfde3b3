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

"""Joints: axes, limits, mimic chains and safety controllers."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from urdfgenpy_ros.model.findings import Findings, joint_path
from urdfgenpy_ros.model.joint import Joint, JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def check_joints(robot: RobotModel, findings: Findings) -> None:
    """Check every joint's axis, limit, mimic and safety controller."""
    for joint in robot.joints:
        _check_axis(joint, findings)
        _check_limit(joint, findings)
        _check_safety(joint, findings)
    _check_mimics(robot, findings)


def _check_axis(joint: Joint, findings: Findings) -> None:
    if joint.axis is None or not joint.type.is_movable:
        return
    where, element = joint_path(joint.name) + '/axis', f'joint {joint.name!r}'
    norm = math.sqrt(sum(value * value for value in joint.axis))
    if norm == 0.0:
        findings.add('J101', joint, element, where, f'axis is zero for a {joint.type} joint',
                     'give the direction of motion, e.g. <axis xyz="0 0 1"/>', 'axis')
    elif math.isfinite(norm) and abs(norm - 1.0) > 1e-6:
        unit = ' '.join(f'{value / norm:.9g}' for value in joint.axis)
        findings.add('J102', joint, element, where, f'axis has length {norm:.6g}',
                     f'URDF consumers normalise it differently: write xyz="{unit}"', 'axis')


def _check_limit(joint: Joint, findings: Findings) -> None:
    element, where = f'joint {joint.name!r}', joint_path(joint.name)
    limit = joint.limit
    if limit is None:
        if joint.type.needs_limit:
            findings.add('J103', joint, element, where,
                         f'a {joint.type} joint needs <limit>',
                         'add <limit lower=... upper=... effort=... velocity=...>')
        return
    where += '/limit'
    bounded = joint.type in (JointType.REVOLUTE, JointType.PRISMATIC)
    if bounded and limit.lower > limit.upper:
        findings.add('J104', limit, element, where,
                     f'<limit> lower {limit.lower:g} > upper {limit.upper:g}',
                     'swap them, or widen the range', 'limit')
    for name in ('effort', 'velocity'):
        value = getattr(limit, name)
        if value < 0.0:
            findings.add('J105', limit, element, where, f'<limit> {name} {value:g} < 0',
                         f'{name} is a magnitude: make it positive', 'limit')
        elif value == 0.0 and joint.type.is_movable:
            findings.add('J106', limit, element, where, f'<limit> {name} is 0',
                         f'controllers and simulators cannot move it: set the {name}',
                         'limit')


def _check_safety(joint: Joint, findings: Findings) -> None:
    safety, limit = joint.safety_controller, joint.limit
    if safety is None or limit is None or joint.type not in (JointType.REVOLUTE,
                                                             JointType.PRISMATIC):
        return
    if safety.soft_lower_limit < limit.lower or safety.soft_upper_limit > limit.upper:
        findings.add('J110', safety, f'joint {joint.name!r}',
                     joint_path(joint.name) + '/safety_controller',
                     f'soft limits [{safety.soft_lower_limit:g}, {safety.soft_upper_limit:g}]'
                     f' reach outside [{limit.lower:g}, {limit.upper:g}]',
                     'keep soft limits inside the <limit> range', 'safety_controller')


def _check_mimics(robot: RobotModel, findings: Findings) -> None:
    leaders = {joint.name: joint.mimic.joint for joint in robot.joints
               if joint.mimic is not None}
    reported: set[str] = set()
    for joint in robot.joints:
        mimic = joint.mimic
        if mimic is None:
            continue
        element, where = f'joint {joint.name!r}', joint_path(joint.name) + '/mimic'
        if not robot.has_joint(mimic.joint):
            findings.add('J107', mimic, element, where,
                         f'mimics {mimic.joint!r}, which does not exist',
                         'name an existing joint in <mimic joint=...>', 'mimic')
            continue
        leader = robot.get_joint(mimic.joint)
        if not joint.type.is_movable:
            findings.add('J111', mimic, element, where,
                         f'a {joint.type} joint cannot follow {leader.name!r}',
                         'remove the <mimic>, or make the joint movable', 'mimic')
        elif not leader.type.is_movable:
            findings.add('J108', mimic, element, where,
                         f'mimics {leader.name!r}, a {leader.type} joint',
                         'mimic a revolute, continuous or prismatic joint', 'mimic')
        chain, current = [joint.name], mimic.joint
        while current in leaders and current not in chain:
            chain.append(current)
            current = leaders[current]
        if current in chain and joint.name not in reported:
            cycle = chain[chain.index(current):]
            reported.update(cycle)
            findings.add('J109', mimic, element, where,
                         'mimic cycle: ' + ' -> '.join([*cycle, current]),
                         'one joint of the cycle must move on its own: remove its <mimic>',
                         'mimic')
