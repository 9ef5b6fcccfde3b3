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
Sensors in MJCF: what Gazebo's ``<sensor>`` elements become in MuJoCo.

They are built in Python, or read from ``<gazebo reference>`` blocks.

A camera becomes a ``<camera>`` looking where Gazebo's does (along the sensor's +X, with +Z
up: MuJoCo's camera looks along its -Z with +Y up, the REP-103 optical frame turned half a
turn about X), its ``fovy`` from the horizontal field of view and the image's aspect. An
IMU becomes a site with accelerometer, gyro and framequat sensors; a force-torque sensor
on a joint a site at the child's frame with force and torque sensors; a lidar one site and
rangefinder per horizontal sample. Other sensor types are findings (M806).
"""

from __future__ import annotations

from dataclasses import dataclass
import math
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.formats.mjcf.bodies import quat
from urdfgenpy_ros.model.floats import fmt, fmt_vec
from urdfgenpy_ros.model.geometry import Origin
from urdfgenpy_ros.model.transforms import from_xyz_rpy, multiply, to_xyz_rpy

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

CAMERAS = ('camera', 'depth_camera', 'depth', 'rgbd_camera', 'wideanglecamera')
LIDARS = ('gpu_lidar', 'lidar', 'ray', 'gpu_ray')
# the sensor frame's axes seen from MuJoCo's camera frame: x_cam = -y, y_cam = z, z_cam = -x
_OPTICAL = [[0.0, 0.0, -1.0, 0.0], [-1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 1.0]]


@dataclass
class Placed:
    """A sensor's SDF element and the body (and joint, for force-torque) it goes on."""

    element: Any
    body: str
    joint: str | None = None


def _sdf_element(sensor: Any) -> Any:
    from urdfgenpy_ros.formats.sdf import sensor_element
    return sensor_element(sensor)


def gather(robot: RobotModel) -> list[Placed]:
    """Return the sensors of ``robot``'s links and joints, in the model's order."""
    found = []
    for link in robot.links:
        elements = [_sdf_element(sensor) for sensor in link.sensors]
        elements += [node for block in link.extensions for node in block.element.iter('sensor')]
        found += [Placed(element, link.name) for element in elements]
    for joint in robot.joints:
        elements = [_sdf_element(sensor) for sensor in joint.sensors]
        elements += [node for block in joint.extensions
                     for node in block.element.iter('sensor')]
        found += [Placed(element, joint.child, joint.name) for element in elements]
    return found


def _pose(element: Any) -> Origin:
    text = element.findtext('pose') or ''
    try:
        numbers = [float(value) for value in text.split()]
    except ValueError:
        numbers = []
    if len(numbers) != 6:
        return Origin()
    return Origin(tuple(numbers[:3]), tuple(numbers[3:]))


def _number(element: Any, path: str, default: float) -> float:
    try:
        return float((element.findtext(path) or '').strip())
    except ValueError:
        return default


def write_sensors(document: Any, worldbody: Any, robot: RobotModel,
                  partly: dict[str, str] | None = None) -> set[str]:
    """
    Add the robot's sensors to the bodies and a ``<sensor>`` section; return their names.

    ``partly`` gets, by sensor name, what of a sensor written was left out.
    """
    bodies = {body.get('name'): body for body in worldbody.iter('body')}
    section = etree.Element('sensor')
    written = set()
    taken = {node.get('name') for node in worldbody.iter('site', 'camera')}
    for placed in gather(robot):
        kind, given = placed.element.get('type', ''), placed.element.get('name', '')
        body = bodies.get(placed.body)
        if body is None or not given:
            continue
        name, number = given, 2  # Gazebo names sensors per link; MJCF per model
        while name in taken:
            name, number = f'{given}_{number}', number + 1
        taken.add(name)
        pose = _pose(placed.element)
        if kind in CAMERAS:
            _camera(body, name, pose, placed.element)
        elif kind == 'imu':
            _site(body, name, pose)
            for what in ('accelerometer', 'gyro'):
                etree.SubElement(section, what, name=f'{name}_{what}', site=name)
            etree.SubElement(section, 'framequat', name=f'{name}_framequat', objtype='site',
                             objname=name)
        elif kind == 'force_torque' and placed.joint is not None:
            _site(body, name, pose)
            for what in ('force', 'torque'):
                etree.SubElement(section, what, name=f'{name}_{what}', site=name)
        elif kind in LIDARS:
            left = _lidar(body, section, name, pose, placed.element)
            if left and partly is not None:
                partly[given] = left
        else:
            continue
        written.add(given)
    if len(section):
        index = list(document).index(worldbody) + 1
        for later in ('equality', 'actuator'):
            found = document.find(later)
            if found is not None:
                index = max(index, list(document).index(found) + 1)
        document.insert(index, section)
    return written


