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
The body tree of an MJCF model: one body per URDF link, posed at its joint.

A URDF joint's frame is its child link's frame, so each body sits at its joint's origin
in its parent body and carries the joint at its own origin, with the URDF axis. The
inertial is written as the URDF gives it: ``fullinertia`` with the six numbers as they
are when the inertial frame is not turned, ``diaginertia`` with the frame's ``quat`` when
the tensor is diagonal, else the tensor turned into the body frame (MJCF takes no
orientation with ``fullinertia``); it is never diagonalised.
"""

from __future__ import annotations

from dataclasses import dataclass, field
import math
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.formats.mjcf.meshes import MeshAssets, MeshNotWritten
from urdfgenpy_ros.model.floats import fmt, fmt_vec
from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, Geometry, Mesh, Origin, Sphere
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.joint import Joint, JointType
from urdfgenpy_ros.model.link import Link, Shape, Visual
from urdfgenpy_ros.model.transforms import quaternion_matrix

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

WORLD = 'world'
_SLIDE_AXES = ('x', 'y')


@dataclass
class MjcfJoint:
    """One joint written in MJCF: its name, type, the URDF joint it stands for."""

    name: str
    kind: str  # hinge, slide, ball, free
    joint: Joint | None
    home: tuple[float, ...]


@dataclass
class BodyTree:
    """What writing the bodies produced, for the sections written after them."""

    joints: list[MjcfJoint] = field(default_factory=list)
    materials: dict[str, tuple[float, ...]] = field(default_factory=dict)
    stand_ins: dict[str, str] = field(default_factory=dict)  # URDF joint -> what replaced it
    missing: dict[str, tuple[str, str]] = field(default_factory=dict)  # mesh URI -> why
    # it is left out, and the fix


def quat(origin: Origin) -> str | None:
    """Return MJCF's ``w x y z`` text of an origin's rotation, or None for none."""
    if origin.quat_xyzw is None and not any(origin.rpy):
        return None
    x, y, z, w = origin.quaternion
    return fmt_vec((w, x, y, z))


def _pose(attributes: dict[str, str], origin: Origin) -> dict[str, str]:
    if any(origin.xyz):
        attributes['pos'] = fmt_vec(origin.xyz)
    turned = quat(origin)
    if turned is not None:
        attributes['quat'] = turned
    return attributes


def inertial_attributes(inertial: Inertial) -> dict[str, str]:
    """Return the ``<inertial>`` attributes of a URDF inertial (see the module's note)."""
    origin = inertial.origin
    attributes = {'pos': fmt_vec(origin.xyz), 'mass': fmt(inertial.mass)}
    diagonal = inertial.ixy == inertial.ixz == inertial.iyz == 0.0
    turned = quat(origin)
    if diagonal and inertial.ixx == inertial.iyy == inertial.izz == 0.0:
        attributes['diaginertia'] = '0 0 0'  # a point mass, which MuJoCo reads as such
    elif turned is None:
        attributes['fullinertia'] = fmt_vec((inertial.ixx, inertial.iyy, inertial.izz,
                                             inertial.ixy, inertial.ixz, inertial.iyz))
    elif diagonal:
        attributes['quat'] = turned
        attributes['diaginertia'] = fmt_vec((inertial.ixx, inertial.iyy, inertial.izz))
    else:
        rotation = [row[:3] for row in quaternion_matrix(origin.quaternion)[:3]]
        tensor = inertial.tensor
        body = [[sum(rotation[i][k] * tensor[k][m] * rotation[j][m] for k in range(3)
                     for m in range(3)) for j in range(3)] for i in range(3)]
        attributes['fullinertia'] = fmt_vec((body[0][0], body[1][1], body[2][2], body[0][1],
                                             body[0][2], body[1][2]))
    return attributes


def geometry_attributes(geometry: Geometry, meshes: MeshAssets, where: str) -> dict[str, str]:
    """Return the ``type`` and ``size`` (or ``mesh``) of a geom for a URDF geometry."""
    if isinstance(geometry, Box):
        return {'type': 'box', 'size': fmt_vec(value / 2.0 for value in geometry.size)}
    if isinstance(geometry, Cylinder):
        return {'type': 'cylinder', 'size': fmt_vec((geometry.radius, geometry.length / 2.0))}
    if isinstance(geometry, Capsule):
        return {'type': 'capsule', 'size': fmt_vec((geometry.radius, geometry.length / 2.0))}
    if isinstance(geometry, Sphere):
        return {'type': 'sphere', 'size': fmt(geometry.radius)}
    assert isinstance(geometry, Mesh)
    return {'type': 'mesh', 'mesh': meshes.add(geometry, where)}


def has_size(geometry: Geometry) -> bool:
    """Return whether every size of ``geometry`` is positive (MuJoCo refuses zero)."""
    if isinstance(geometry, Box):
        return all(value > 0.0 for value in geometry.size)
    if isinstance(geometry, (Cylinder, Capsule)):
        return geometry.radius > 0.0 and geometry.length > 0.0
    if isinstance(geometry, Sphere):
        return geometry.radius > 0.0
    return geometry.scale is None or all(value != 0.0 for value in geometry.scale)


class BodyWriter:
    """Write a robot's links as nested bodies under ``<worldbody>``."""

    def __init__(self, robot: RobotModel, meshes: MeshAssets, base: str,
                 sites: dict[str, list[tuple[str, Origin]]]) -> None:
        self.robot = robot
        self.meshes = meshes
        self.base = base  # fixed or floating
        self.sites = sites  # body -> merged links and where they are on it
        self.tree = BodyTree()
        self._geom_names: set[str] = set()
        # friction by link, and the link each collision of a fused body came from
        self.friction: tuple[dict[str, str], dict[str, list[str]]] = ({}, {})

    def write(self, worldbody: Any) -> BodyTree:
        """Add the bodies to ``worldbody``; return what the later sections need."""
        root = self.robot.root
        if root.name == WORLD:
            self._shapes(worldbody, root)
            for joint in self.robot.child_joints(root):
                self._body(worldbody, joint, top=True)
        else:
            body = etree.SubElement(worldbody, 'body', name=root.name)
            if self.base == 'floating':
                etree.SubElement(body, 'freejoint', name=f'{root.name}_freejoint')
                self.tree.joints.append(MjcfJoint(f'{root.name}_freejoint', 'free', None,
                                                  (0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0)))
            self._contents(body, root)
        return self.tree

    def _body(self, parent: Any, joint: Joint, top: bool = False) -> None:
        link = self.robot.get_link(joint.child)
        attributes = {'name': link.name}
        if joint.type is not JointType.FLOATING or not top:
            _pose(attributes, joint.origin)
        body = etree.SubElement(parent, 'body', attributes)
        self._joint(body, joint, top)
        self._contents(body, link)

    def _contents(self, body: Any, link: Link) -> None:
        if link.inertial is not None and (link.inertial.mass != 0.0 or any(
                value != 0.0 for row in link.inertial.tensor for value in row)):
            etree.SubElement(body, 'inertial', inertial_attributes(link.inertial))
        for name, origin in self.sites.get(link.name, []):
            etree.SubElement(body, 'site', _pose({'name': name}, origin))
        self._shapes(body, link)
        for joint in self.robot.child_joints(link):
            self._body(body, joint)

    def _shapes(self, body: Any, link: Link) -> None:
        shapes: list[tuple[str, list[Shape]]] = [('visual', list(link.visuals)),
                                                 ('collision', list(link.collisions))]
        for kind, items in shapes:
            for number, item in enumerate(items, start=1):
                where = f"link '{link.name}' {kind} {number}"
                attributes: dict[str, str] = {}
                if item.name and item.name not in self._geom_names:
                    self._geom_names.add(item.name)
                    attributes['name'] = item.name
                attributes['class'] = kind
                if not has_size(item.geometry):
                    continue  # MuJoCo refuses a geom of size 0: the loss report says so
                try:
                    pieces = self._pieces(item, where)
                except MeshNotWritten as error:
                    assert isinstance(item.geometry, Mesh)
                    self.tree.missing[item.geometry.filename] = (str(error), error.hint)
                    continue
                _pose(attributes, item.origin)
                if isinstance(item, Visual):
                    material = self._material(item)
                    if material is not None:
                        attributes['material'] = material
                else:
                    friction, owners = self.friction
                    owner = owners[link.name][number - 1] if link.name in owners else link.name
                    if owner in friction:
                        attributes['friction'] = friction[owner]
                for piece, (shape, rgba, colour) in enumerate(pieces):
                    written = {**attributes, **shape}
                    if piece and 'name' in written:  # a DAE's colours: one geom each
                        written.pop('name')
                        if f"{attributes['name']}_{piece + 1}" not in self._geom_names:
                            written['name'] = f"{attributes['name']}_{piece + 1}"
                            self._geom_names.add(written['name'])
                    if rgba is not None:  # the mesh's own colour wins, as in RViz
                        written['material'] = self._colour(colour or 'mesh', rgba)
                    etree.SubElement(body, 'geom', written)

    def _pieces(self, item: Shape, where: str) -> list[tuple[dict[str, str], Any, str]]:
        """Return a shape's geoms: one, or one per colour of a visual DAE."""
        if isinstance(item, Visual) and isinstance(item.geometry, Mesh):
            return [({'type': 'mesh', 'mesh': name}, rgba, colour) for name, rgba, colour
                    in self.meshes.add_coloured(item.geometry, where)]
        return [(geometry_attributes(item.geometry, self.meshes, where), None, '')]

    def _colour(self, base: str, rgba: tuple[float, ...]) -> str:
        """Return the name of a material of colour ``rgba`` (``base``, or numbered)."""
        name, number = base, 2
        while name in self.tree.materials and self.tree.materials[name] != tuple(rgba):
            name, number = f'{base}_{number}', number + 1
        self.tree.materials[name] = tuple(rgba)
        return name

    def _material(self, visual: Visual) -> str | None:
        material = visual.material
        if material is None:
            return None
        rgba = material.rgba
        if rgba is None and self.robot.has_material(material.name):
            rgba = self.robot.get_material(material.name).rgba
        if rgba is None:
            return None
        return self._colour(material.name or 'material', rgba)  # name="" is allowed

    def _joint(self, body: Any, joint: Joint, top: bool) -> None:
        kind = joint.type
        if kind is JointType.FIXED:
            return
        if kind is JointType.FLOATING:
            if top:
                etree.SubElement(body, 'freejoint', name=joint.name)
                pose = joint.origin
                x, y, z, w = pose.quaternion
                self.tree.joints.append(MjcfJoint(joint.name, 'free', joint,
                                                  (*pose.xyz, w, x, y, z)))
                if any(pose.xyz) or quat(pose) is not None:
                    body.set('pos', fmt_vec(pose.xyz))
                    turned = quat(pose)
                    if turned is not None:
                        body.set('quat', turned)
                return
            for axis in ('x', 'y', 'z'):  # a free joint is only allowed at the top
                name = f'{joint.name}_{axis}'
                etree.SubElement(body, 'joint', name=name, type='slide',
                                 axis={'x': '1 0 0', 'y': '0 1 0', 'z': '0 0 1'}[axis])
                self.tree.joints.append(MjcfJoint(name, 'slide', joint, (0.0,)))
            etree.SubElement(body, 'joint', name=f'{joint.name}_ball', type='ball')
            self.tree.joints.append(MjcfJoint(f'{joint.name}_ball', 'ball', joint,
                                              (1.0, 0.0, 0.0, 0.0)))
            self.tree.stand_ins[joint.name] = 'three slide joints and a ball joint'
            return
        if kind is JointType.PLANAR:
            self._planar(body, joint)
            return
        attributes = {'name': joint.name,
                      'type': 'slide' if kind is JointType.PRISMATIC else 'hinge',
                      'axis': fmt_vec(joint.effective_axis)}
        limit = joint.limit
        home = 0.0
        if kind is not JointType.CONTINUOUS and limit is not None \
                and limit.lower < limit.upper:
            attributes['range'] = fmt_vec((limit.lower, limit.upper))
            home = min(max(0.0, limit.lower), limit.upper)
        self._dynamics(attributes, joint)
        etree.SubElement(body, 'joint', attributes)
        self.tree.joints.append(MjcfJoint(joint.name, attributes['type'], joint, (home,)))

    def _dynamics(self, attributes: dict[str, str], joint: Joint) -> None:
        if joint.limit is not None and joint.limit.effort > 0.0 \
                and math.isfinite(joint.limit.effort):
            attributes['actuatorfrcrange'] = fmt_vec((-joint.limit.effort, joint.limit.effort))
        if joint.dynamics is not None:
            if joint.dynamics.damping:
                attributes['damping'] = fmt(joint.dynamics.damping)
            if joint.dynamics.friction:
                attributes['frictionloss'] = fmt(joint.dynamics.friction)

    def _planar(self, body: Any, joint: Joint) -> None:
        """Write a planar joint as two slides in the plane and a hinge about its normal."""
        normal = joint.effective_axis
        first, second = _plane(normal)
        for axis, direction in zip(_SLIDE_AXES, (first, second)):
            name = f'{joint.name}_{axis}'
            attributes = {'name': name, 'type': 'slide', 'axis': fmt_vec(direction)}
            self._dynamics(attributes, joint)
            etree.SubElement(body, 'joint', attributes)
            self.tree.joints.append(MjcfJoint(name, 'slide', joint, (0.0,)))
        attributes = {'name': f'{joint.name}_yaw', 'type': 'hinge', 'axis': fmt_vec(normal)}
        self._dynamics(attributes, joint)
        etree.SubElement(body, 'joint', attributes)
        self.tree.joints.append(MjcfJoint(f'{joint.name}_yaw', 'hinge', joint, (0.0,)))
        self.tree.stand_ins[joint.name] = (f'slides {joint.name}_x, {joint.name}_y and hinge '
                                           f'{joint.name}_yaw')


def _plane(normal: tuple[float, float, float]) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """Return two unit vectors spanning the plane normal to ``normal``."""
    length = math.sqrt(sum(value * value for value in normal)) or 1.0
    n = [value / length for value in normal]
    helper = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
    u = [helper[i] - sum(helper[k] * n[k] for k in range(3)) * n[i] for i in range(3)]
    size = math.sqrt(sum(value * value for value in u))
    u = [value / size for value in u]
    v = [n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]]
    return tuple(u), tuple(v)
