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
reads; SDF gets the ``<sensor>`` itself (both made by :mod:`urdfgenpy_ros.formats.sdf`).
``topic`` defaults to the sensor's name and ``gz_frame_id`` to the link's, so the
messages are stamped with a frame that TF knows.
"""

from __future__ import annotations

from dataclasses import dataclass, field, KW_ONLY
import math

from urdfgenpy_ros.model.geometry import Origin


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
