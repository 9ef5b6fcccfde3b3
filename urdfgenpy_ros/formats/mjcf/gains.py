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
Servo gains: one default and per-joint values.

``kp=2000`` or ``kp={'default': 2000, 'wrist_3_joint': 500}`` in Python; on the command
line ``--kp 2000 --kp wrist_3_joint=500``.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
import math
from typing import Union

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.floats import fmt

DEFAULT = 'default'
"""The key of a gain mapping that sets every joint not named in it."""

GainOption = Union[float, Mapping[str, float], None]
"""What ``kp``/``kv`` take: a number, a mapping of joint names (and ``'default'``), None."""


def gain_ok(gain: float, positive: bool) -> bool:
    """Return whether ``gain`` is a finite number above zero (or zero when not ``positive``)."""
    return math.isfinite(gain) and (gain > 0.0 if positive else gain >= 0.0)


def _least(positive: bool) -> str:
    return 'above zero' if positive else 'zero or more'


@dataclass(frozen=True)
class Gains:
    """A servo gain: the ``default`` (None: not given) and the joints given their own."""

    option: str  # kp or kv
    default: float | None = None
    joints: Mapping[str, float] = field(default_factory=dict)

    @classmethod
    def of(cls, option: str, value: GainOption, positive: bool) -> Gains:
        """
        Return the gains ``value`` gives (a number, a mapping, or None).

        :raises ModelError: for a gain that is not a finite number (``positive``: above
            zero; else zero or more), or a mapping key that is not a string.
        """
        if value is None:
            return cls(option)
        if isinstance(value, Mapping):
            given = dict(value)
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            given = {DEFAULT: value}
        else:
            raise ModelError(f'{option}={value!r}: give a number, or a mapping of joint names '
                             f"(and {DEFAULT!r}) to numbers, e.g. {{'{DEFAULT}': 2000, "
                             "'wrist_3_joint': 500}")
        checked: dict[str, float] = {}
        for name, gain in given.items():
            if not isinstance(name, str) or isinstance(gain, bool) \
                    or not isinstance(gain, (int, float)) or not gain_ok(gain, positive):
                where = option if name == DEFAULT else f'{option}[{name!r}]'
                raise ModelError(f'{where}={gain!r}: a servo gain is a finite number, '
                                 f'{_least(positive)} (N/m or Nm/rad per unit of error)')
            checked[name] = float(gain)
        default = checked.pop(DEFAULT, None)
        return cls(option, default, checked)

    @property
    def given(self) -> bool:
        """Whether any gain was given."""
        return self.default is not None or bool(self.joints)

    def of_joint(self, joint: str) -> float | None:
        """Return the gain of ``joint``: its own, else the default (None: neither)."""
        return self.joints.get(joint, self.default)

    def check_joints(self, known: Iterable[str], actuated: Iterable[str]) -> list[str]:
        """
        Refuse a joint the robot does not have; return notes for given gains left unused.

        :raises ModelError: naming the unknown joint and the actuated ones.
        """
        known_names, actuated_names = set(known), set(actuated)
        for name in self.joints:
            if name not in known_names:
                listed = ', '.join(sorted(actuated_names)) or 'none'
                raise ModelError(f'{self.option}[{name!r}]: the robot has no joint {name!r} '
                                 f'(actuated joints: {listed})')
        return [f'{self.option} for joint {name!r} unused: it has no actuator that takes '
                f'{self.option}' for name in self.joints if name not in actuated_names]

    def describe(self, fallback: float) -> str:
        """Return the gains as a note says them: ``2000 (given), wrist_3_joint 500``."""
        default = (f'{fmt(self.default)} (given)' if self.default is not None
                   else f"{fmt(fallback)} (MuJoCo's default: set {self.option}= / "
                        f'--{self.option})')
        return ', '.join([default] + [f'{name} {fmt(value)}'
                                      for name, value in sorted(self.joints.items())])


def parse_gain_words(option: str, words: Iterable[str], positive: bool) -> GainOption:
    """
    Return the gains of ``--kp 2000 --kp wrist_3_joint=500`` (None when none was given).

    :raises ModelError: for a word that is not ``NUMBER`` or ``JOINT=NUMBER``, or a
        default given twice.
    """
    given: dict[str, float] = {}
    for word in words:
        name, _, number = word.rpartition('=')
        key = name.strip() if name else DEFAULT
        if name and not key:
            raise ModelError(f'--{option} {word!r}: give NUMBER or JOINT=NUMBER')
        try:
            value = float(number)
        except ValueError:
            raise ModelError(f'--{option} {word!r}: give NUMBER or JOINT=NUMBER '
                             f'(e.g. --{option} 2000 --{option} wrist_3_joint=500)') from None
        if key in given:
            said = 'the default' if key == DEFAULT else f'joint {key!r}'
            raise ModelError(f'--{option} gives {said} twice: give it once')
        if not gain_ok(value, positive):
            raise ModelError(f'--{option} {word!r}: a finite number {_least(positive)}')
        given[key] = value
    if not given:
        return None
    if set(given) == {DEFAULT}:
        return given[DEFAULT]
    return given
