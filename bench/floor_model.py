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
The least a library with the seeds' API can do to build and write a robot: a floor.

Plain classes with ``__slots__``, no check of any value, one f-string per element and
``repr`` for numbers (what any writer that keeps every digit must do). bench_build.py
runs it beside the real libraries, to show what CPython alone costs on the same calls.
Not a model to use: it accepts anything and reads nothing.
"""

from __future__ import annotations

from typing import Any


class Box:
    """A box's three sizes."""

    __slots__ = ('x', 'y', 'z')

    def __init__(self, x: float, y: float, z: float) -> None:
        self.x, self.y, self.z = x, y, z

    def text(self) -> str:
        """Return ``<box>``."""
        return f'<box size="{self.x!r} {self.y!r} {self.z!r}"/>'


class Origin:
    """A pose: xyz and rpy."""

    __slots__ = ('xyz', 'rpy')

    def __init__(self, xyz: Any = (0.0, 0.0, 0.0), rpy: Any = (0.0, 0.0, 0.0)) -> None:
        self.xyz, self.rpy = xyz, rpy

    @classmethod
    def above(cls, box: Box) -> Origin:
        """Return the origin that puts ``box`` on the frame's xy plane."""
        return cls((0.0, 0.0, box.z / 2))

    def text(self) -> str:
        """Return ``<origin>``."""
        x, y, z = self.xyz
        r, p, w = self.rpy
        return f'<origin xyz="{x!r} {y!r} {z!r}" rpy="{r!r} {p!r} {w!r}"/>'


class Visual:
    """A geometry at an origin."""

    __slots__ = ('geometry', 'origin')
    tag = 'visual'

    def __init__(self, geometry: Box, origin: Origin) -> None:
        self.geometry, self.origin = geometry, origin

    def text(self, pad: str) -> str:
        """Return the element, its lines indented by ``pad``."""
        inner = pad + '  '
        return (f'{pad}<{self.tag}>\n{inner}{self.origin.text()}\n{inner}<geometry>\n'
                f'{inner}  {self.geometry.text()}\n{inner}</geometry>\n{pad}</{self.tag}>')


class Collision(Visual):
    """The same, collided."""

    __slots__ = ()
    tag = 'collision'


class Inertial:
    """A mass and its tensor at an origin."""

    __slots__ = ('mass', 'origin', 'moments')

    def __init__(self, mass: float, origin: Origin, moments: tuple[float, float, float]) -> None:
        self.mass, self.origin, self.moments = mass, origin, moments

    @classmethod
    def from_box(cls, mass: float, x: float, y: float, z: float, origin: Origin) -> Inertial:
        """Return a solid box's inertial."""
        return cls(mass, origin, (mass * (y * y + z * z) / 12, mass * (x * x + z * z) / 12,
                                  mass * (x * x + y * y) / 12))

    def text(self, pad: str) -> str:
        """Return ``<inertial>``."""
        a, b, c = self.moments
        inner = pad + '  '
        return (f'{pad}<inertial>\n{inner}{self.origin.text()}\n{inner}<mass value='
                f'"{self.mass!r}"/>\n{inner}<inertia ixx="{a!r}" ixy="0.0" ixz="0.0" '
                f'iyy="{b!r}" iyz="0.0" izz="{c!r}"/>\n{pad}</inertial>')


class Link:
    """A name, visuals, collisions and an inertial."""

    __slots__ = ('name', 'visuals', 'collisions', 'inertial')

    def __init__(self, name: str) -> None:
        self.name = name
        self.visuals: list[Visual] = []
        self.collisions: list[Collision] = []
        self.inertial: Inertial | None = None

    def add_visual(self, visual: Visual) -> None:
        """Add a visual."""
        self.visuals.append(visual)

    def add_collision(self, collision: Collision) -> None:
        """Add a collision."""
        self.collisions.append(collision)

    def set_inertial(self, inertial: Inertial) -> None:
        """Set the inertial."""
        self.inertial = inertial

    def text(self) -> str:
        """Return ``<link>``."""
        parts = [f'  <link name="{self.name}">']
        if self.inertial is not None:
            parts.append(self.inertial.text('    '))
        parts += [visual.text('    ') for visual in self.visuals]
        parts += [collision.text('    ') for collision in self.collisions]
        parts.append('  </link>')
        return '\n'.join(parts)


class JointLimit:
    """Lower, upper, effort and velocity."""

    __slots__ = ('lower', 'upper', 'effort', 'velocity')

    def __init__(self, lower: float, upper: float, effort: float, velocity: float) -> None:
        self.lower, self.upper, self.effort, self.velocity = lower, upper, effort, velocity


class Joint:
    """A joint between two links."""

    __slots__ = ('name', 'kind', 'parent', 'child', 'origin', 'axis', 'limit')

    def __init__(self, name: str, kind: str, parent: str, child: str, origin: Origin,
                 axis: Any, limit: JointLimit) -> None:
        self.name, self.kind, self.parent, self.child = name, kind, parent, child
        self.origin, self.axis, self.limit = origin, axis, limit

    def text(self) -> str:
        """Return ``<joint>``."""
        x, y, z = self.axis
        limit = self.limit
        return (f'  <joint name="{self.name}" type="{self.kind}">\n    <parent link='
                f'"{self.parent}"/>\n    <child link="{self.child}"/>\n    '
                f'{self.origin.text()}\n    <axis xyz="{x!r} {y!r} {z!r}"/>\n    <limit '
                f'lower="{limit.lower!r}" upper="{limit.upper!r}" effort="{limit.effort!r}" '
                f'velocity="{limit.velocity!r}"/>\n  </joint>')


class Robot:
    """Links and joints by name."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.links: dict[str, Link] = {}
        self.joints: dict[str, Joint] = {}

    def add_link(self, link: Link) -> None:
        """Add a link."""
        self.links[link.name] = link

    def add_joint(self, joint: Joint) -> None:
        """Add a joint."""
        self.joints[joint.name] = joint

    def to_urdf(self) -> str:
        """Return the URDF text."""
        parts = ['<?xml version="1.0"?>', f'<robot name="{self.name}">']
        parts += [link.text() for link in self.links.values()]
        parts += [joint.text() for joint in self.joints.values()]
        parts.append('</robot>\n')
        return '\n'.join(parts)
