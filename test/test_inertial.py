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

"""The solid-body helpers agree with trimesh's volume integration of the same solids."""

from __future__ import annotations

from helpers import require_module
import pytest

from urdfgenpy_ros import Box, Cylinder, Inertial, Mesh, Sphere


@pytest.fixture
def trimesh():
    """Return trimesh, the independent integrator (skip without it)."""
    return require_module('trimesh')


def _integrated(mesh, mass: float) -> list[list[float]]:
    mesh.density = mass / mesh.volume
    return mesh.moment_inertia.tolist()


@pytest.mark.parametrize('mass, size', [(1.0, (0.2, 0.2, 0.1)), (0.8, (0.14, 0.14, 0.025)),
                                        (12.5, (1.3, 0.01, 0.4))])
def test_box_equals_integration_of_a_box_mesh(trimesh, mass: float, size: tuple) -> None:
    expected = _integrated(trimesh.creation.box(extents=size), mass)
    inertial = Inertial.from_box(mass, *size)
    for ours, theirs in zip(inertial.tensor, expected):
        assert ours == pytest.approx(tuple(theirs), rel=1e-12, abs=1e-18)
    assert Inertial.from_geometry(mass, Box(*size)) == inertial


@pytest.mark.parametrize('mass, radius, length', [(0.5, 0.05, 0.2), (0.18, 0.028, 0.07)])
def test_cylinder_converges_to_integration_of_a_fine_cylinder_mesh(
        trimesh, mass: float, radius: float, length: float) -> None:
    mesh = trimesh.creation.cylinder(radius=radius, height=length, sections=4096)
    expected = _integrated(mesh, mass)
    inertial = Inertial.from_cylinder(mass, radius, length)
    for ours, theirs in zip(inertial.tensor, expected):
        assert ours == pytest.approx(tuple(theirs), rel=1e-6, abs=1e-15)
    assert Inertial.from_geometry(mass, Cylinder(radius, length)) == inertial


def test_sphere_converges_to_integration_of_a_fine_sphere_mesh(trimesh) -> None:
    expected = _integrated(trimesh.creation.icosphere(subdivisions=7, radius=0.03), 0.1)
    inertial = Inertial.from_sphere(0.1, 0.03)
    for ours, theirs in zip(inertial.tensor, expected):
        assert ours == pytest.approx(tuple(theirs), rel=1e-4, abs=1e-15)
    assert Inertial.from_geometry(0.1, Sphere(0.03)) == inertial


def test_origin_is_kept_and_mesh_is_pointed_to_from_mesh() -> None:
    from urdfgenpy_ros import Origin
    inertial = Inertial.from_box(1.0, 1, 1, 1, origin=Origin((0, 0, 0.5)))
    assert inertial.origin.xyz == (0.0, 0.0, 0.5)
    with pytest.raises(ValueError, match='from_mesh'):
        Inertial.from_geometry(1.0, Mesh('part.stl'))


def test_matches_solid_notices_an_edit() -> None:
    inertial = Inertial.from_box(1.0, 0.2, 0.2, 0.1)
    assert inertial.matches_solid()
    inertial.mass = 2.0
    assert not inertial.matches_solid()
