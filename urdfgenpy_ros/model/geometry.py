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

"""Shapes of visuals and collisions, and the ``Origin`` pose that places them."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, KW_ONLY
import math

from urdfgenpy_ros.model import checks
from urdfgenpy_ros.model.checks import Vec3
from urdfgenpy_ros.model.errors import FrozenValueError, ModelError, SourceLocation
from urdfgenpy_ros.model.preserved import Preserved
from urdfgenpy_ros.model.transforms import (
    from_xyz_rpy, Matrix4, matrix_rpy, quaternion_matrix, rpy_quaternion)

_ZERO: Vec3 = (0.0, 0.0, 0.0)
_XY = (0.0, 0.0)
Vec4 = tuple[float, float, float, float]


def _setters(cls: type, *names: str) -> tuple:
    """Return the slot setters of a frozen class, to initialise it without __setattr__."""
    return tuple(getattr(cls, name).__set__ for name in names)


def _positive(owner: str, names: tuple[str, ...], *values: float) -> tuple[float, ...]:
    """Return sizes unchanged when they are positive floats, else check them in full."""
    for value in values:
        if type(value) is not float or not 0.0 < value < _INF:
            return checks.numbers(owner, names, values, 0.0, strict=True)
    return values


_INF = math.inf
_new = object.__new__


def _vector(field: str, given: Sequence[float]) -> Vec3:
    """Return an origin's ``xyz`` or ``rpy`` as floats: the fast path, else the checked one."""
    return checks.floats3(given) or checks.vec3('origin', field, given)


@dataclass(slots=True, frozen=True, init=False)
class Origin:
    """
    Pose of a frame: translation ``xyz`` in metres and one rotation.

    The rotation is given as fixed-axis ``rpy`` in radians, or as a quaternion
    ``quat_xyzw`` (URDF 1.1). Given as a quaternion, ``quat_xyzw`` keeps it as written
    and ``rpy`` holds the same rotation, so every consumer of either gets it right;
    given as rpy, ``quat_xyzw`` is None (:attr:`quaternion` converts).
    """

    xyz: Vec3 = _ZERO
    rpy: Vec3 = _ZERO
    _: KW_ONLY
    quat_xyzw: Vec4 | None = None
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)

    def __init__(self, xyz: Sequence[float] = _ZERO, rpy: Sequence[float] = _ZERO, *,
                 quat_xyzw: Sequence[float] | None = None,
                 source: SourceLocation | None = None, extras: Preserved | None = None) -> None:
        _set_xyz(self, xyz if xyz is _ZERO else _vector('xyz', xyz))
        if quat_xyzw is None:
            _set_rpy(self, rpy if rpy is _ZERO else _vector('rpy', rpy))
            _set_quat(self, None)
        else:
            quat = _quaternion(quat_xyzw)
            turned = quaternion_rpy(quat)
            if rpy is not _ZERO and checks.vec3('origin', 'rpy', rpy) != turned:
                raise ModelError('origin: give the rotation as rpy or as quat_xyzw, not both '
                                 f'(rpy {tuple(rpy)!r}, quat_xyzw {quat!r})')
            _set_rpy(self, turned)
            _set_quat(self, quat)
        _set_source(self, source)
        _set_extras(self, extras)

    @property
    def is_identity(self) -> bool:
        """Return whether this origin neither moves nor turns."""
        return self.xyz == _ZERO and self.rpy == _ZERO

    @property
    def quaternion(self) -> Vec4:
        """Return the rotation as a unit quaternion ``(x, y, z, w)``, however it was given."""
        if self.quat_xyzw is not None:
            x, y, z, w = self.quat_xyzw
            norm = math.sqrt(x * x + y * y + z * z + w * w)
            return (x / norm, y / norm, z / norm, w / norm) if norm else (0.0, 0.0, 0.0, 1.0)
        return rpy_quaternion(self.rpy)

    def matrix(self) -> Matrix4:
        """Return the 4x4 transform of this origin (the quaternion's own, if given so)."""
        if self.quat_xyzw is None:
            return from_xyz_rpy(self.xyz, self.rpy)
        result = quaternion_matrix(self.quat_xyzw)
        result[0][3], result[1][3], result[2][3] = self.xyz
        return result

    def as_rpy(self) -> Origin:
        """Return this origin with its rotation written as rpy."""
        if self.quat_xyzw is None:
            return self
        return Origin(self.xyz, self.rpy, source=self.source)

    def as_quaternion(self) -> Origin:
        """Return this origin with its rotation written as a quaternion (``quat_xyzw``)."""
        if self.quat_xyzw is not None:
            return self
        return Origin(self.xyz, quat_xyzw=self.quaternion, source=self.source)

    @classmethod
    def above(cls, geometry: Geometry, xy: tuple[float, float] = _XY,
              rpy: Vec3 = _ZERO) -> Origin:
        """
        Return the origin that puts the bottom of ``geometry`` at z = 0.

        A box or cylinder is lifted by half its height, a sphere by its radius, a capsule
        by half its length plus its radius.
        """
        if cls is not Origin or xy is not _XY or rpy is not _ZERO:
            return cls((xy[0], xy[1], geometry.half_height()), rpy)
        height = geometry.half_height()
        if type(height) is not float or height - height != 0.0:
            return cls((0.0, 0.0, height))  # checked: a size of a shape made unchecked
        origin = _new(Origin)  # a finite float straight up: nothing to check
        _set_xyz(origin, (0.0, 0.0, height))
        _set_rpy(origin, _ZERO)
        _set_quat(origin, None)
        _set_source(origin, None)
        _set_extras(origin, None)
        return origin

    @classmethod
    def wheel(cls, xy: tuple[float, float] = (0.0, 0.0), z: float = 0.0) -> Origin:
        """Return an origin rolled by -pi/2, turning a cylinder's axis from z onto y."""
        return cls(xyz=(xy[0], xy[1], z), rpy=(-math.pi / 2.0, 0.0, 0.0))


