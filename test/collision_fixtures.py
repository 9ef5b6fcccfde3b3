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
Non-convex collision fixtures made in the tests, and the independent measure that judges.

The shapes (a U bracket, an L beam, a gripper finger, a cylinder-like link, a dense
torus) are unions of trimesh primitives. The judge samples points with trimesh
(``contains``, ray tests) and nearest points on surfaces: it shares nothing with
``urdfgenpy_ros.collision.measure``, which uses manifold3d's exact booleans.
"""

from __future__ import annotations

from pathlib import Path

from helpers import require_module
import numpy

trimesh = require_module('trimesh')  # skips (naming it) without trimesh

SAMPLES = 40000


def _box(extents, center):
    made = trimesh.creation.box(extents)
    made.apply_translation(center)
    return made


def _union(parts):
    return trimesh.boolean.union(parts, engine='manifold')


def u_bracket():
    """Return a U bracket: a 0.12 m base and two 0.08 m arms, a 0.08 m gap between."""
    return _union([_box((0.12, 0.04, 0.02), (0, 0, 0.01)),
                   _box((0.02, 0.04, 0.08), (-0.05, 0, 0.06)),
                   _box((0.02, 0.04, 0.08), (0.05, 0, 0.06))])


def l_beam():
    """Return an L beam: two 0.2 m flanges at a right angle."""
    return _union([_box((0.2, 0.03, 0.01), (0.1, 0, 0.005)),
                   _box((0.01, 0.03, 0.2), (0.005, 0, 0.1))])


def gripper_finger():
    """Return a gripper finger: a mount, a long finger and an inward hook at its tip."""
    return _union([_box((0.04, 0.03, 0.02), (0, 0, 0.01)),
                   _box((0.01, 0.03, 0.1), (0.015, 0, 0.07)),
                   _box((0.03, 0.03, 0.01), (0.0, 0, 0.115))])


def cylinder_link():
    """Return a cylinder-like link: a tessellated cylinder, 0.04 m radius, 0.3 m long."""
    made = trimesh.creation.cylinder(0.04, 0.3, sections=40)
    made.apply_transform(trimesh.transformations.rotation_matrix(0.7, (1, 1, 0)))
    made.apply_translation((0.01, 0.02, 0.15))
    return made


def dense_torus():
    """Return a dense torus (about 20,000 faces)."""
    return trimesh.creation.torus(0.1, 0.03, major_sections=200, minor_sections=50)


SHAPES = {'u_bracket': u_bracket, 'l_beam': l_beam, 'gripper_finger': gripper_finger,
          'cylinder_link': cylinder_link}


def robot_text(meshes: dict[str, str], version: str | None = None) -> str:
    """Return a URDF of one link per mesh (link name: mesh file), chained by fixed joints."""
    names = list(meshes)
    links = ''.join(
        f'  <link name="{name}">\n'
        f'    <visual>\n      <geometry><mesh filename="{file}"/></geometry>\n    </visual>\n'
        f'    <collision>\n      <origin xyz="0 0 0.01" rpy="0 0 0.3"/>\n'
        f'      <geometry><mesh filename="{file}"/></geometry>\n    </collision>\n'
        '    <inertial><mass value="0.5"/><inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" '
        'iyz="0" izz="0.001"/></inertial>\n  </link>\n' for name, file in meshes.items())
    joints = ''.join(f'  <joint name="j{index}" type="fixed"><parent link="{parent}"/>'
                     f'<child link="{child}"/><origin xyz="0 0 0.3"/></joint>\n'
                     for index, (parent, child) in enumerate(zip(names, names[1:])))
    attribute = f' version="{version}"' if version else ''
    return f'<?xml version="1.0"?>\n<robot name="fixtures"{attribute}>\n{links}{joints}</robot>\n'


def write_fixtures(folder: Path, names=tuple(SHAPES)) -> Path:
    """Write the named shapes as STL and a robot of them into ``folder``; return the URDF."""
    for name in names:
        SHAPES[name]().export(folder / f'{name}.stl')
    path = folder / 'robot.urdf'
    path.write_text(robot_text({name: f'{name}.stl' for name in names}))
    return path


def solid_of(shapes):
    """Return the closed solids of a link's collision shapes as one list (in link frame)."""
    return list(shapes)


def sampled(original, shapes, seed: int = 7) -> tuple[float, float]:
    """
    Return (IoU, coverage) of ``shapes`` (closed trimesh meshes) against ``original``.

    Points are drawn uniformly in the box around both; each is inside a solid by
    trimesh's ray test.
    """
    rng = numpy.random.default_rng(seed)
    bounds = numpy.vstack([original.bounds] + [shape.bounds for shape in shapes])
    low, high = bounds.min(axis=0), bounds.max(axis=0)
    points = rng.uniform(low, high, size=(SAMPLES, 3))
    inside_a = original.contains(points)
    inside_b = numpy.zeros(len(points), bool)
    for shape in shapes:
        inside_b |= shape.contains(points)
    both = numpy.count_nonzero(inside_a & inside_b)
    either = numpy.count_nonzero(inside_a | inside_b)
    return both / either, both / numpy.count_nonzero(inside_a)


def coverage_inside(original, shapes, seed: int = 7) -> float:
    """Return the share of points drawn inside ``original`` that some shape contains."""
    rng = numpy.random.default_rng(seed)
    points = numpy.empty((0, 3))
    while len(points) < SAMPLES // 4:
        drawn = rng.uniform(*original.bounds, size=(SAMPLES, 3))
        points = numpy.vstack([points, drawn[original.contains(drawn)]])
    inside = numpy.zeros(len(points), bool)
    for shape in shapes:
        inside |= shape.contains(points)
    return float(numpy.count_nonzero(inside) / len(points))


def surface_distance(a, b, count: int = 5000) -> float:
    """Return the largest distance from points on either surface to the other surface."""
    worst = 0.0
    for one, other in ((a, b), (b, a)):
        points, _ = trimesh.sample.sample_surface(one, count, seed=3)
        _, distances, _ = trimesh.proximity.closest_point(other, points)
        worst = max(worst, float(distances.max()))
    return worst
