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
Mirror a limb: add the reflection of the subtree below a link's parent joint.

A reflection ``S`` through a plane of a frame turns a link's pose ``W`` into ``S W``,
which is left-handed; the copy's link frame is ``S W D``, with ``D`` the same reflection
in the link's own axes (for the xz plane: y flips), so every frame stays right-handed.
Then each joint origin inside the subtree becomes ``D O D`` (xz: x, -y, z and -roll,
pitch, -yaw), the first joint's ``P^-1 S P O D`` (``P`` its parent's pose), and each
shape, inertial and sensor pose ``D V D``, the shape itself reflected by ``D`` (a primitive
is its own mirror image; a mesh is written reflected, beside the original). A turn about
axis ``a`` becomes a turn about ``-D a`` by the same angle, or about ``D a`` by the
opposite one: each joint keeps its axis where it can, and :class:`MirroredJoint` says
which (positions, and so limits, kept or negated). Mimic multipliers and offsets follow.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
import copy
from dataclasses import dataclass, replace
from os import PathLike
from typing import Any
import warnings

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.floats import fmt_vec
from urdfgenpy_ros.model.geometry import Mesh, Origin
from urdfgenpy_ros.model.joint import Joint, JointMimic, JointType
from urdfgenpy_ros.model.transforms import IDENTITY4, Matrix4, multiply
from urdfgenpy_ros.reshape._frames import general_multiply, inverse, origin_of, require_link
from urdfgenpy_ros.reshape.assembly import _rename, _Renaming
from urdfgenpy_ros.reshape.mirror_mesh import FLIPPED_AXIS, MeshWriter
from urdfgenpy_ros.reshape.mirror_names import limb_renamer, require_one_to_one

PLANES = FLIPPED_AXIS
_TURNING = (JointType.REVOLUTE, JointType.CONTINUOUS)


@dataclass(frozen=True)
class MirroredJoint:
    """One joint of the copy: ``position == sign * original's position``."""

    name: str
    original: str
    sign: int

    def __str__(self) -> str:
        """Return the rule as one line."""
        rule = 'positions kept' if self.sign > 0 else 'positions negated (limits -upper..-lower)'
        return f'joint {self.name!r} mirrors {self.original!r}: {rule}'


def _flip(axis: int) -> Matrix4:
    matrix = [row[:] for row in IDENTITY4]
    matrix[axis][axis] = -1.0
    return matrix


def _conjugate(origin: Origin, flip: Matrix4) -> Origin:
    """
    Return the origin ``D O D``, exactly.

    A flip of axis k negates xyz[k], and the angles (rpy, or a quaternion's vector part)
    about the two other axes.
    """
    k = next(i for i in range(3) if flip[i][i] < 0.0)
    xyz = tuple(-v + 0.0 if i == k else v for i, v in enumerate(origin.xyz))
    if origin.quat_xyzw is not None:
        quat = tuple(v if i in (k, 3) else -v + 0.0 for i, v in enumerate(origin.quat_xyzw))
        return Origin(xyz, quat_xyzw=quat, source=origin.source, extras=origin.extras)
    rpy = tuple(v if i == k else -v + 0.0 for i, v in enumerate(origin.rpy))
    return Origin(xyz, rpy, source=origin.source, extras=origin.extras)


