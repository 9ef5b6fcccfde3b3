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
Effort in one voice: ``<limit effort>``, ros2_control and Gazebo should agree.

A joint's force limit can be written in three places of one URDF: the ``effort`` of its
``<limit>``, the ``max`` (and ``min``) of the ``effort`` command interface of its
``<ros2_control>`` joint, and an ``<effort>`` in a ``<gazebo reference="JOINT">`` block
(SDFormat's joint ``<limit>``, which Gazebo applies); and in an MJCF file made from it, the
joint's ``actuatorfrcrange`` and the ``forcerange`` of actuators on the joint times their
``gear`` (the torque MuJoCo applies at the joint), as MuJoCo compiles them. T802 lists
them when they differ.
"""

from __future__ import annotations

import math
from os import PathLike
from pathlib import Path
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.errors import MissingDependencyError, ParseError, SourceLocation
from urdfgenpy_ros.model.findings import Findings, joint_path

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def _number(text: str | None) -> float | None:
    try:
        value = float(text or '')
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def _ros2_control(element: Any) -> dict[str, list[tuple[str, float]]]:
    """Return the effort bounds of each joint of one ``<ros2_control>`` block."""
    found: dict[str, list[tuple[str, float]]] = {}
    block = element.get('name') or '?'
    for joint in element.iter('joint'):
        for interface in joint.iter('command_interface'):
            if interface.get('name') != 'effort':
                continue
            for param in interface.iter('param'):
                bound, value = param.get('name'), _number(param.text)
                if bound in ('min', 'max') and value is not None:
                    found.setdefault(joint.get('name') or '', []).append(
                        (f'<ros2_control name="{block}"> effort {bound}', abs(value)))
    return found


def voices(robot: RobotModel) -> dict[str, list[tuple[str, float]]]:
    """Return, per joint, every place that gives it a force limit, and the value."""
    found: dict[str, list[tuple[str, float]]] = {}
    for joint in robot.joints:
        if (joint.limit is not None and joint.type.is_movable
                and math.isfinite(joint.limit.effort)):  # R305 reports one that is not
            found.setdefault(joint.name, []).append(('<limit> effort', joint.limit.effort))
    gazebo = [(extension, joint.name) for joint in robot.joints
              for extension in joint.extensions]
    for extension in robot.extensions:
        if extension.tag == 'ros2_control':
            for name, values in _ros2_control(extension.element).items():
                found.setdefault(name, []).extend(values)
        elif robot.has_joint(extension.reference or ''):
            gazebo.append((extension, str(extension.reference)))
    for extension, name in gazebo:
        if extension.tag == 'gazebo':
            for node in extension.element.iter('effort'):
                value = _number(node.text)
                if value is not None:
                    found.setdefault(name, []).append(('<gazebo> <effort>', abs(value)))
    return found


def mjcf_voices(path: str | PathLike[str]) -> dict[str, list[tuple[str, float]]]:
    """Return the force limits MuJoCo compiles from the MJCF file ``path``, per joint."""
    try:
        import mujoco
    except ImportError:
        raise MissingDependencyError('mujoco', 'engines', 'Comparing efforts with an MJCF '
                                     'file') from None
    try:
        model = mujoco.MjModel.from_xml_path(str(path))
    except ValueError as error:
        raise ParseError(f'MuJoCo cannot load the MJCF file: {" ".join(str(error).split())}',
                         SourceLocation(str(path))) from None
    found: dict[str, list[tuple[str, float]]] = {}
    where = Path(path).name
    for joint in range(model.njnt):
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, joint)
        if name and model.jnt_actfrclimited[joint]:
            found.setdefault(name, []).append(
                (f'{where} actuatorfrcrange', float(abs(model.jnt_actfrcrange[joint]).max())))
    for actuator in range(model.nu):
        if (model.actuator_trntype[actuator] != mujoco.mjtTrn.mjTRN_JOINT
                or not model.actuator_forcelimited[actuator]):
            continue
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT,
                                 model.actuator_trnid[actuator][0])
        label = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, actuator) or actuator
        gear = abs(float(model.actuator_gear[actuator][0]))  # MuJoCo applies gear x force
        if name:
            geared = f' x gear {gear:g}' if gear != 1.0 else ''
            found.setdefault(name, []).append(
                (f'{where} actuator {label!r} forcerange{geared}',
                 gear * float(abs(model.actuator_forcerange[actuator]).max())))
    return found


def check_efforts(robot: RobotModel, findings: Findings,
                  mjcf: str | PathLike[str] | None = None) -> None:
    """Add T802 for every joint whose force limits (with ``mjcf``'s, if given) disagree."""
    found = voices(robot)
    for name, values in (mjcf_voices(mjcf) if mjcf is not None else {}).items():
        if name in found:
            found[name].extend(values)
    for name, values in found.items():
        numbers = [value for _, value in values]
        if len(values) < 2 or max(numbers) - min(numbers) <= 1e-9 * max(numbers):
            continue
        if not robot.has_joint(name):
            continue  # a <ros2_control> joint the robot does not have
        joint = robot.get_joint(name)
        listed = ', '.join(f'{value:g} in {where}' for where, value in values)
        at, where = ((joint.limit, joint_path(name) + '/limit') if joint.limit is not None
                     else (joint, joint_path(name)))
        findings.add('T802', at, f'joint {name!r}', where,
                     f'its force limits disagree: {listed}',
                     'write one value everywhere: the torque the actuator can hold '
                     'continuously (peak torque is not an effort limit)',
                     'limit' if joint.limit is not None else 'joint')