def quaternion_rpy(quat_xyzw: Sequence[float]) -> Vec3:
    """Return the fixed-axis rpy of a quaternion ``(x, y, z, w)`` (normalised first)."""
    x, y, z, w = quat_xyzw
    return matrix_rpy(quaternion_matrix((x, y, z, w)))


def _quaternion(value: Sequence[object]) -> Vec4:
    """Return a quaternion of four finite numbers, not all zero; raise ModelError if not."""
    try:
        x, y, z, w = (float(part) for part in value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ModelError(f'origin: quat_xyzw must have 4 numbers (x, y, z, w), got {value!r}'
                         ) from None
    total = x * x + y * y + z * z + w * w
    if checks.enabled() and (total - total != 0.0 or total == 0.0):
        raise ModelError(f'origin: quat_xyzw must be 4 finite numbers, not all 0, got '
                         f'{value!r} (no rotation is 0 0 0 1)')
    return (x, y, z, w)


_set_xyz, _set_rpy, _set_quat, _set_source, _set_extras = _setters(
    Origin, 'xyz', 'rpy', 'quat_xyzw', 'source', 'extras')
IDENTITY = Origin()
_BOX_SIZES = ('length', 'width', 'height')


@dataclass(slots=True, frozen=True, init=False)
class Box:
    """A box centred on its frame; sizes along x, y and z in metres."""

    length: float
    width: float
    height: float
    _: KW_ONLY
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)

    def __init__(self, length: float, width: float, height: float, *,
                 source: SourceLocation | None = None, extras: Preserved | None = None) -> None:
        if not (type(length) is float and type(width) is float and type(height) is float
                and 0.0 < length < _INF and 0.0 < width < _INF and 0.0 < height < _INF):
            length, width, height = checks.numbers('box', _BOX_SIZES, (length, width, height),
                                                   0.0, strict=True)
        _set_length(self, length)
        _set_width(self, width)
        _set_height(self, height)
        _set_box_source(self, source)
        _set_box_extras(self, extras)

    @property
    def size(self) -> Vec3:
        """Return ``(length, width, height)`` as URDF's ``size`` attribute lists them."""
        return (self.length, self.width, self.height)

    def half_height(self) -> float:
        """Return the distance from the centre to the bottom face."""
        return self.height / 2.0


_set_length, _set_width, _set_height, _set_box_source, _set_box_extras = _setters(
    Box, 'length', 'width', 'height', 'source', 'extras')


