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
The box, cylinder, capsule or sphere that best fits a solid, by volume overlap.

Each candidate encloses the solid's convex hull (nothing a gripper touches is lost): the
oriented bounding box, trimesh's minimum cylinder, the capsule of that axis and radius
shortened as far as the points allow, and the minimum sphere. The one with the highest
intersection over union wins (measured with :mod:`urdfgenpy_ros.collision.measure`).
"""

from __future__ import annotations

from typing import Any

from urdfgenpy_ros.collision.parts import Part, pose_tuple


def candidates(solid: Any) -> list[Part]:
    """Return the enclosing sphere, capsule, box and cylinder of a solid, lightest first."""
    import numpy
    import trimesh
    points = solid.convex_hull.vertices
    center, sphere_radius = trimesh.nsphere.minimum_nsphere(points)
    sphere = Part('sphere', size=(float(sphere_radius),),
                  pose=pose_tuple(trimesh.transformations.translation_matrix(center)))
    transform, extents = trimesh.bounds.oriented_bounds(points)
    box = Part('box', size=tuple(float(x) for x in extents),
               pose=pose_tuple(numpy.linalg.inv(transform)))
    cylinder = min(_cylinders(points, numpy.linalg.inv(transform)[:3, :3].T),
                   key=lambda part: part.size[0] ** 2 * part.size[1])
    pose = numpy.asarray(cylinder.pose, float)
    return [sphere, _capsule(points, pose, cylinder.size[0]), box, cylinder]


def _cylinders(points: Any, box_axes: Any) -> list[Part]:
    """Return enclosing cylinders about trimesh's best axis, the box's and the principal."""
    import numpy
    import trimesh
    fitted = trimesh.bounds.minimum_cylinder(points)
    found = [Part('cylinder', size=(float(fitted['radius']), float(fitted['height'])),
                  pose=pose_tuple(fitted['transform']))]
    centred = points - points.mean(axis=0)
    principal = numpy.linalg.svd(centred, full_matrices=False)[2]
    for axis in (*box_axes, *principal):
        found.append(_cylinder_about(points, axis / numpy.linalg.norm(axis)))
    return found


def _cylinder_about(points: Any, axis: Any) -> Part:
    """Return the least cylinder about a direction that holds every point."""
    import trimesh
    pose = trimesh.geometry.align_vectors([0.0, 0.0, 1.0], axis)
    local = points @ pose[:3, :3]  # coordinates along the pose's axes
    (cx, cy), radius = trimesh.nsphere.minimum_nsphere(local[:, :2])
    low, high = local[:, 2].min(), local[:, 2].max()
    pose[:3, 3] = pose[:3, :3] @ [cx, cy, (low + high) / 2.0]
    return Part('cylinder', size=(float(radius), float(high - low)), pose=pose_tuple(pose))


def _capsule(points: Any, pose: Any, radius: float) -> Part:
    """
    Return the shortest capsule of ``radius`` about the cylinder axis that holds ``points``.

    A point at radial distance d and height t is inside a capsule of half-length h when
    |t| - h <= sqrt(r^2 - d^2); h is the least that holds for every point, re-centred.
    """
    import numpy
    local = (numpy.linalg.inv(pose) @ numpy.c_[points, numpy.ones(len(points))].T).T[:, :3]
    radial = numpy.hypot(local[:, 0], local[:, 1])
    reach = numpy.sqrt(numpy.clip(radius ** 2 - radial ** 2, 0.0, None))
    top = float(numpy.max(local[:, 2] - reach))  # the upper sphere's centre at least here
    bottom = float(numpy.min(local[:, 2] + reach))  # the lower one's at most here
    middle = (top + bottom) / 2.0
    shift = numpy.eye(4)
    shift[2, 3] = middle
    return Part('capsule', size=(radius, max(top - bottom, 0.0)), pose=pose_tuple(pose @ shift))


def split_capsule(part: Part) -> list[Part]:
    """Return a capsule as a cylinder and two spheres (for URDF 1.0, which has none)."""
    import numpy
    radius, length = part.size
    pose = numpy.asarray(part.pose, float)
    pieces = [Part('cylinder', size=(radius, length), pose=part.pose)]
    for end in (length / 2.0, -length / 2.0):
        shift = numpy.eye(4)
        shift[2, 3] = end
        pieces.append(Part('sphere', size=(radius,), pose=pose_tuple(pose @ shift)))
    return pieces
