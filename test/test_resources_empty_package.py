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

"""``package:///pkg/x.stl`` (no package name) is read as pinocchio and yourdfpy read it."""

from __future__ import annotations

from importlib import metadata
from pathlib import Path

from click.testing import CliRunner
from helpers import require_module
import pytest

from urdfgenpy_ros import Mesh, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.resources import PackageResolver, uri_warning

ROBOT = """<?xml version="1.0"?>
<robot name="r">
  <link name="base_link"><collision><geometry>
    <mesh filename="package:///my-robot-data/meshes/cube.stl"/></geometry></collision>
    <inertial><mass value="1"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
</robot>
"""


@pytest.fixture
def share(tmp_path: Path) -> Path:
    """Write a folder of packages holding my-robot-data, whose URDF names its mesh so."""
    trimesh = require_module('trimesh')
    package = tmp_path / 'share' / 'my-robot-data'
    (package / 'meshes').mkdir(parents=True)
    (package / 'robots').mkdir()
    trimesh.creation.box(extents=(0.1, 0.1, 0.1)).export(package / 'meshes' / 'cube.stl')
    (package / 'package.xml').write_text('<package format="3"><name>my-robot-data</name>'
                                         '</package>')
    (package / 'robots' / 'r.urdf').write_text(ROBOT)
    return tmp_path / 'share'


def _pinocchio_paths(urdf: Path, share: Path) -> list[Path]:
    pinocchio = require_module('pinocchio')
    model = pinocchio.buildModelFromUrdf(str(urdf))
    geometry = pinocchio.buildGeomFromUrdf(model, str(urdf), pinocchio.GeometryType.COLLISION,
                                           package_dirs=[str(share)])
    return [Path(item.meshPath).resolve() for item in geometry.geometryObjects
            if '/' in item.meshPath]  # not its BOX, CYLINDER


def test_the_file_is_the_one_pinocchio_and_yourdfpy_find(share: Path) -> None:
    yourdfpy = require_module('yourdfpy')
    urdf = share / 'my-robot-data' / 'robots' / 'r.urdf'
    uri = 'package:///my-robot-data/meshes/cube.stl'
    ours = PackageResolver([share]).resolve(uri, urdf.parent).resolve()
    assert [ours] == _pinocchio_paths(urdf, share)
    theirs = yourdfpy.urdf.filename_handler_magic(uri, dir=str(urdf.parent))
    assert Path(theirs).resolve() == ours
    assert PackageResolver().resolve(uri, urdf.parent).resolve() == ours  # as yourdfpy: above
    said = uri_warning(uri)
    assert said is not None and 'resource_retriever (RViz) does not find it: write ' \
        'package://my-robot-data/meshes/cube.stl' in said


def test_check_and_convert_read_it_and_say_ros_does_not(share: Path, tmp_path: Path) -> None:
    urdf = share / 'my-robot-data' / 'robots' / 'r.urdf'
    result = CliRunner().invoke(main, ['check', str(urdf), '-p', str(share)])
    assert ' R303 ' not in result.output and ' R308 ' in result.output, result.output
    out = tmp_path / 'r.xml'
    result = CliRunner().invoke(main, ['convert', str(urdf), str(out), '-p', str(share)])
    assert result.exit_code == 0, result.output
    mujoco = require_module('mujoco')
    assert mujoco.MjModel.from_xml_path(str(out)).nmesh == 1


def test_example_robot_data_talos_meshes_as_pinocchio_finds_them() -> None:
    try:
        share = Path(str(metadata.distribution('example-robot-data').locate_file(
            'cmeel.prefix/share')))
    except metadata.PackageNotFoundError:
        pytest.skip('example-robot-data is not installed (pip install example-robot-data)')
    urdf = share / 'example-robot-data/robots/talos_data/robots/talos_full_v2.urdf'
    robot = Robot.from_urdf(urdf)
    resolver = PackageResolver([share])
    uris = [item.geometry.filename for link in robot.links for item in link.collisions
            if isinstance(item.geometry, Mesh)]
    assert any(uri.startswith('package:///') for uri in uris)
    ours = [resolver.resolve(uri, urdf.parent).resolve() for uri in uris]
    assert set(ours) == set(_pinocchio_paths(urdf, share))
