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
Joint values as MoveIt draws them: the bounds, the default state, random states.

The bounds are MoveIt's (``moveit_core``'s robot model): the ``<limit>``, narrowed by a
``<safety_controller>``'s soft limits where given; continuous joints (and joints without
limits) turn over [-pi, pi]. The default state is 0, or mid-range where 0 is outside the
bounds. Random states are uniform within the bounds; mimic joints follow their leaders
through the forward kinematics (:mod:`urdfgenpy_ros.dynamics`), so only the independent
joints are drawn. Everything comes from one seeded numpy generator: the same seed, the
same states.
"""

from __future__ import annotations

from collections.abc import Mapping
import math
from typing import TYPE_CHECKING

import numpy

from urdfgenpy_ros.dynamics import compiled
from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.joint import Joint, JointType

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

ROUND = 200
"""States per round of the "Always" test (MoveIt's ``SMALL_TRIAL_COUNT``)."""


def joint_bounds(joint: Joint) -> tuple[float, float]:
    """Return the range MoveIt samples ``joint`` over."""
    limit = joint.limit
    if joint.type is JointType.CONTINUOUS or limit is None or limit.lower > limit.upper:
        if joint.type is JointType.PRISMATIC:
            return (0.0, 0.0)
        return (-math.pi, math.pi)
    lower, upper = limit.lower, limit.upper
    safety = joint.safety_controller
    if safety is not None:
        lower, upper = max(lower, safety.soft_lower_limit), min(upper, safety.soft_upper_limit)
    return (lower, upper)


def bounds(robot: RobotModel) -> numpy.ndarray:
    """Return (dof, 2): the range of each of ``robot.movable_joints``."""
    names = compiled(robot).movable
    return numpy.array([joint_bounds(robot.get_joint(name)) for name in names]
                       ).reshape(len(names), 2)


def default_state(robot: RobotModel, values: Mapping[str, float] | None = None) -> numpy.ndarray:
    """
    Return MoveIt's default state over ``robot.movable_joints`` (0, or mid-range).

    ``values`` (a named state, say) replace the defaults of the joints they name.
    """
    names = compiled(robot).movable
    ranges = bounds(robot)
    state = numpy.where((ranges[:, 0] <= 0.0) & (ranges[:, 1] >= 0.0), 0.0,
                        ranges.mean(axis=1))
    for name, value in (values or {}).items():
        if name not in names:
            raise ModelError(f'state names joint {name!r}, which is not a movable joint of '
                             f'{robot.name!r} (one of: {", ".join(names)})')
        state[names.index(name)] = value
    return state


def random_states(ranges: numpy.ndarray, count: int, generator: numpy.random.Generator
                  ) -> numpy.ndarray:
    """Return (count, dof) states drawn uniformly within ``ranges``."""
    low, high = ranges[:, 0], ranges[:, 1]
    return low + generator.random((count, len(ranges))) * (high - low)


def generator(seed: int) -> numpy.random.Generator:
    """Return the generator every state of one computation is drawn from."""
    return numpy.random.default_rng(seed)