def mirror_subtree(robot, root: str, plane: str = 'xz', frame: str | None = None,
                   rename: Mapping[str, str] | None = None, *,
                   mesh_folder: str | PathLike[str] | None = None,
                   search_paths: tuple = ()) -> list[MirroredJoint]:
    """
    Add to ``robot`` the mirror image of the subtree below link ``root``'s parent joint.

    Return each moving joint's rule. See :meth:`urdfgenpy_ros.robot.Robot.mirror`.

    :raises ModelError: one line, for an unknown plane or link, or names the copy would
        take that are taken (all listed), before anything changes.
    """
    if plane not in PLANES:
        raise ModelError(f"mirror: plane {plane!r} is not one of 'xz', 'yz', 'xy'")
    rename = {'left_': 'right_'} if rename is None else dict(rename)
    top = robot.parent_joint(require_link(robot, root, 'mirror: root'))
    at_frame = require_link(robot, frame, 'mirror: frame') if frame is not None else None
    if top is None:
        raise ModelError(f'mirror: {root!r} is the root link: name the first link of a limb '
                         '(the child of the joint the copy hangs from)')
    links = robot.subtree(root)
    joints = [top, *(joint for joint in robot.joints
                     if joint.parent in {link.name for link in links})]
    renamed, link_names, joint_names = _new_names(robot, root, links, joints, rename)
    flip = _flip(PLANES[plane])
    poses = _zero_poses(robot)
    at = poses[at_frame or robot.root.name]
    reflection = general_multiply(at, flip, inverse(at))  # S in the root's frame
    parent = poses[top.parent]
    first = general_multiply(inverse(parent), reflection, parent, top.origin.matrix(), flip)
    piece = _copy(robot, links, joints)
    meshes = MeshWriter(robot, plane, mesh_folder, search_paths)
    signs = _mirror_piece(piece, top.name, first, flip, meshes, renamed)
    blocks = _robot_blocks(robot, joint_names, link_names, renamed)
    _rename_texts(piece, renamed)
    _rename(piece, _Renaming(link_names, joint_names))
    _rename_sensors(piece, renamed)
    meshes.commit()  # the last step that can fail: all mirrored files, or none
    for link in piece.links:
        robot.add_link(link)
    for joint in piece.joints:
        robot.add_joint(joint)
    robot.extensions.extend(blocks)
    return [MirroredJoint(joint_names[name], name, sign) for name, sign in signs.items()
            if sign]


def _new_names(robot, root: str, links: list, joints: list, rename: dict[str, str]
               ) -> tuple[Callable[[str], str], dict[str, str], dict[str, str]]:
    """
    Return the renamer and the copy's link and joint names, old to new.

    :raises ModelError: for names the copy would share, or take from the robot (all listed).
    """
    shapes = {shape.name for link in links for shape in (*link.visuals, *link.collisions)
              if shape.name}
    renamed = limb_renamer(rename, [*(item.name for item in (*links, *joints)), *shapes],
                           [item.name for item in (*robot.links, *robot.joints)])
    link_names = {link.name: renamed(link.name) for link in links}
    joint_names = {joint.name: renamed(joint.name) for joint in joints}
    for kind, names in (('link', link_names), ('joint', joint_names),
                        ('visual and collision name', {name: renamed(name) for name in shapes})):
        require_one_to_one(kind, names, rename)
    taken = [f'link {new!r}' for new in link_names.values() if robot.has_link(new)]
    taken += [f'joint {new!r}' for new in joint_names.values() if robot.has_joint(new)]
    if taken:
        shown = ', '.join(taken[:6]) + (f' and {len(taken) - 6} more' if len(taken) > 6 else '')
        raise ModelError(f'mirror: the copy of {root!r} would take names in use: {shown} '
                         f'(pass rename= that changes them; it was {rename!r})')
    return renamed, link_names, joint_names


def _mirror_piece(piece, top: str, first: Matrix4, flip: Matrix4, meshes: MeshWriter,
                  renamed: Callable[[str], str]) -> dict[str, int]:
    """Mirror the copied joints, sensors, blocks and links in place; return each joint's sign."""
    signs: dict[str, int] = {}
    for joint in piece.joints:
        joint.origin = (origin_of(first, joint.origin) if joint.name == top
                        else _conjugate(joint.origin, flip))
        signs[joint.name] = _mirror_motion(joint, flip)
    for joint in piece.joints:
        _mirror_mimic(joint, signs)
        for sensor in joint.sensors:
            sensor.origin = _conjugate(sensor.origin, flip)
        for block in joint.extensions:
            for pose in block.element.iter('pose'):
                _mirror_pose_text(pose, flip, f'joint {joint.name!r}')
    for link in piece.links:
        _mirror_link(link, flip, meshes)
        for shape in (*link.visuals, *link.collisions):
            shape.name = renamed(shape.name) if shape.name else shape.name
    return signs


def _zero_poses(robot) -> dict[str, Matrix4]:
    poses: dict[str, Matrix4] = {}
    for joint, link in robot.walk():
        poses[link.name] = IDENTITY4 if joint is None else multiply(
            poses[joint.parent], joint.origin.matrix())
    return poses


