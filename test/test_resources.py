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

from helpers import ament_index, CORPUS, load_yourdfpy
import pytest

from urdfgenpy_ros import Mesh, Robot
from urdfgenpy_ros.resources import PackageResolver, ResourceError


def _meshes(robot: Robot) -> list[str]:
    return [shape.geometry.filename for link in robot.links
            for shape in (*link.visuals, *link.collisions) if isinstance(shape.geometry, Mesh)]


def test_package_uris_resolve_through_search_paths() -> None:
    robot = Robot.from_urdf(CORPUS / 'urdf_tutorial/urdf/05-visual.urdf')
    resolver = PackageResolver([CORPUS])
    files = {resolver.resolve(uri) for uri in _meshes(robot)}
    assert files == {CORPUS / 'urdf_tutorial/meshes/l_finger.dae',
                     CORPUS / 'urdf_tutorial/meshes/l_finger_tip.dae'}


def test_package_uris_resolve_like_yourdfpy_does_with_the_same_map() -> None:
    path = CORPUS / 'urdf_tutorial/urdf/05-visual.urdf'
    resolver = PackageResolver([CORPUS])
    theirs = load_yourdfpy(path)
    uris = sorted({m.geometry.mesh.filename for link in theirs.links for m in link.visuals
                   if m.geometry.mesh is not None})
    assert uris == sorted(set(_meshes(Robot.from_urdf(path))))
    for uri in uris:
        assert resolver.resolve(uri).read_bytes()[:5] == b'<?xml'


def test_the_ament_index_is_used(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for key, value in ament_index(tmp_path).items():
        monkeypatch.setenv(key, value)
    found = PackageResolver().resolve('package://urdf_tutorial/meshes/l_finger.dae')
    assert found.resolve() == (CORPUS / 'urdf_tutorial/meshes/l_finger.dae').resolve()


def test_ros_package_path_is_used(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv('ROS_PACKAGE_PATH', str(CORPUS / 'husky'))
    monkeypatch.delenv('AMENT_PREFIX_PATH', raising=False)
    assert PackageResolver().find('husky_control') == CORPUS / 'husky' / 'husky_control'


def test_relative_and_file_uris(tmp_path: Path) -> None:
    resolver = PackageResolver()
    stl = CORPUS / 'pybullet_data' / 'l_finger.stl'
    assert resolver.resolve('l_finger.stl', CORPUS / 'pybullet_data') == stl
    assert resolver.resolve(stl.as_uri()) == stl


def test_unresolvable_uris_fail_only_when_needed() -> None:
    robot = Robot.from_urdf(CORPUS / 'urdf/urdf/test/pr2_desc.urdf')  # reading is fine
    uri = _meshes(robot)[0]
    with pytest.raises(ResourceError, match="package 'pr2_description' of .* not found"):
        PackageResolver([CORPUS]).resolve(uri)
    with pytest.raises(ResourceError, match='does not exist'):
        PackageResolver([CORPUS]).resolve('package://urdf_tutorial/meshes/missing.dae')
    with pytest.raises(ResourceError, match="unsupported URI scheme 'http'"):
        PackageResolver().resolve('http://example.com/a.stl')
