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

"""Joints between links and their limits, dynamics, mimic and calibration."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, KW_ONLY
from enum import Enum
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros import checks
from urdfgenpy_ros.checks import Vec3
from urdfgenpy_ros.errors import ModelError, SourceLocation
from urdfgenpy_ros.geometry import IDENTITY, Origin
from urdfgenpy_ros.owned_names import own_names
from urdfgenpy_ros.preserved import Preserved

if TYPE_CHECKING:
    from urdfgenpy_ros.extensions import Extension
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.sensors import Sensor


class JointType(str, Enum):
    """The six joint types of URDF."""

    REVOLUTE = 'revolute'
    CONTINUOUS = 'continuous'
    PRISMATIC = 'prismatic'
    FIXED = 'fixed'
    FLOATING = 'floating'
    PLANAR = 'planar'

    def __str__(self) -> str:
        """Return the URDF spelling."""
        return self.value

    @property
    def is_movable(self) -> bool:
        """Return whether joint_states carries a position for this type."""
        return self in _ONE_DOF

    @property
    def needs_limit(self) -> bool:
        """Return whether URDF requires a ``<limit>`` for this type."""
        return self in (JointType.REVOLUTE, JointType.PRISMATIC)


_ONE_DOF = frozenset((JointType.REVOLUTE, JointType.CONTINUOUS, JointType.PRISMATIC))
_TYPES: dict[object, JointType] = {**{t.value: t for t in JointType}, **{t: t for t in JointType}}
_LIMIT_FIELDS = ('lower', 'upper', 'effort', 'velocity')
_LIMITS_1_2 = ('acceleration', 'deceleration', 'jerk')
_INF = float('inf')
_TYPE_NAMES = ', '.join(t.value for t in JointType)


def _hidden() -> Any:
    """Declare a field that equality and repr ignore (source and extras)."""
    return field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class JointLimit:
    """Position range (rad or m), maximal ``effort`` (N m or N) and ``velocity``."""

    lower: float = 0.0
    upper: float = 0.0
    _: KW_ONLY
    effort: float = 0.0
    velocity: float = 0.0
    acceleration: float | None = None  # URDF 1.2: the joint's largest acceleration
    deceleration: float | None = None  # URDF 1.2: its largest deceleration
    jerk: float | None = None  # URDF 1.2: its largest jerk
    source: SourceLocation | None = _hidden()
    extras: Preserved | None = _hidden()

    def __post_init__(self) -> None:
        """Coerce to floats; reject negative effort, velocity or URDF 1.2 limits."""
        for name in _LIMITS_1_2:
            value = getattr(self, name)
            if value is not None:
                setattr(self, name, checks.non_negative('limit', name, value, ''))
        try:
            lower, upper = self.lower, self.upper = float(self.lower), float(self.upper)
            effort, velocity = self.effort, self.velocity = (float(self.effort),
                                                             float(self.velocity))
            if (lower - lower == 0.0 and upper - upper == 0.0 and 0.0 <= effort < _INF
                    and 0.0 <= velocity < _INF):
                return
        except (TypeError, ValueError):
            pass
        self.lower, self.upper, self.effort, self.velocity = checks.numbers(
            'limit', _LIMIT_FIELDS, (self.lower, self.upper, self.effort, self.velocity))
        if not (self.effort >= 0.0 and self.velocity >= 0.0):
            checks.non_negative('limit', 'effort', self.effort, '(N m or N)')
            checks.non_negative('limit', 'velocity', self.velocity, '(rad/s or m/s)')


@dataclass(slots=True)
class JointDynamics:
    """Viscous ``damping`` and static ``friction`` of a joint."""

    damping: float = 0.0
    friction: float = 0.0
    _: KW_ONLY
    source: SourceLocation | None = _hidden()
    extras: Preserved | None = _hidden()

    def __post_init__(self) -> None:
        """Coerce to floats."""
        self.damping = checks.finite('dynamics', 'damping', self.damping)
        self.friction = checks.finite('dynamics', 'friction', self.friction)


@dataclass(slots=True)
class JointMimic:
    """This joint follows ``joint``: value = multiplier * leader + offset."""

    joint: str
    multiplier: float = 1.0
    offset: float = 0.0
    _: KW_ONLY
    source: SourceLocation | None = _hidden()
    extras: Preserved | None = _hidden()

    def __post_init__(self) -> None:
        """Check the leader's name and coerce the factors."""
        checks.name('mimic', self.joint)
        self.multiplier = checks.finite('mimic', 'multiplier', self.multiplier)
        self.offset = checks.finite('mimic', 'offset', self.offset)


@dataclass(slots=True)
class SafetyController:
    """Soft limits and the gains that enforce them (``<safety_controller>``)."""

    soft_lower_limit: float = 0.0
    soft_upper_limit: float = 0.0
    k_position: float = 0.0
    k_velocity: float = 0.0
    _: KW_ONLY
    source: SourceLocation | None = _hidden()
    extras: Preserved | None = _hidden()

    def __post_init__(self) -> None:
        """Coerce to floats."""
        for attr in ('soft_lower_limit', 'soft_upper_limit', 'k_position', 'k_velocity'):
            setattr(self, attr, checks.finite('safety_controller', attr, getattr(self, attr)))


