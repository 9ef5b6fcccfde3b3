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


"""Friction from ``<gazebo reference="LINK">`` ``mu1``/``mu2``: the link's collision geoms'."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.floats import fmt

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

TORSION_ROLLING = '0.005 0.0001'  # MuJoCo's defaults for the other two coefficients


@dataclass
class Friction:
    """A link's friction: MuJoCo's ``friction`` text, whether mu2 fits it, the block."""

    text: str
    isotropic: bool
    element: Any


def declared_friction(robot: RobotModel) -> dict[str, Friction]:
    """Return the friction each link's ``<gazebo reference>`` block gives, by link."""
    found: dict[str, Friction] = {}
    blocks = [*robot.extensions, *(block for link in robot.links for block in link.extensions)]
    for block in blocks:
        reference = block.reference
        if block.tag != 'gazebo' or reference is None or not robot.has_link(reference):
            continue
        mu = block.element.findtext('mu1') or block.element.findtext('mu2')
        if mu is None:
            continue
        try:
            value = float(mu.strip())
        except ValueError:
            continue
        mu2 = block.element.findtext('mu2')
        found[reference] = Friction(f'{fmt(value)} {TORSION_ROLLING}',
                                    mu2 is None or mu2.strip() == mu.strip(), block.element)
    return found
