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
Which errors break which consumers: physics findings do not stop a description's display.

robot_state_publisher, RViz and check_urdf read a robot whose masses and tensors are wrong;
physics engines do not. A publisher refuses what breaks its consumers and warns about the
rest, naming the engine that would refuse.
"""

from __future__ import annotations

from urdfgenpy_ros.model.errors import ValidationError

_TENSOR = ('MuJoCo refuses the model and Gazebo refuses the link (libsdformat: '
           '"invalid inertia")')

PHYSICS_ONLY: dict[str, str] = {
    'I201': 'MuJoCo refuses a moving body without mass and Gazebo drops the link',
    'I202': _TENSOR,
    'I203': _TENSOR,
    'I210': 'Gazebo refuses the link (libsdformat: "invalid inertia")',
}
"""Error codes that matter to physics engines only: code to who refuses it."""


def is_physics_only(finding: ValidationError) -> bool:
    """Return whether ``finding`` matters to simulators only (display and TF are unharmed)."""
    return finding.code in PHYSICS_ONLY


def physics_warning(finding: ValidationError) -> str:
    """Return the warning line for a physics-only error: the finding and who would refuse."""
    return (f'{finding} [physics only: {PHYSICS_ONLY[finding.code]}; robot_state_publisher '
            'and RViz read it, so it is published (strict:=true refuses it)]')
