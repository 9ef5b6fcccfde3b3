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

"""Mass, centre of mass and inertia tensor of a link, with solid-body helpers."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, KW_ONLY
import math

from urdfgenpy_ros.model import checks
from urdfgenpy_ros.model.errors import ModelError, ModelTypeError, SourceLocation
from urdfgenpy_ros.model.geometry import (
    _positive, Box, Capsule, Cylinder, Geometry, IDENTITY, Mesh, Origin, Sphere)
from urdfgenpy_ros.model.preserved import Preserved

INERTIA_ATTRS = ('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz')


def box_tensor(mass: float, length: float, width: float, height: float) -> tuple[float, ...]:
    """Return ``(ixx, ixy, ixz, iyy, iyz, izz)`` of a solid box about its centre."""
    return (mass * (width * width + height * height) / 12.0, 0.0, 0.0,
            mass * (length * length + height * height) / 12.0, 0.0,
            mass * (length * length + width * width) / 12.0)


def cylinder_tensor(mass: float, radius: float, length: float) -> tuple[float, ...]:
    """Return the tensor of a solid cylinder along z about its centre."""
    side = mass * (3.0 * radius * radius + length * length) / 12.0
    return (side, 0.0, 0.0, side, 0.0, mass * radius * radius / 2.0)


def sphere_tensor(mass: float, radius: float) -> tuple[float, ...]:
    """Return the tensor of a solid sphere about its centre."""
    moment = 2.0 * mass * radius * radius / 5.0
    return (moment, 0.0, 0.0, moment, 0.0, moment)


def capsule_tensor(mass: float, radius: float, length: float) -> tuple[float, ...]:
    """
    Return the tensor of a solid capsule along z about its centre.

    The mass splits between the cylinder of ``length`` and the two half spheres by volume;
    each half sphere's moment about x is taken at its own centre of mass and moved.
    """
    tube = mass * length / (length + 4.0 * radius / 3.0)
    caps = mass - tube
    side = tube * (3.0 * radius * radius + length * length) / 12.0 + caps * (
        2.0 * radius * radius / 5.0 + length * length / 4.0 + 3.0 * length * radius / 8.0)
    return (side, 0.0, 0.0, side, 0.0,
            tube * radius * radius / 2.0 + caps * 2.0 * radius * radius / 5.0)


@dataclass(slots=True)
class Inertial:
    """Mass (kg) and inertia tensor (kg m^2) about the centre of mass at ``origin``."""

    mass: float
    ixx: float = 0.0
    ixy: float = 0.0
    ixz: float = 0.0
    iyy: float = 0.0
    iyz: float = 0.0
    izz: float = 0.0
    _: KW_ONLY
    origin: Origin = IDENTITY
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)
    # The solid this was computed from, e.g. ('box', mass, l, w, h); the Xacro writer
    # turns it back into an inertia macro call while the values still match it.
    solid: tuple | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        """Check the mass and coerce the tensor to floats."""
        tensor = (self.ixx, self.ixy, self.ixz, self.iyy, self.iyz, self.izz)
        if checks.are_finite_floats(self.mass, *tensor) and self.mass >= 0.0:
            return
        self.mass = checks.non_negative('inertial', 'mass', self.mass, 'kg')
        (self.ixx, self.ixy, self.ixz, self.iyy, self.iyz, self.izz) = checks.numbers(
            'inertial', INERTIA_ATTRS, tensor)

    @property
    def tensor(self) -> tuple[tuple[float, float, float], ...]:
        """Return the symmetric 3x3 inertia matrix."""
        return ((self.ixx, self.ixy, self.ixz),
                (self.ixy, self.iyy, self.iyz),
                (self.ixz, self.iyz, self.izz))

    def matches_solid(self) -> bool:
        """Return whether the values still equal the solid they were computed from."""
        if self.solid is None or self.mass != self.solid[1]:
            return False
        tensor = _SOLID_TENSORS[self.solid[0]](*self.solid[1:])
        return tensor == tuple(getattr(self, attr) for attr in INERTIA_ATTRS)

    @classmethod
    def _of_solid(cls, kind: str, mass: float, dims: tuple[float, ...],
                  origin: Origin | None) -> Inertial:
        if not (type(mass) is float and 0.0 <= mass < _INF):
            mass = checks.non_negative(f'Inertial.from_{kind}', 'mass', mass, 'kg')
        tensor = _SOLID_TENSORS[kind](mass, *dims)
        total = sum(tensor)
        if cls is not Inertial or total - total != 0.0 or (
                origin is not None and type(origin) is not Origin):
            inertial = cls(mass, *tensor, origin=origin or IDENTITY)
        else:  # finite floats computed from checked ones: nothing left to check
            inertial = _new(cls)
            inertial.mass = mass
            (inertial.ixx, inertial.ixy, inertial.ixz, inertial.iyy, inertial.iyz,
             inertial.izz) = tensor
            inertial.origin = origin or IDENTITY
            inertial.source = inertial.extras = None
        inertial.solid = (kind, mass, *dims)
        return inertial

    @classmethod
    def from_box(cls, mass: float, length: float, w: float, h: float, *,
                 origin: Origin | None = None) -> Inertial:
        """Return the inertial of a solid box of sizes ``length`` x ``w`` x ``h``."""
        if type(length) is float and type(w) is float and type(h) is float and \
                0.0 < length < _INF and 0.0 < w < _INF and 0.0 < h < _INF:
            if cls is Inertial and type(mass) is float and 0.0 <= mass < _INF and (
                    origin is None or type(origin) is Origin):
                ixx = mass * (w * w + h * h) / 12.0  # box_tensor's terms, in its order
                iyy = mass * (length * length + h * h) / 12.0
                izz = mass * (length * length + w * w) / 12.0
                total = ixx + iyy + izz
                if total - total == 0.0:  # finite floats from checked ones: build directly
                    inertial = _new(Inertial)
                    inertial.mass = mass
                    inertial.ixx, inertial.iyy, inertial.izz = ixx, iyy, izz
                    inertial.ixy = inertial.ixz = inertial.iyz = 0.0
                    inertial.origin = origin or IDENTITY
                    inertial.source = inertial.extras = None
                    inertial.solid = ('box', mass, length, w, h)
                    return inertial
            return cls._of_solid('box', mass, (length, w, h), origin)
        size = checks.numbers('Inertial.from_box', ('length', 'w', 'h'), (length, w, h), 0.0,
                              strict=True)
        return cls._of_solid('box', mass, size, origin)

    @classmethod
    def from_cylinder(cls, mass: float, radius: float, length: float, *,
                      origin: Origin | None = None) -> Inertial:
        """Return the inertial of a solid cylinder along z."""
        dims = _positive('Inertial.from_cylinder', ('radius', 'length'), radius, length)
        return cls._of_solid('cylinder', mass, dims, origin)

    @classmethod
    def from_sphere(cls, mass: float, radius: float, *,
                    origin: Origin | None = None) -> Inertial:
        """Return the inertial of a solid sphere."""
        dims = _positive('Inertial.from_sphere', ('radius',), radius)
        return cls._of_solid('sphere', mass, dims, origin)

    @classmethod
    def from_capsule(cls, mass: float, radius: float, length: float, *,
                     origin: Origin | None = None) -> Inertial:
        """Return the inertial of a solid capsule along z (``length``: its cylinder)."""
        dims = _positive('Inertial.from_capsule', ('radius', 'length'), radius, length)
        return cls._of_solid('capsule', mass, dims, origin)

    @classmethod
    def from_geometry(cls, mass: float, geometry: Geometry, *,
                      origin: Origin | None = None) -> Inertial:
        """Return the inertial of a solid primitive (box, cylinder, sphere or capsule)."""
        if isinstance(geometry, Box):
            return cls._of_solid('box', mass, geometry.size, origin)
        if isinstance(geometry, Cylinder):
            return cls._of_solid('cylinder', mass, (geometry.radius, geometry.length), origin)
        if isinstance(geometry, Sphere):
            return cls._of_solid('sphere', mass, (geometry.radius,), origin)
        if isinstance(geometry, Capsule):
            return cls._of_solid('capsule', mass, (geometry.radius, geometry.length), origin)
        if isinstance(geometry, Mesh):
            raise ModelError(f'Inertial.from_geometry(): {geometry.filename!r} is a mesh; '
                             'use Inertial.from_mesh(filename, mass=...)')
        raise ModelTypeError('Inertial.from_geometry(): expected Box, Cylinder, Sphere, '
                             'Capsule or Mesh, '
                             f'got {type(geometry).__name__}')

    @classmethod
    def from_mesh(cls, filename: str, density: float | None = None, mass: float | None = None,
                  scale: tuple[float, float, float] | None = None) -> Inertial:
        """
        Return the inertial of a closed mesh (STL, OBJ, DAE) of uniform density or mass.

        Needs the ``mesh`` extra (trimesh). The origin is the centre of mass.
        """
        from urdfgenpy_ros.model.mesh_inertia import inertial_from_mesh
        return inertial_from_mesh(filename, density, mass, scale, cls=cls)

    @classmethod
    def from_meshlab(cls, mass: float, volume: float, tensor: list[list[float]],
                     centre: tuple[float, float, float] | None = None) -> Inertial:
        """Return an SI inertial from MeshLab's geometric measures (mm, density 1)."""
        from urdfgenpy_ros.model.mesh_inertia import inertial_from_meshlab
        return inertial_from_meshlab(mass, volume, tensor, centre, cls=cls)


_INF = math.inf
_new = object.__new__
_SOLID_TENSORS: dict[str, Callable[..., tuple[float, ...]]] = {
    'box': box_tensor, 'cylinder': cylinder_tensor, 'sphere': sphere_tensor,
    'capsule': capsule_tensor}
