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
The rows of a Denavit-Hartenberg table and its two conventions (see :mod:`urdfgenpy_ros.dh`).

Values only: ``formats.dh_table`` and ``reshape.dh_extract`` build rows from here, and
the table class they are given (``DHTable.from_file`` and ``from_robot`` pass theirs).
"""

from __future__ import annotations

from dataclasses import dataclass, KW_ONLY
from enum import Enum
import math

from urdfgenpy_ros.model.errors import ModelError


JOINT_TYPES = ('revolute', 'continuous', 'prismatic')


class DHConvention(str, Enum):
    """Which Denavit-Hartenberg convention a table uses."""

    STANDARD = 'standard'
    MODIFIED = 'modified'


@dataclass(slots=True)
class DHRow:
    """
    One joint: ``DHRow(joint, a, alpha, d, theta_offset, joint_type)``.

    ``joint`` is a number or a name; lengths in metres, angles in radians. ``joint_type``
    is revolute, continuous (a revolute row without position limits: a wheel) or
    prismatic. Limits are optional (revolute: -pi..pi; prismatic: 0..1 m by default);
    a continuous row whose ``effort`` and ``velocity`` are None has no ``<limit>``.
    """

    joint: int | str
    a: float = 0.0
    alpha: float = 0.0
    d: float = 0.0
    theta_offset: float = 0.0
    joint_type: str = 'revolute'
    _: KW_ONLY
    lower: float | None = None
    upper: float | None = None
    effort: float | None = 100.0
    velocity: float | None = 2.0

    def __post_init__(self) -> None:
        """Check the joint type and coerce numbers."""
        if self.joint_type not in JOINT_TYPES:
            raise ModelError(f'DH row {self.joint!r}: joint_type must be revolute, '
                             f'continuous or prismatic, got {self.joint_type!r}')
        for name in ('a', 'alpha', 'd', 'theta_offset'):
            value = float(getattr(self, name))
            if not math.isfinite(value):
                raise ModelError(f'DH row {self.joint!r}: {name} must be finite')
            setattr(self, name, value)

    @property
    def turns(self) -> bool:
        """Return whether the row's variable is theta (revolute or continuous)."""
        return self.joint_type != 'prismatic'

    @property
    def name(self) -> str:
        """Return the joint name: ``joint_<n>`` for a number, else the name itself."""
        return f'joint_{self.joint}' if isinstance(self.joint, int) else str(self.joint)