@dataclass(slots=True, frozen=True, init=False)
class Cylinder:
    """A cylinder along z, centred on its frame."""

    radius: float
    length: float
    _: KW_ONLY
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)

    def __init__(self, radius: float, length: float, *, source: SourceLocation | None = None,
                 extras: Preserved | None = None) -> None:
        if not (type(radius) is float and type(length) is float
                and 0.0 < radius < _INF and 0.0 < length < _INF):
            radius, length = checks.numbers('cylinder', ('radius', 'length'), (radius, length),
                                            0.0, strict=True)
        set_radius, set_length, set_source, set_extras = _CYLINDER_SLOTS
        set_radius(self, radius)
        set_length(self, length)
        set_source(self, source)
        set_extras(self, extras)

    def half_height(self) -> float:
        """Return the distance from the centre to the bottom face."""
        return self.length / 2.0


_CYLINDER_SLOTS = _setters(Cylinder, 'radius', 'length', 'source', 'extras')


@dataclass(slots=True, frozen=True, init=False)
class Sphere:
    """A sphere centred on its frame."""

    radius: float
    _: KW_ONLY
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)

    def __init__(self, radius: float, *, source: SourceLocation | None = None,
                 extras: Preserved | None = None) -> None:
        if not (type(radius) is float and 0.0 < radius < _INF):
            (radius,) = checks.numbers('sphere', ('radius',), (radius,), 0.0, strict=True)
        set_radius, set_source, set_extras = _SPHERE_SLOTS
        set_radius(self, radius)
        set_source(self, source)
        set_extras(self, extras)

    def half_height(self) -> float:
        """Return the distance from the centre to the lowest point."""
        return self.radius


_SPHERE_SLOTS = _setters(Sphere, 'radius', 'source', 'extras')


@dataclass(slots=True, frozen=True, init=False)
class Capsule:
    """
    A capsule along z, centred on its frame (URDF 1.1).

    A cylinder of ``length`` capped by two half spheres of ``radius``: it is
    ``length + 2 radius`` long in all, as in urdfdom, SDFormat and MuJoCo.
    """

    radius: float
    length: float
    _: KW_ONLY
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)

    def __init__(self, radius: float, length: float, *, source: SourceLocation | None = None,
                 extras: Preserved | None = None) -> None:
        radius, length = _positive('capsule', ('radius', 'length'), radius, length)
        set_radius, set_length, set_source, set_extras = _CAPSULE_SLOTS
        set_radius(self, radius)
        set_length(self, length)
        set_source(self, source)
        set_extras(self, extras)

    def half_height(self) -> float:
        """Return the distance from the centre to the lowest point."""
        return self.length / 2.0 + self.radius


_CAPSULE_SLOTS = _setters(Capsule, 'radius', 'length', 'source', 'extras')


@dataclass(slots=True, frozen=True)
class Mesh:
    """A mesh file (``package://``, ``file://`` or a path) with an optional scale."""

    filename: str
    scale: Vec3 | None = None
    _: KW_ONLY
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        """Check the file name and coerce the scale."""
        if checks.enabled() and (not isinstance(self.filename, str) or not self.filename):
            raise ModelError(f'mesh: filename must be a non-empty string, got {self.filename!r}')
        if self.scale is not None:
            scale = checks.vec3('mesh', 'scale', self.scale)
            if checks.enabled() and 0.0 in scale:
                raise ModelError(f'mesh {self.filename!r}: scale must not be 0, got {scale!r}')
            object.__setattr__(self, 'scale', scale)

    def half_height(self) -> float:
        """Refuse: a mesh's extent is not known without loading it."""
        raise ModelError(
            f'Origin.above(): the height of mesh {self.filename!r} is unknown; '
            'give the origin explicitly, e.g. Origin(xyz=(0, 0, h / 2))')


Geometry = Box | Cylinder | Sphere | Capsule | Mesh


def _refuse_change(value: object, name: str, *_: object) -> None:
    """Refuse to change a value in place, saying what to assign instead."""
    kind = type(value).__name__
    owner = 'joint.origin' if kind == 'Origin' else 'visual.geometry'
    raise FrozenValueError(
        f'cannot assign to field {name!r}: {kind} is a value type, never changed in place; '
        f'assign a new one: {owner} = {kind}(...) (or {owner} = '
        f'dataclasses.replace({owner}, {name}=...))')


for _value_class in (Origin, Box, Cylinder, Sphere, Capsule, Mesh):
    setattr(_value_class, '__setattr__', _refuse_change)
    setattr(_value_class, '__delattr__', _refuse_change)
