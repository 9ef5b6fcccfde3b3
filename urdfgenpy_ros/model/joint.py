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

from urdfgenpy_ros.model import checks
from urdfgenpy_ros.model.checks import Vec3
from urdfgenpy_ros.model.edits import counted, edited
from urdfgenpy_ros.model.errors import ModelError, SourceLocation
from urdfgenpy_ros.model.geometry import IDENTITY, Origin
from urdfgenpy_ros.model.lazy_lists import lazy_lists, LazySlots
from urdfgenpy_ros.model.owned_names import own_names
from urdfgenpy_ros.model.preserved import Preserved

if TYPE_CHECKING:
    from urdfgenpy_ros.model.extensions import Extension
    from urdfgenpy_ros.model.sensors import Sensor


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
_ZERO = (0.0, 0.0, 0.0)
_class = type  # Joint.__init__ has a parameter called type


def _hidden() -> Any:
    """Declare a field that equality and repr ignore (source and extras)."""
    return field(default=None, compare=False, repr=False)


@dataclass(slots=True, init=False)
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

    def __init__(self, lower: float = 0.0, upper: float = 0.0, *, effort: float = 0.0,
                 velocity: float = 0.0, acceleration: float | None = None,
                 deceleration: float | None = None, jerk: float | None = None,
                 source: SourceLocation | None = None, extras: Preserved | None = None) -> None:
        """Coerce to floats; reject negative effort, velocity or URDF 1.2 limits."""
        if acceleration is not None:
            acceleration = checks.non_negative('limit', 'acceleration', acceleration, '')
        if deceleration is not None:
            deceleration = checks.non_negative('limit', 'deceleration', deceleration, '')
        if jerk is not None:
            jerk = checks.non_negative('limit', 'jerk', jerk, '')
        try:
            lower, upper, effort, velocity = (float(lower), float(upper), float(effort),
                                              float(velocity))
            good = (lower - lower == 0.0 and upper - upper == 0.0 and 0.0 <= effort < _INF
                    and 0.0 <= velocity < _INF)
        except (TypeError, ValueError):
            good = False
        if not good:
            lower, upper, effort, velocity = checks.numbers(
                'limit', _LIMIT_FIELDS, (lower, upper, effort, velocity))
            if not (effort >= 0.0 and velocity >= 0.0):
                checks.non_negative('limit', 'effort', effort, '(N m or N)')
                checks.non_negative('limit', 'velocity', velocity, '(rad/s or m/s)')
        self.lower = lower
        self.upper = upper
        self.effort = effort
        self.velocity = velocity
        self.acceleration = acceleration
        self.deceleration = deceleration
        self.jerk = jerk
        self.source = source
        self.extras = extras


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


@dataclass(slots=True, init=False)
class Joint(LazySlots):
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
    # the RobotModel holding it (not imported for the type: model.py imports this module)
    _robot: object | None = field(default=None, init=False, compare=False, repr=False)

    def __init__(self, name: str, type: JointType | str,  # noqa: A002
                 parent: str, child: str, *, origin: Origin = IDENTITY,
                 axis: Sequence[float] | None = None, limit: JointLimit | None = None,
                 dynamics: JointDynamics | None = None, mimic: JointMimic | None = None,
                 safety_controller: SafetyController | None = None,
                 calibration: JointCalibration | None = None,
                 extensions: list[Extension] | None = None,
                 sensors: list[Sensor] | None = None,
                 source: SourceLocation | None = None,
                 extras: Preserved | None = None) -> None:
        """Check the name, type and link names; coerce the axis (a type name is accepted)."""
        kind = _TYPES.get(type)
        if kind is None:
            raise ModelError(f'joint {name!r}: unknown type {type!r} (use one of {_TYPE_NAMES})')
        if _class(name) is not str or not name or name.isspace():
            checks.name('joint', name)
        if not (_class(parent) is str and parent and _class(child) is str and child):
            checks.name(f'joint {name!r} parent', parent)
            checks.name(f'joint {name!r} child', child)
        if axis is not None:
            given = axis
            axis = checks.floats3(given)
            if axis is None:
                axis = checks.vec3(f'joint {name!r}', 'axis', given)
            if axis == _ZERO and kind in _ONE_DOF and checks.is_on():
                raise ModelError(f'joint {name!r}: axis must not be zero for a {kind} '
                                 'joint (give the direction of motion, e.g. (0, 0, 1))')
        self.name_slot = name  # the slot itself: a new joint belongs to no robot yet
        self.type_slot = kind  # the slot itself: the type is checked above
        self.parent_slot = parent  # the slots themselves: a new joint is in no robot yet
        self.child_slot = child
        self.origin_slot = origin
        self.axis_slot = axis
        self.limit = limit
        self.dynamics = dynamics
        self.mimic_slot = mimic
        self.safety_controller = safety_controller
        self.calibration = calibration
        self.extensions_if_any = extensions  # None: made on first use (lazy_lists)
        self.sensors_if_any = sensors
        self.source = source
        self.extras = extras
        self._robot = None

    @property
    def is_movable(self) -> bool:
        """Return whether this joint has one degree of freedom (revolute, etc.)."""
        return self.type.is_movable

    @property
    def effective_axis(self) -> Vec3:
        """Return the axis URDF consumers use: the given one or (1, 0, 0)."""
        return self.axis if self.axis is not None else (1.0, 0.0, 0.0)

    if TYPE_CHECKING:
        @property
        def type_slot(self) -> JointType:
            """Return the type's slot, set without coercing (constructors)."""

        @type_slot.setter
        def type_slot(self, value: JointType) -> None:
            """Set the type's slot itself."""

        # the slots of the fields a set of counts as an edit (urdfgenpy_ros.model.edits), set
        # as they are by the constructor: a new joint belongs to no robot yet
        parent_slot: str = ''
        child_slot: str = ''
        origin_slot: Origin = IDENTITY
        axis_slot: Vec3 | None = None
        mimic_slot: JointMimic | None = None

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
        edited()


setattr(Joint, 'type_slot', Joint.__dict__['type'])
Joint.type = _TypeField(Joint.__dict__['type'])  # type: ignore[assignment]
setattr(Joint, 'name_slot', Joint.__dict__['name'])  # the slot, also under this name
own_names(Joint, 'joint')
lazy_lists(Joint, 'extensions', 'sensors')
counted(Joint, 'parent', 'child', 'origin', 'axis', 'mimic')  # kinematics caches see edits