@dataclass(slots=True)
class JointCalibration:
    """Reference positions where a ``rising`` or ``falling`` edge triggers."""

    rising: float | None = None
    falling: float | None = None
    _: KW_ONLY
    source: SourceLocation | None = _hidden()
    extras: Preserved | None = _hidden()

    def __post_init__(self) -> None:
        """Coerce the given edges to floats."""
        if self.rising is not None:
            self.rising = checks.finite('calibration', 'rising', self.rising)
        if self.falling is not None:
            self.falling = checks.finite('calibration', 'falling', self.falling)


@dataclass(slots=True)
class Joint:
    """
    A joint from ``parent`` to ``child`` link, placed at ``origin`` in the parent.

    ``axis`` is None when not given (URDF then uses (1, 0, 0)); ``extensions`` are
    ``<gazebo>`` or ``<transmission>`` blocks that belong to this joint.
    """

    name: str
    type: JointType  # noqa: A003
    parent: str
    child: str
    _: KW_ONLY
    origin: Origin = IDENTITY
    axis: Vec3 | None = None
    limit: JointLimit | None = None
    dynamics: JointDynamics | None = None
    mimic: JointMimic | None = None
    safety_controller: SafetyController | None = None
    calibration: JointCalibration | None = None
    extensions: list[Extension] = field(default_factory=list)
    sensors: list[Sensor] = field(default_factory=list)
    source: SourceLocation | None = _hidden()
    extras: Preserved | None = _hidden()
    _robot: RobotModel | None = field(default=None, init=False, compare=False, repr=False)

    if TYPE_CHECKING:
        # The generated __init__ accepts a type name too ('revolute'); say so to checkers.
        def __init__(self, name: str, type: JointType | str,  # noqa: A002
                     parent: str, child: str, *, origin: Origin = IDENTITY,
                     axis: Sequence[float] | None = None, limit: JointLimit | None = None,
                     dynamics: JointDynamics | None = None, mimic: JointMimic | None = None,
                     safety_controller: SafetyController | None = None,
                     calibration: JointCalibration | None = None,
                     extensions: list[Extension] = ...,
                     sensors: list[Sensor] = ...,
                     source: SourceLocation | None = None,
                     extras: Preserved | None = None) -> None: ...

    def __post_init__(self) -> None:
        """Check the name and type; coerce the axis."""
        checks.name('joint', self.name)
        kind = self.type  # a JointType: the field coerces what is set (_TypeField)
        if not (type(self.parent) is str and self.parent and type(self.child) is str
                and self.child):
            checks.name(f'joint {self.name!r} parent', self.parent)
            checks.name(f'joint {self.name!r} child', self.child)
        if self.axis is not None:
            self.axis = checks.vec3(f'joint {self.name!r}', 'axis', self.axis)
            if self.axis == (0.0, 0.0, 0.0) and kind in _ONE_DOF and checks.enabled():
                raise ModelError(f'joint {self.name!r}: axis must not be zero for a {kind} '
                                 'joint (give the direction of motion, e.g. (0, 0, 1))')

    @property
    def is_movable(self) -> bool:
        """Return whether this joint has one degree of freedom (revolute, etc.)."""
        return self.type.is_movable

    @property
    def effective_axis(self) -> Vec3:
        """Return the axis URDF consumers use: the given one or (1, 0, 0)."""
        return self.axis if self.axis is not None else (1.0, 0.0, 0.0)

    def add_sensor(self, sensor: Sensor) -> Joint:
        """Attach a sensor that lives in a joint (ForceTorque) and return the joint."""
        self.sensors.append(sensor)
        return self

    def add_extension(self, extension: Extension) -> Joint:
        """Attach a block that belongs to this joint; return the joint."""
        self.extensions.append(extension)
        return self


class _TypeField:
    """
    ``Joint.type``: a type name set (``joint.type = 'fixed'``) is stored as its JointType.

    An unknown name fails where it is set, naming the joint, as in the constructor.
    """

    def __init__(self, slot: Any) -> None:
        self._get = slot.__get__
        self._set = slot.__set__

    def __get__(self, joint: Joint | None, owner: type | None = None) -> Any:
        return self if joint is None else self._get(joint, owner)

    def __set__(self, joint: Joint, value: object) -> None:
        kind = value if type(value) is JointType else _TYPES.get(value)
        if kind is None:
            raise ModelError(f'joint {joint.name!r}: unknown type {value!r} '
                             f'(use one of {_TYPE_NAMES})')
        self._set(joint, kind)


Joint.type = _TypeField(Joint.__dict__['type'])  # type: ignore[assignment,misc]
own_names(Joint, 'joint')