def _copy(robot, links, joints):
    """Return a robot holding deep copies of ``links`` and ``joints``."""
    from urdfgenpy_ros.model import checks
    piece = type(robot)(robot.name)
    for link in copy.deepcopy(links):
        piece.add_link(link)
    with checks.unchecked():  # the first joint's parent stays outside the copy
        for joint in copy.deepcopy(joints):
            piece.add_joint(joint)
    return piece


def _mirror_motion(joint: Joint, flip: Matrix4) -> int:
    """Turn ``joint``'s axis and limits; return the position's sign (0: no position)."""
    if not joint.type.is_movable:
        if joint.axis is not None:
            joint.axis = _clean(tuple(flip[i][i] * joint.axis[i] for i in range(3)))
        return 0
    axis = joint.effective_axis
    flipped = tuple(flip[i][i] * axis[i] for i in range(3))
    same = tuple(-value for value in flipped) if joint.type in _TURNING else flipped
    other = tuple(-value for value in same)
    closeness = sum(a * b for a, b in zip(same, axis))
    if closeness >= sum(a * b for a, b in zip(other, axis)) - 1e-12:
        joint.axis = _clean(same) if joint.axis is not None or same != (1.0, 0.0, 0.0) \
            else None
        return 1
    joint.axis = _clean(other) if joint.axis is not None or other != (1.0, 0.0, 0.0) else None
    if joint.limit is not None:
        joint.limit = replace(joint.limit, lower=-joint.limit.upper + 0.0,
                              upper=-joint.limit.lower + 0.0)
    if joint.safety_controller is not None:
        soft = joint.safety_controller
        joint.safety_controller = replace(soft, soft_lower_limit=-soft.soft_upper_limit + 0.0,
                                          soft_upper_limit=-soft.soft_lower_limit + 0.0)
    if joint.calibration is not None:
        edges = joint.calibration
        joint.calibration = replace(
            edges, rising=None if edges.falling is None else -edges.falling + 0.0,
            falling=None if edges.rising is None else -edges.rising + 0.0)
    return -1


def _clean(vector: tuple) -> tuple[float, float, float]:
    return (vector[0] + 0.0, vector[1] + 0.0, vector[2] + 0.0)


def _mirror_mimic(joint: Joint, signs: dict[str, int]) -> None:
    """Keep ``q = m q_leader + o`` true between the mirrored positions."""
    mimic = joint.mimic
    if mimic is None:
        return
    own = signs.get(joint.name) or 1
    leader = signs.get(mimic.joint) or 1  # a leader outside the limb is not mirrored
    multiplier = 1.0 if mimic.multiplier is None else mimic.multiplier
    offset = 0.0 if mimic.offset is None else mimic.offset
    joint.mimic = JointMimic(mimic.joint, own * leader * multiplier + 0.0,
                             own * offset + 0.0, source=mimic.source, extras=mimic.extras)
    if mimic.multiplier is None and own * leader == 1:
        joint.mimic = replace(joint.mimic, multiplier=None)
    if mimic.offset is None and offset == 0.0:
        joint.mimic = replace(joint.mimic, offset=None)


def _mirror_link(link: Any, flip: Matrix4, meshes: MeshWriter) -> None:
    for item in (*link.visuals, *link.collisions):
        item.origin = _conjugate(item.origin, flip)
        if isinstance(item.geometry, Mesh):
            item.geometry = meshes.mirrored(item.geometry, link.name)
    inertial = link.inertial
    if inertial is not None:
        d = [flip[i][i] for i in range(3)]
        inertial.ixy *= d[0] * d[1]
        inertial.ixz *= d[0] * d[2]
        inertial.iyz *= d[1] * d[2]
        inertial.origin = _conjugate(inertial.origin, flip)
    for sensor in link.sensors:
        sensor.origin = _conjugate(sensor.origin, flip)
    for block in link.extensions:
        for pose in block.element.iter('pose'):
            _mirror_pose_text(pose, flip, f'link {link.name!r}')