def _site(body: Any, name: str, pose: Origin) -> Any:
    return _first_after_joints(body, 'site', _site_attributes(name, pose))


def _site_attributes(name: str, pose: Origin) -> dict[str, str]:
    attributes = {'name': name}
    if any(pose.xyz):
        attributes['pos'] = fmt_vec(pose.xyz)
    turned = quat(pose)
    if turned is not None:
        attributes['quat'] = turned
    return attributes


def _first_after_joints(body: Any, tag: str, attributes: dict[str, str]) -> Any:
    """Add ``tag`` to ``body`` before its child bodies (MJCF wants no order; readers do)."""
    return _placed(body, etree.Element(tag, attributes), body.find('body'))


def _placed(body: Any, element: Any, before: Any) -> Any:
    """Add ``element`` to ``body`` before its child body ``before`` (None: at the end)."""
    if before is None:
        body.append(element)
    else:
        before.addprevious(element)
    return element


def _camera(body: Any, name: str, pose: Origin, element: Any) -> None:
    turned = multiply(from_xyz_rpy(pose.xyz, pose.rpy), _OPTICAL)
    xyz, rpy = to_xyz_rpy(turned)
    width = _number(element, 'camera/image/width', 640.0)
    height = _number(element, 'camera/image/height', 480.0)
    horizontal = _number(element, 'camera/horizontal_fov', 1.047)
    vertical = 2.0 * math.atan(math.tan(horizontal / 2.0) * height / width)
    attributes = {'name': name, 'pos': fmt_vec(xyz), 'quat': quat(Origin(xyz, rpy)) or '1 0 0 0',
                  'fovy': fmt(math.degrees(vertical)),  # MJCF gives fovy in degrees, always
                  'resolution': f'{int(width)} {int(height)}'}
    _first_after_joints(body, 'camera', attributes)


def _lidar(body: Any, section: Any, name: str, pose: Origin, element: Any) -> str:
    """Write a lidar's horizontal ring of rangefinders; return what was left out, or ''."""
    scan = element.find('lidar') if element.find('lidar') is not None else element.find('ray')
    scan = scan if scan is not None else element
    vertical = int(_number(scan, 'scan/vertical/samples', 1.0))
    samples = int(_number(scan, 'scan/horizontal/samples', 1.0)) or 1
    low = _number(scan, 'scan/horizontal/min_angle', 0.0)
    high = _number(scan, 'scan/horizontal/max_angle', 0.0)
    cutoff = _number(scan, 'range/max', 0.0)
    frame = from_xyz_rpy(pose.xyz, pose.rpy)
    width = len(str(samples - 1))
    before = body.find('body')  # found once: a ring can be a thousand sites
    for index in range(samples):
        angle = low + (high - low) * index / (samples - 1) if samples > 1 else low
        # the ray is the site's +Z: turn +Z onto the sensor's (cos a, sin a, 0)
        ray = multiply(frame, from_xyz_rpy((0.0, 0.0, 0.0), (0.0, math.pi / 2.0, angle)))
        xyz, rpy = to_xyz_rpy(ray)
        site = f'{name}_ray{index:0{width}d}'
        _placed(body, etree.Element('site', _site_attributes(site, Origin(xyz, rpy))), before)
        attributes = {'name': site, 'site': site}
        if cutoff > 0.0:
            attributes['cutoff'] = fmt(cutoff)
        etree.SubElement(section, 'rangefinder', attributes)
    return (f'its {vertical} vertical samples are not carried: one horizontal ring of '
            f'{samples} rangefinders is written' if vertical > 1 else '')
