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

"""package:// and file:// resolution through search paths, the ament index and the env."""

from __future__ import annotations

from pathlib import Path

from helpers import ament_index, FIXTURE_PACKAGES, FIXTURES, load_yourdfpy
import pytest

from urdfgenpy_ros import Mesh, Robot
from urdfgenpy_ros.resources import PackageResolver, ResourceError


def _meshes(robot: Robot) -> list[str]:
    return [shape.geometry.filename for link in robot.links
            for shape in (*link.visuals, *link.collisions) if isinstance(shape.geometry, Mesh)]


PACKAGES = FIXTURES / 'packages'
EVERY = PACKAGES / 'fixture_description/urdf/every_element.urdf'
CUBE = PACKAGES / 'fixture_description/meshes/cube.stl'


def test_package_uris_resolve_through_search_paths() -> None:
    robot = Robot.from_urdf(EVERY)
    resolver = PackageResolver([PACKAGES])
    assert {resolver.resolve(uri) for uri in _meshes(robot)} == {CUBE.absolute()}


def test_package_uris_resolve_like_yourdfpy_does_with_the_same_map() -> None:
    resolver = PackageResolver([PACKAGES])
    theirs = load_yourdfpy(EVERY)
    uris = sorted({m.geometry.mesh.filename for link in theirs.links
                   for m in (*link.visuals, *link.collisions) if m.geometry.mesh is not None})
    assert uris == sorted(set(_meshes(Robot.from_urdf(EVERY))))
    for uri in uris:
        assert resolver.resolve(uri).read_bytes()[:5] == b'solid'


def test_the_ament_index_is_used(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for key, value in ament_index(tmp_path, FIXTURE_PACKAGES).items():
        monkeypatch.setenv(key, value)
    found = PackageResolver().resolve('package://fixture_description/meshes/cube.stl')
    assert found.resolve() == CUBE.resolve()


def test_ros_package_path_is_used(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv('ROS_PACKAGE_PATH', str(PACKAGES))
    monkeypatch.delenv('AMENT_PREFIX_PATH', raising=False)
    assert PackageResolver().find('fixture_description') == PACKAGES / 'fixture_description'


def test_relative_and_file_uris(tmp_path: Path) -> None:
    resolver = PackageResolver()
    assert resolver.resolve('cube.stl', CUBE.parent) == CUBE
    assert resolver.resolve(CUBE.as_uri()) == CUBE


def test_unresolvable_uris_fail_only_when_needed() -> None:
    robot = Robot.from_urdf(EVERY)  # reading is fine
    uri = _meshes(robot)[0]
    with pytest.raises(ResourceError, match="package 'fixture_description' of .* not found"):
        PackageResolver([FIXTURES / 'robots']).resolve(uri)
    with pytest.raises(ResourceError, match='does not exist'):
        PackageResolver([PACKAGES]).resolve('package://fixture_description/meshes/gone.dae')
    with pytest.raises(ResourceError, match="unsupported URI scheme 'http'"):
        PackageResolver().resolve('http://example.com/a.stl')
