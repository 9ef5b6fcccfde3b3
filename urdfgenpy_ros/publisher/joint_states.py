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
Joint positions for ``joint_states``, the way joint_state_publisher computes them.

Every revolute, continuous and prismatic joint in document order; mimic joints follow
their leaders (chains resolved, cycles refused); a joint's default is its ``zeros`` value,
else the middle of its range when 0 lies outside it, else 0; positions merged from other
publishers are clamped to the limits. No rclpy here, so it is tested on its own.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
import math

from urdfgenpy_ros.model.errors import ModelError, UrdfgenpyError
from urdfgenpy_ros.model.joint import JointType
from urdfgenpy_ros.robot import Robot


@dataclass(slots=True)
class _Free:
    lower: float
    upper: float
    continuous: bool
    position: float
    velocity: float = 0.0
    effort: float = 0.0
    forward: bool = True


@dataclass(slots=True)
class JointStateOptions:
    """The joint_state_publisher parameters that shape the message."""

    zeros: Mapping[str, float] = field(default_factory=dict)
    use_mimic_tags: bool = True
    use_smallest_joint_limits: bool = True
    publish_default_positions: bool = True
    publish_default_velocities: bool = False
    publish_default_efforts: bool = False


class JointStates:
    """The state of a robot's movable joints; ``message_arrays()`` fills a JointState."""

    def __init__(self, robot: Robot, options: JointStateOptions | None = None) -> None:
        self.options = options or JointStateOptions()
        self.names: list[str] = []
        self.free: dict[str, _Free] = {}
        self.mimics: dict[str, tuple[str, float, float]] = {}  # name: (leader, factor, offset)
        for joint in robot.joints:
            if joint.type not in (JointType.REVOLUTE, JointType.CONTINUOUS,
                                  JointType.PRISMATIC):
                continue
            self.names.append(joint.name)
            if joint.mimic is not None and self.options.use_mimic_tags:
                self.mimics[joint.name] = (joint.mimic.joint, joint.mimic.multiplier,
                                           joint.mimic.offset)
                continue
            self.free[joint.name] = self._free_joint(joint)
        self._resolved = {name: self._resolve(name) for name in self.mimics}
        self.version = 0  # changes whenever a value does, so callers can cache a message

    def _free_joint(self, joint) -> _Free:
        continuous = joint.type is JointType.CONTINUOUS
        if continuous or joint.limit is None:
            lower, upper = -math.pi, math.pi
        else:
            lower, upper = joint.limit.lower, joint.limit.upper
        safety = joint.safety_controller
        if safety is not None and self.options.use_smallest_joint_limits and not continuous:
            lower = max(lower, safety.soft_lower_limit)
            upper = min(upper, safety.soft_upper_limit)
        if joint.name in self.options.zeros:  # clamped, as joint_state_publisher does
            zero = float(self.options.zeros[joint.name])
            if not continuous:
                zero = min(max(zero, lower), upper)
        elif lower > 0.0 or upper < 0.0:
            zero = (lower + upper) / 2.0
        else:
            zero = 0.0
        return _Free(lower, upper, continuous, zero)

    def _resolve(self, name: str) -> tuple[str, float, float]:
        """Return the free joint a mimic chain ends at, with the chain's factor and offset."""
        leader, factor, offset = self.mimics[name]
        chain = [name]
        while leader in self.mimics:
            if leader in chain:
                raise UrdfgenpyError('mimic cycle: ' + ' -> '.join([*chain, leader])
                                     + ' (remove one <mimic>)')
            chain.append(leader)
            next_leader, next_factor, next_offset = self.mimics[leader]
            offset += factor * next_offset
            factor *= next_factor
            leader = next_leader
        if leader not in self.free:
            raise UrdfgenpyError(f'joint {name!r} mimics {leader!r}, which is not a movable '
                                 'joint (fix the <mimic joint=...>)')
        return leader, factor, offset

    def clamp(self, name: str, position: float) -> float:
        """Return ``position`` inside the joint's limits (continuous joints are free)."""
        joint = self.free[name]
        if joint.continuous:
            return position
        return min(max(position, joint.lower), joint.upper)

    def merge(self, names: Sequence[str], positions: Sequence[float],
              velocities: Sequence[float], efforts: Sequence[float]) -> list[str]:
        """
        Take values from another JointState; return the names this robot does not know.

        :raises ValueError: when an array's length differs from the names' or holds NaN.
        """
        for label, values in (('position', positions), ('velocity', velocities),
                              ('effort', efforts)):
            if values and len(values) != len(names):
                raise ModelError(f'{len(names)} names but {len(values)} {label} values')
            if any(math.isnan(value) for value in values):
                raise ModelError(f'{label} holds NaN')
        unknown = []
        self.version += 1
        for index, name in enumerate(names):
            joint = self.free.get(name)
            if joint is None:
                if name not in self.mimics:
                    unknown.append(name)
                continue
            if positions:
                joint.position = self.clamp(name, positions[index])
            if velocities:
                joint.velocity = velocities[index]
            if efforts:
                joint.effort = efforts[index]
        return unknown

    def step(self, delta: float) -> None:
        """Move every free joint by ``delta``, bouncing at limits (the ``delta`` option)."""
        self.version += 1
        for joint in self.free.values():
            if joint.forward:
                joint.position += delta
                if joint.position > joint.upper:
                    if joint.continuous:
                        joint.position = joint.lower
                    else:
                        joint.position, joint.forward = joint.upper, False
            else:
                joint.position -= delta
                if joint.position < joint.lower:
                    joint.position, joint.forward = joint.lower, True

    def message_arrays(self) -> tuple[list[str], list[float], list[float], list[float]]:
        """Return names, positions, velocities and efforts as JointState carries them."""
        options = self.options
        positions, velocities, efforts = [], [], []
        for name in self.names:
            joint = self.free.get(name)
            factor, offset = 1.0, 0.0
            if joint is None:
                leader, factor, offset = self._resolved[name]
                joint = self.free[leader]
            positions.append(joint.position * factor + offset)
            velocities.append(joint.velocity * factor)
            efforts.append(joint.effort)
        return (list(self.names),
                positions if options.publish_default_positions or self.mimics else [],
                velocities if options.publish_default_velocities else [],
                efforts if options.publish_default_efforts else [])
