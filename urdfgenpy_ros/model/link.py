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

"""Links and the visuals and collisions they carry."""

from __future__ import annotations

from dataclasses import dataclass, field, KW_ONLY
from typing import TYPE_CHECKING

from urdfgenpy_ros.model import checks
from urdfgenpy_ros.model.errors import ModelTypeError, SourceLocation
from urdfgenpy_ros.model.geometry import Geometry, IDENTITY, Origin
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.lazy_lists import lazy_lists, LazySlots
from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.model.owned_names import own_names
from urdfgenpy_ros.model.preserved import Preserved

if TYPE_CHECKING:
    from urdfgenpy_ros.model.extensions import Extension
    from urdfgenpy_ros.model.sensors import Sensor


@dataclass(slots=True)
class Visual:
    """What a link looks like: a geometry at an origin, optionally named and coloured."""

    geometry: Geometry
    _: KW_ONLY
    origin: Origin = IDENTITY
    material: Material | None = None
    name: str | None = None
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)


@dataclass(slots=True)
class Collision:
    """The shape a physics engine collides: a geometry at an origin, optionally named."""

    geometry: Geometry
    _: KW_ONLY
    origin: Origin = IDENTITY
    name: str | None = None
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)


Shape = Visual | Collision
"""A visual or a collision: a geometry placed at an origin in its link."""


@dataclass(slots=True, init=False)
class Link(LazySlots):
    """
    A rigid body: any number of visuals and collisions, and at most one inertial.

    ``extensions`` are ``<gazebo>`` blocks that refer to this link; writers set their
    ``reference`` to the link's current name.
    """

    name: str
    _: KW_ONLY
    visuals: list[Visual] = field(default_factory=list)
    collisions: list[Collision] = field(default_factory=list)
    inertial: Inertial | None = None
    extensions: list[Extension] = field(default_factory=list)
    sensors: list[Sensor] = field(default_factory=list)
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)
    # the RobotModel holding it (not imported for the type: model.py imports this module)
    _robot: object | None = field(default=None, init=False, compare=False, repr=False)

    def __init__(self, name: str, *, visuals: list[Visual] | None = None,
                 collisions: list[Collision] | None = None, inertial: Inertial | None = None,
                 extensions: list[Extension] | None = None, sensors: list[Sensor] | None = None,
                 source: SourceLocation | None = None, extras: Preserved | None = None) -> None:
        """Check the name; lists not given start empty."""
        if type(name) is not str or not name or name.isspace():
            checks.name('link', name)
        self.name_slot = name  # the slot itself: a new link belongs to no robot yet
        self.visuals = [] if visuals is None else visuals
        self.collisions = [] if collisions is None else collisions
        self.inertial = inertial
        self.extensions_if_any = extensions  # None: made on first use (lazy_lists)
        self.sensors_if_any = sensors
        self.source = source
        self.extras = extras
        self._robot = None

    def add_sensor(self, sensor: Sensor) -> Link:
        """Attach a simulated sensor (Camera, Lidar, Imu) and return the link."""
        sensor.frame = sensor.frame or self.name
        self.sensors.append(sensor)
        return self

    def add_visual(self, visual: Visual) -> Link:
        """Append a visual and return the link, for chaining."""
        if not isinstance(visual, Visual):
            raise ModelTypeError(f'link {self.name!r}: add_visual() takes a Visual, '
                                 f'got {type(visual).__name__}')
        self.visuals.append(visual)
        return self

    def add_collision(self, collision: Collision) -> Link:
        """Append a collision and return the link, for chaining."""
        if not isinstance(collision, Collision):
            raise ModelTypeError(f'link {self.name!r}: add_collision() takes a Collision, '
                                 f'got {type(collision).__name__}')
        self.collisions.append(collision)
        return self

    def set_inertial(self, inertial: Inertial | None) -> Link:
        """Set (or clear, with None) the inertial and return the link."""
        if inertial is not None and not isinstance(inertial, Inertial):
            raise ModelTypeError(f'link {self.name!r}: set_inertial() takes an Inertial, '
                                 f'got {type(inertial).__name__}')
        self.inertial = inertial
        return self

    def add_extension(self, extension: Extension) -> Link:
        """Attach a ``<gazebo>`` block that refers to this link; return the link."""
        self.extensions.append(extension)
        return self

    @property
    def visual(self) -> Visual | None:
        """Return the first visual, or None."""
        return self.visuals[0] if self.visuals else None

    @property
    def collision(self) -> Collision | None:
        """Return the first collision, or None."""
        return self.collisions[0] if self.collisions else None


setattr(Link, 'name_slot', Link.__dict__['name'])  # the slot, also under this name
own_names(Link, 'link')
lazy_lists(Link, 'extensions', 'sensors')
