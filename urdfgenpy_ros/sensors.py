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
Simulated sensors: ``Camera``, ``Lidar``, ``Imu``, ``ForceTorque``.

Attach with ``link.add_sensor(...)`` (``joint.add_sensor`` for a force-torque sensor). The
URDF gets a ``<gazebo reference="...">`` block holding the SDF ``<sensor>`` that Gazebo
reads; SDF gets the ``<sensor>`` itself. ``topic`` defaults to the sensor's name and
``gz_frame_id`` to the link's, so the messages are stamped with a frame that TF knows.
"""

from __future__ import annotations

from dataclasses import dataclass, field, KW_ONLY
import math
from typing import Any

from lxml import etree

from urdfgenpy_ros.formats._xml import fmt, fmt_vec
from urdfgenpy_ros.geometry import Origin


def _add(parent: Any, tag: str, value: object) -> Any:
    element = etree.SubElement(parent, tag)
    element.text = fmt(value) if isinstance(value, float) else str(value)
    return element


@dataclass(slots=True)
class Sensor:
    """What every sensor has: a name, a pose on its link, a rate and a topic."""

    name: str
    _: KW_ONLY
    origin: Origin = field(default_factory=Origin)
    update_rate: float = 30.0
    topic: str | None = None
    always_on: bool = True
    visualize: bool = False
    frame: str | None = None  # set by add_sensor: the link (or joint) it is attached to

    kind = 'sensor'

    def to_sdf(self) -> Any:
        """Return the SDF ``<sensor>`` element."""
        element = etree.Element('sensor', name=self.name, type=self.kind)
        if not self.origin.is_identity:
            _add(element, 'pose', f'{fmt_vec(self.origin.xyz)} {fmt_vec(self.origin.rpy)}')
        _add(element, 'always_on', 'true' if self.always_on else 'false')
        _add(element, 'update_rate', float(self.update_rate))
        _add(element, 'visualize', 'true' if self.visualize else 'false')
        _add(element, 'topic', self.topic or self.name)
        if self.frame:
            _add(element, 'gz_frame_id', self.frame)
        self._body(element)
        return element

    def _body(self, element: Any) -> None:
        """Add the type-specific part."""


@dataclass(slots=True)
class Camera(Sensor):
    """An RGB camera: ``fov`` (horizontal, rad), image size and clip distances."""

    fps: float = 30.0
    width: int = 640
    height: int = 480
    fov: float = 1.047
    near: float = 0.05
    far: float = 100.0
    image_format: str = 'R8G8B8'

    kind = 'camera'

    def __post_init__(self) -> None:
        """Take the rate from ``fps``."""
        self.update_rate = self.fps

    def _body(self, element: Any) -> None:
        camera = etree.SubElement(element, 'camera')
        _add(camera, 'horizontal_fov', float(self.fov))
        image = etree.SubElement(camera, 'image')
        _add(image, 'width', int(self.width))
        _add(image, 'height', int(self.height))
        _add(image, 'format', self.image_format)
        clip = etree.SubElement(camera, 'clip')
        _add(clip, 'near', float(self.near))
        _add(clip, 'far', float(self.far))


@dataclass(slots=True)
class Lidar(Sensor):
    """A scanning range finder (Gazebo's ``gpu_lidar``)."""

    samples: int = 360
    min_angle: float = -math.pi
    max_angle: float = math.pi
    vertical_samples: int = 1
    range_min: float = 0.1
    range_max: float = 10.0
    resolution: float = 0.01
    update_rate: float = 10.0

    kind = 'gpu_lidar'

    def _body(self, element: Any) -> None:
        lidar = etree.SubElement(element, 'lidar')
        scan = etree.SubElement(lidar, 'scan')
        horizontal = etree.SubElement(scan, 'horizontal')
        _add(horizontal, 'samples', int(self.samples))
        _add(horizontal, 'resolution', 1.0)
        _add(horizontal, 'min_angle', float(self.min_angle))
        _add(horizontal, 'max_angle', float(self.max_angle))
        vertical = etree.SubElement(scan, 'vertical')
        _add(vertical, 'samples', int(self.vertical_samples))
        _add(vertical, 'resolution', 1.0)
        _add(vertical, 'min_angle', 0.0)
        _add(vertical, 'max_angle', 0.0)
        ranges = etree.SubElement(lidar, 'range')
        _add(ranges, 'min', float(self.range_min))
        _add(ranges, 'max', float(self.range_max))
        _add(ranges, 'resolution', float(self.resolution))


@dataclass(slots=True)
class Imu(Sensor):
    """An inertial measurement unit."""

    update_rate: float = 100.0

    kind = 'imu'


@dataclass(slots=True)
class ForceTorque(Sensor):
    """A force-torque sensor in a joint, measuring in the ``child`` (or ``parent``) frame."""

    measure_frame: str = 'child'
    measure_direction: str = 'child_to_parent'
    update_rate: float = 100.0

    kind = 'force_torque'

    def _body(self, element: Any) -> None:
        sensor = etree.SubElement(element, 'force_torque')
        _add(sensor, 'frame', self.measure_frame)
        _add(sensor, 'measure_direction', self.measure_direction)