def _mirror_pose_text(pose: Any, flip: Matrix4, owner: str) -> None:
    if pose.get('relative_to') or pose.get('rotation_format') not in (None, 'euler_rpy') \
            or pose.get('degrees', '').strip().lower() in ('true', '1'):
        raise ModelError(f'mirror: {owner} has a <pose> the mirror cannot turn (give '
                         "it as 'x y z roll pitch yaw' in radians, without relative_to)")
    try:
        numbers = [float(value) for value in (pose.text or '').split()]
    except ValueError:
        numbers = []
    if len(numbers) != 6:
        raise ModelError(f"mirror: {owner}: <pose> {(pose.text or '').strip()!r} is "
                         "not 'x y z roll pitch yaw'")
    turned = _conjugate(Origin(tuple(numbers[:3]), tuple(numbers[3:])), flip)
    pose.text = f'{fmt_vec(turned.xyz)} {fmt_vec(turned.rpy)}'


def _rename_sensors(piece: Any, renamed: Any) -> None:
    """Give the copy's sensors names of their own (renamed, else ``_mirror`` appended)."""
    def new(name: str) -> str:
        changed = renamed(name)
        return changed if changed != name else f'{name}_mirror'

    for owner in (*piece.links, *piece.joints):
        for sensor in owner.sensors:
            sensor.name = new(sensor.name)
        for block in owner.extensions:
            for element in block.element.iter():
                if _is_sensor(element) and element.get('name'):
                    element.set('name', new(element.get('name')))


def _is_sensor(element: Any) -> bool:
    """Return whether ``element`` is a sensor (``<sensor>``, or gazebo 1.x ``<sensor:camera>``)."""
    if not isinstance(element.tag, str):
        return False
    return element.tag == 'sensor' or element.tag.startswith('{') and 'sensor' in \
        element.tag.partition('}')[0].lower()


def _rename_texts(piece: Any, renamed: Any) -> None:
    """Rename the names the copy's blocks hold as text (topics, frames: ``l_cam/image``)."""
    for owner in (*piece.links, *piece.joints):
        for block in owner.extensions:
            for element in block.element.iter():
                if not isinstance(element.tag, str) or len(element) or not element.text:
                    continue
                text = element.text.strip()
                if text and renamed(text, False) != text:
                    element.text = element.text.replace(text, renamed(text, False))


def _joints_named(element: Any, robot: Any) -> set[str]:
    """Return the robot's joints a ``<transmission>`` names (PR2's ``<flexJoint>`` too)."""
    return {node.get('name') for node in element.iter() if node is not element
            and isinstance(node.tag, str) and robot.has_joint(node.get('name') or '')}


def _robot_blocks(robot: Any, joints: dict[str, str], links: dict[str, str],
                  renamed: Any) -> list[Any]:
    """
    Give the copy its part of the robot-level blocks; return new blocks to add.

    A ``<transmission>`` of the limb's joints only is copied, renamed; in other blocks
    (``<ros2_control>``, plugins), each element naming a joint or link of the limb gets a
    renamed sibling after it. A transmission of the limb's joints and others is not
    copied: a warning says so.
    """
    renaming = _Renaming(links, joints)
    added = []
    for block in robot.extensions:
        element = block.element
        if element.tag == 'transmission':
            named = _joints_named(element, robot)
            name = element.get('name') or ''
            if named and named <= set(joints):
                twin = copy.deepcopy(block)
                twin.element.set('name', renamed(name) if renamed(name) != name else
                                 f'{name}_mirror')
                for actuator in twin.element.iter():
                    if isinstance(actuator.tag, str) and \
                            actuator.tag.lower().endswith('actuator'):
                        old = actuator.get('name') or ''
                        actuator.set('name', renamed(old) if renamed(old) != old
                                     else f'{old}_mirror')
                _rename_block_copy(twin.element, renaming)
                added.append(twin)
            elif named & set(joints):
                shared = ', '.join(sorted(named & set(joints)))
                warnings.warn(f'mirror: transmission {name!r} drives {shared} of the limb '
                              'and joints outside it: not mirrored (write its mirror image '
                              'by hand)', stacklevel=3)
            continue
        for node in list(element.iter()):
            if not isinstance(node.tag, str) or node is element:
                continue
            text = (node.text or '').strip() if len(node) == 0 else ''
            if node.get('name') in joints and node.tag == 'joint' or text in joints \
                    or text in links:
                twin = copy.deepcopy(node)
                _rename_block_copy(twin, renaming)
                node.addnext(twin)
    return added


def _rename_block_copy(element: Any, renaming: _Renaming) -> None:
    from urdfgenpy_ros.reshape.assembly import _rename_block
    _rename_block(element, renaming)
