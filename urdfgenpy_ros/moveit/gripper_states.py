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
A gripper's ``open`` and ``close`` from its geometry, not from which limit is the upper.

The finger tips are the leaf links of the gripper group, each at the centre of its
collision geometry (else its frame). With the gripper's joints at their lower and then at
their upper limits (mimic joints following, :meth:`Robot.fk`), the limit where the tips
lie farther apart is ``open``: the Robotiq 2F-85 opens at 0, its lower limit. With fewer
than two tips, or the same spread at both, the upper limit is ``open`` and a note says so.
"""

from __future__ import annotations

from itertools import combinations
from typing import TYPE_CHECKING

import numpy

from urdfgenpy_ros.dynamics import fk

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

SAME = 1e-6  # metres: spreads closer than this cannot tell open from closed


def finger_tips(robot: RobotModel, links: tuple[str, ...]) -> list[tuple[str, numpy.ndarray]]:
    """Return each leaf link of ``links`` with its point (collision centre, else frame)."""
    tips = []
    for name in links:
        if list(robot.child_joints(name)):
            continue
        link = robot.get_link(name)
        centres = [collision.origin.xyz for collision in link.collisions
                   if collision.origin is not None] or [(0.0, 0.0, 0.0)]
        tips.append((name, numpy.append(numpy.mean(centres, axis=0), 1.0)))
    return tips


def spread(robot: RobotModel, tips: list[tuple[str, numpy.ndarray]],
           values: dict[str, float]) -> float:
    """Return the sum of the distances between the tips with the joints at ``values``."""
    poses = fk(robot, values)
    points = [(poses[name] @ point)[:3] for name, point in tips]
    return float(sum(numpy.linalg.norm(one - two) for one, two in combinations(points, 2)))


def opens_at_upper(robot: RobotModel, name: str, links: tuple[str, ...],
                   ranges: dict[str, tuple[float, float]]) -> tuple[bool, str | None]:
    """Return whether gripper ``name`` opens at its upper limits, and a note if guessed."""
    tips = finger_tips(robot, links)
    if len(tips) >= 2:
        low = spread(robot, tips, {joint: bounds[0] for joint, bounds in ranges.items()})
        high = spread(robot, tips, {joint: bounds[1] for joint, bounds in ranges.items()})
        if abs(high - low) > SAME:
            return high > low, None
        why = 'its finger tips are as far apart at both limits'
    else:
        why = 'it has one finger tip (leaf link)'
    return True, (f'gripper {name!r}: {why}: open is taken at the upper limits '
                  '(check the open and close states)')
