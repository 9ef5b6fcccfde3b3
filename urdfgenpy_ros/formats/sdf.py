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
SDF writer (1.9, or 1.11 for mimic joints): a ``<model>`` as SDFormat's URDF conversion makes it.

Frames follow SDFormat's own URDF conversion: each joint's pose is given relative to its
parent link, and each child link sits at its joint, so the axis is expressed in the joint
frame exactly as in URDF. Floating joints become free links posed at their origin. A link
without mass on a fixed joint (every link on one, with ``lump_fixed``) is merged into its
parent and leaves ``<frame>`` elements (:mod:`.sdf_frames`). Sensors on links are written
natively; ``<gazebo>`` blocks go where libsdformat puts them (:mod:`.sdf_gazebo`); mimic
joints are 1.11's ``<mimic>`` (:mod:`.sdf_mimic`). A joint named like a link (URDF allows
it, SDF does not) gets ``_joint`` appended. What the SDF cannot carry is a warning, one line
each.
"""

from __future__ import annotations

from os import PathLike
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.caller import warn_caller
from urdfgenpy_ros.formats._xml import robot_name, write_text
from urdfgenpy_ros.formats.sdf_frames import merge_for_sdf, Merged
from urdfgenpy_ros.formats.sdf_gazebo import (
    apply_blocks, apply_shape_blocks, gazebo_losses, script_notes)
from urdfgenpy_ros.formats.sdf_mimic import Follow, follows, mimic_notes, MIMIC_VERSION
from urdfgenpy_ros.formats.sdf_mimic import sdf_version
from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.floats import fmt, fmt_vec
from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, Geometry, Mesh, Origin, Sphere
from urdfgenpy_ros.model.joint import Joint, JointType
from urdfgenpy_ros.model.link import Link, Visual
from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.model.sensors import Camera, ForceTorque, Lidar, Sensor
from urdfgenpy_ros.reshape.lumping import WORLD

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

_TYPES = {JointType.REVOLUTE: 'revolute', JointType.CONTINUOUS: 'continuous',
          JointType.PRISMATIC: 'prismatic', JointType.FIXED: 'fixed'}


def _text(parent: Any, tag: str, text: str, **attributes: str) -> Any:
    element = etree.SubElement(parent, tag, attributes)
    element.text = text
    return element


def _pose(parent: Any, origin: Origin, relative_to: str | None = None) -> None:
    if origin.is_identity and relative_to is None:
        return
    attributes = {'relative_to': relative_to} if relative_to else {}
    _text(parent, 'pose', f'{fmt_vec(origin.xyz)} {fmt_vec(origin.rpy)}', **attributes)


def _geometry(parent: Any, geometry: Geometry) -> None:
    holder = etree.SubElement(parent, 'geometry')
    if isinstance(geometry, Box):
        _text(etree.SubElement(holder, 'box'), 'size', fmt_vec(geometry.size))
    elif isinstance(geometry, Cylinder):
        shape = etree.SubElement(holder, 'cylinder')
        _text(shape, 'radius', fmt(geometry.radius))
        _text(shape, 'length', fmt(geometry.length))
    elif isinstance(geometry, Sphere):
        _text(etree.SubElement(holder, 'sphere'), 'radius', fmt(geometry.radius))
    elif isinstance(geometry, Capsule):  # SDF 1.8+: length is the cylinder's, as in URDF
        shape = etree.SubElement(holder, 'capsule')
        _text(shape, 'radius', fmt(geometry.radius))
        _text(shape, 'length', fmt(geometry.length))
    elif isinstance(geometry, Mesh):
        shape = etree.SubElement(holder, 'mesh')
        _text(shape, 'uri', geometry.filename)
        if geometry.scale is not None:
            _text(shape, 'scale', fmt_vec(geometry.scale))


def _material(parent: Any, material: Material | None, robot: RobotModel) -> None:
    if material is None:
        return
    rgba = material.rgba
    if rgba is None and robot.has_material(material.name):
        rgba = robot.get_material(material.name).rgba
    if rgba is None:
        return
    element = etree.SubElement(parent, 'material')
    for tag in ('ambient', 'diffuse'):
        _text(element, tag, fmt_vec(rgba))


def _add(parent: Any, tag: str, value: object) -> Any:
    element = etree.SubElement(parent, tag)
    element.text = fmt(value) if isinstance(value, float) else str(value)
    return element


def sensor_element(sensor: Sensor) -> Any:
    """Return the SDF ``<sensor>`` element of a sensor (URDF carries it in ``<gazebo>``)."""
    element = etree.Element('sensor', name=sensor.name, type=sensor.kind)
    if not sensor.origin.is_identity:
        _add(element, 'pose', f'{fmt_vec(sensor.origin.xyz)} {fmt_vec(sensor.origin.rpy)}')
    _add(element, 'always_on', 'true' if sensor.always_on else 'false')
    _add(element, 'update_rate', float(sensor.update_rate))
    _add(element, 'visualize', 'true' if sensor.visualize else 'false')
    _add(element, 'topic', sensor.topic or sensor.name)
    if sensor.frame:
        _add(element, 'gz_frame_id', sensor.frame)
    if isinstance(sensor, Camera):
        camera = etree.SubElement(element, 'camera')
        _add(camera, 'horizontal_fov', float(sensor.fov))
        image = etree.SubElement(camera, 'image')
        _add(image, 'width', int(sensor.width))
        _add(image, 'height', int(sensor.height))
        _add(image, 'format', sensor.image_format)
        clip = etree.SubElement(camera, 'clip')
        _add(clip, 'near', float(sensor.near))
        _add(clip, 'far', float(sensor.far))
    elif isinstance(sensor, Lidar):
        lidar = etree.SubElement(element, 'lidar')
        scan = etree.SubElement(lidar, 'scan')
        horizontal = etree.SubElement(scan, 'horizontal')
        _add(horizontal, 'samples', int(sensor.samples))
        _add(horizontal, 'resolution', 1.0)
        _add(horizontal, 'min_angle', float(sensor.min_angle))
        _add(horizontal, 'max_angle', float(sensor.max_angle))
        vertical = etree.SubElement(scan, 'vertical')
        _add(vertical, 'samples', int(sensor.vertical_samples))
        _add(vertical, 'resolution', 1.0)
        _add(vertical, 'min_angle', 0.0)
        _add(vertical, 'max_angle', 0.0)
        ranges = etree.SubElement(lidar, 'range')
        _add(ranges, 'min', float(sensor.range_min))
        _add(ranges, 'max', float(sensor.range_max))
        _add(ranges, 'resolution', float(sensor.resolution))
    elif isinstance(sensor, ForceTorque):
        torque = etree.SubElement(element, 'force_torque')
        _add(torque, 'frame', sensor.measure_frame)
        _add(torque, 'measure_direction', sensor.measure_direction)
    return element


def _unique(name: str, taken: set[str]) -> str:
    candidate, number = name, 1
    while candidate in taken:
        candidate, number = f'{name}_{number}', number + 1
    taken.add(candidate)
    return candidate


def _link(model: Any, link: Link, robot: RobotModel, pose: tuple[Origin, str] | None) -> Any:
    element = etree.SubElement(model, 'link', name=link.name)
    if pose is not None:
        _pose(element, pose[0], pose[1])
    inertial = link.inertial
    if inertial is not None:
        block = etree.SubElement(element, 'inertial')
        _pose(block, inertial.origin)
        _text(block, 'mass', fmt(inertial.mass))
        tensor = etree.SubElement(block, 'inertia')
        for name in ('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz'):
            _text(tensor, name, fmt(getattr(inertial, name)))
    blocks = [block for block in link.extensions if block.tag == 'gazebo']
    taken: set[str] = set()
    for kind, items in (('collision', link.collisions), ('visual', link.visuals)):
        for item in items:
            shape = etree.SubElement(element, kind,
                                     name=_unique(item.name or f'{link.name}_{kind}', taken))
            _pose(shape, item.origin)
            _geometry(shape, item.geometry)
            if isinstance(item, Visual):
                _material(shape, item.material, robot)
            apply_shape_blocks(shape, blocks, kind, link.name, item.name)
    for sensor in link.sensors:
        element.append(sensor_element(sensor))
    apply_blocks(element, blocks, 'link', link.name)
    return element


def _fixed_to_world(robot: RobotModel) -> bool:
    """
    Return whether the robot's root is URDF's ``world`` link, an empty frame.

    SDFormat's conversion does not make it a link (SDF reserves the name): its joints fix
    the model to the world frame. A ``world`` link with a body is refused.
    """
    if not robot.has_link(WORLD) or robot.parent_joint(WORLD) is not None:
        return False
    world = robot.get_link(WORLD)
    if world.inertial is not None or world.visuals or world.collisions or world.sensors:
        raise ModelError("link 'world' has a body, but SDF reserves the name for the world "
                         'frame: rename the link (robot.rename_link)')
    return True


def _joint(model: Any, joint: Joint, names: dict[str, str], follow: Follow | None) -> None:
    element = etree.SubElement(model, 'joint', name=names[joint.name], type=_TYPES[joint.type])
    # A joint from URDF's world link: the model frame is where the model meets the world.
    _pose(element, joint.origin, '__model__' if joint.parent == WORLD else joint.parent)
    _text(element, 'parent', joint.parent)
    _text(element, 'child', joint.child)
    for sensor in joint.sensors:
        element.append(sensor_element(sensor))
    if joint.type is not JointType.FIXED:
        _axis(element, joint, names, follow)
    apply_blocks(element, [b for b in joint.extensions if b.tag == 'gazebo'], 'joint',
                 joint.name)


def _axis(element: Any, joint: Joint, names: dict[str, str], follow: Follow | None) -> None:
    axis = etree.SubElement(element, 'axis')
    _text(axis, 'xyz', fmt_vec(joint.effective_axis))
    limit = joint.limit
    if limit is not None or joint.type is JointType.CONTINUOUS:
        block = etree.SubElement(axis, 'limit')
        if joint.type is not JointType.CONTINUOUS and limit is not None:
            _text(block, 'lower', fmt(limit.lower))
            _text(block, 'upper', fmt(limit.upper))
        if limit is not None:
            _text(block, 'effort', fmt(limit.effort))
            _text(block, 'velocity', fmt(limit.velocity))
    if joint.dynamics is not None:
        dynamics = etree.SubElement(axis, 'dynamics')
        _text(dynamics, 'damping', fmt(joint.dynamics.damping))
        _text(dynamics, 'friction', fmt(joint.dynamics.friction))
    if follow is not None:  # SDF 1.11: follower = multiplier * (leader - reference) + offset
        mimic = etree.SubElement(axis, 'mimic', joint=names[follow.leader])
        _text(mimic, 'multiplier', fmt(follow.multiplier))
        _text(mimic, 'offset', fmt(follow.offset))
        _text(mimic, 'reference', '0')


def _frames(model: Any, frames: list[Merged], names: set[str]) -> None:
    """Write a ``<frame>`` for each merged fixed joint and link, as libsdformat does."""
    for merged in frames:
        joint_frame = merged.joint not in names  # a joint named like a link: one frame
        holder = etree.SubElement(model, 'frame', name=merged.joint if joint_frame else
                                  merged.link, attached_to=merged.parent)
        _text(holder, 'pose', f'{fmt_vec(merged.origin.xyz)} {fmt_vec(merged.origin.rpy)}')
        if joint_frame:
            etree.SubElement(model, 'frame', name=merged.link, attached_to=merged.joint)


def _joint_names(robot: RobotModel, source: RobotModel) -> dict[str, str]:
    """
    Return each joint's SDF name: SDF frames share one namespace, URDF's do not.

    A joint named like a link of ``source`` (kept, or a frame now) gets ``_joint`` added.
    """
    link_names = {link.name for link in source.links}
    taken = set(link_names) | {joint.name for joint in source.joints}
    return {joint.name: (_unique(f'{joint.name}_joint', taken)
                         if joint.name in link_names else joint.name)
            for joint in robot.joints}


def _check_ends(robot: RobotModel) -> None:
    for joint in robot.joints:
        for role in ('parent', 'child'):
            if not robot.has_link(getattr(joint, role)):
                raise ModelError(f'joint {joint.name!r}: {role} link '
                                 f'{getattr(joint, role)!r} does not exist (validate() reports '
                                 'it as S004/S005): define the link or fix the name')
        if joint.type is JointType.PLANAR:
            raise ModelError(f'joint {joint.name!r}: SDF has no planar joint (model it as '
                             'two prismatic joints and a revolute one)')


def _refused(merged: RobotModel) -> list[str]:
    """Return a line for each link of the SDF whose inertia libsdformat refuses."""
    from urdfgenpy_ros.formats.sdf_refusals import sdformat_refusals
    from urdfgenpy_ros.model.findings import Findings
    lines = []
    for finding in sdformat_refusals(merged, Findings(merged)):
        where = f'{finding.location}: ' if finding.location.line is not None else ''
        lines.append(f'{where}error {finding.code} {finding.element}: {finding.message}, '
                     'which libsdformat refuses: Gazebo will not load this SDF '
                     f'({_MENDS[finding.code]})')
    return lines


_MENDS = {'R305': 'write finite numbers in its <inertial>',
          'I201': 'give it a positive mass (kg)', 'I210': 'give it a positive mass (kg)',
          'I202': 'give the link a valid inertia, e.g. Inertial.from_box, or lump_fixed=True '
                  'to merge a link on a fixed joint into its parent'}
_MENDS['I203'] = _MENDS['I202']


def _notes(robot: RobotModel, merged: RobotModel, frames: list[Merged], version: str) -> list[str]:
    notes = _refused(merged)
    notes += [str(loss) for loss in (*gazebo_losses(merged, [f.joint for f in frames]),
                                     *script_notes(merged))]
    notes.extend(mimic_notes(robot, version))
    if version == MIMIC_VERSION:
        notes.extend(follows(merged, robot)[1])
    return notes


def write_sdf(robot: RobotModel, path: str | PathLike[str] | None = None,
              lump_fixed: bool = False, version: str | None = None) -> str:
    """
    Return the SDF text of ``robot``; also write it to ``path`` when given.

    ``lump_fixed`` merges links joined by fixed joints, as SDFormat's URDF conversion does;
    ``version`` is ``'1.9'`` or ``'1.11'`` (default: 1.11 when a joint mimics another).
    Each thing the SDF does not carry is a warning, one line each.

    :raises ValueError: for a planar joint, which SDF cannot express (make it two
        prismatic joints and a revolute one).
    """
    _check_ends(robot)
    fixed_to_world = _fixed_to_world(robot)
    version = sdf_version(robot, version)
    source = robot
    robot, frames = merge_for_sdf(robot, lump_fixed)
    root = etree.Element('sdf', version=version)
    model = etree.SubElement(root, 'model', name=robot_name(robot.name))
    parent_joint = {joint.child: joint for joint in robot.joints}
    names = _joint_names(robot, source)
    for link in robot.links:
        parent = parent_joint.get(link.name)
        if fixed_to_world and link.name == WORLD:
            continue  # the world frame itself, which SDF reserves
        if parent is None:
            pose = None
        elif parent.type is JointType.FLOATING:
            pose = (parent.origin, parent.parent)
        else:
            pose = (Origin(), names[parent.name])
        _link(model, link, robot, pose)
    resolved = follows(robot, source)[0] if version == MIMIC_VERSION else {}
    for joint in robot.joints:
        if joint.type is not JointType.FLOATING:
            _joint(model, joint, names, resolved.get(joint.name))
    _frames(model, frames, {link.name for link in source.links} | set(names.values()))
    apply_blocks(model, [block for block in robot.extensions
                         if block.tag == 'gazebo' and block.reference is None], 'model', None)
    for note in _notes(source, robot, frames, version):
        warn_caller(note)
    etree.indent(root, space='  ')
    text = '<?xml version="1.0"?>\n' + etree.tostring(root, encoding='unicode') + '\n'
    if path is not None:
        write_text(path, text)
    return text
