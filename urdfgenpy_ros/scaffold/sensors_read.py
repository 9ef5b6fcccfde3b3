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
The sensors a package is scaffolded for: built ones and those read back from a file.

A robot built in Python holds ``Camera``/``Lidar``/``Imu``/``ForceTorque`` objects; the
same robot saved and read again holds ``<gazebo reference="..."><sensor>`` blocks instead.
Both give the same list here, so the bridge, launch and RViz files do not depend on how
the robot reached ``urdfgenpy init``.
"""

from __future__ import annotations

from typing import Any, NamedTuple

from urdfgenpy_ros.robot import Robot


class SensorInfo(NamedTuple):
    """What the scaffold needs of a sensor: its name, SDF type, topic and frame."""

    name: str
    kind: str
    topic: str
    frame: str | None


def _built(sensor: Any, owner: str) -> SensorInfo:
    return SensorInfo(sensor.name, sensor.kind, sensor.topic or sensor.name,
                      sensor.frame or owner)


def _from_block(block: Any, owner: str | None) -> list[SensorInfo]:
    """Return the sensors of one ``<gazebo>`` extension block."""
    if getattr(block, 'tag', None) != 'gazebo':
        return []
    found = []
    for element in block.element.iter('sensor'):
        name = element.get('name') or ''
        topic = (element.findtext('topic') or '').strip() or name
        frame = (element.findtext('gz_frame_id') or '').strip() or owner
        found.append(SensorInfo(name, element.get('type') or '', topic, frame))
    return found


def sensors_of(robot: Robot) -> list[SensorInfo]:
    """Return every sensor of ``robot``, built or read from ``<gazebo>`` blocks, in order."""
    found: list[SensorInfo] = []
    owners: list[Any] = [*robot.links, *robot.joints]
    for owner in owners:
        found += [_built(sensor, owner.name) for sensor in owner.sensors]
        for block in owner.extensions:
            found += _from_block(block, owner.name)
    for block in robot.extensions:
        found += _from_block(block, getattr(block, 'reference', None))
    unique: dict[str, SensorInfo] = {}
    for sensor in found:  # a sensor both built and present as a block counts once
        unique.setdefault(sensor.name, sensor)
    return list(unique.values())
