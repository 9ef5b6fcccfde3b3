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


"""Mimic joints as MuJoCo joint equalities, as stiff as the time step allows."""

from __future__ import annotations

from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.model.floats import fmt, fmt_vec

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

TIMESTEP = 0.002  # MuJoCo's default


def write_equalities(document: Any, robot: RobotModel) -> set[str]:
    """
    Write each mimic joint as a joint equality: q = offset + multiplier * q_leader.

    MuJoCo's constraints are soft; this one is made as stiff as the step allows (a time
    constant of two steps, MuJoCo's safe limit, and an impedance of 0.9999), so the
    follower stays within about 1e-6 rad of the URDF's relation while the leader moves.
    Both joints must move along one axis; return the followers written.
    """
    mimics = [joint for joint in robot.joints if joint.mimic is not None
              and joint.type.is_movable and robot.has_joint(joint.mimic.joint)
              and robot.get_joint(joint.mimic.joint).type.is_movable]
    if not mimics:
        return set()
    section = etree.SubElement(document, 'equality')
    for joint in mimics:
        assert joint.mimic is not None
        etree.SubElement(section, 'joint', name=f'{joint.name}_mimic', joint1=joint.name,
                         joint2=joint.mimic.joint,
                         polycoef=fmt_vec((joint.mimic.offset, joint.mimic.multiplier,
                                           0.0, 0.0, 0.0)),
                         solref=f'{fmt(2.0 * _timestep(document))} 1',
                         solimp='0.9999 0.9999 0.001 0.5 2')
    return {joint.name for joint in mimics}


def _timestep(document: Any) -> float:
    option = document.find('option')
    try:
        return float(option.get('timestep', TIMESTEP)) if option is not None else TIMESTEP
    except ValueError:
        return TIMESTEP
