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
Mirrored meshes as RViz reads them: a DAE keeps its colours, URIs are never bare paths.

Judges: trimesh reads the source and the mirrored file (colours per material, triangles);
the source's unit is read with lxml (mesh_judge); the URIs are read back by yourdfpy.
"""

from __future__ import annotations

import os
from pathlib import Path
import subprocess
import sys

from click.testing import CliRunner
from helpers import require_module
import mesh_judge
import numpy
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main

ARM = ('<robot name="r"><link name="base_link"/><link name="left_arm"><visual><geometry>'
       '<mesh filename="{mesh}"/></geometry></visual></link>'
       '<joint name="left_j" type="revolute"><parent link="base_link"/><child '
       'link="left_arm"/><origin xyz="0 0.2 0"/><axis xyz="1 0 0"/><limit lower="-1" '
       'upper="0" effort="1" velocity="1"/></joint></robot>')


def _colours(path: Path) -> list[tuple[int, ...]]:
    trimesh = require_module('trimesh')
    scene = trimesh.load(str(path), force='scene', process=False)
    return sorted(tuple(int(value) for value in geometry.visual.material.baseColorFactor)
                  for geometry in scene.geometry.values())


def _mirror(source: Path, *options: str):
    result = CliRunner().invoke(main, ['mirror', str(source), '--root', 'left_arm', *options])
    assert result.exit_code == 0, result.output
    return result


def test_a_mirrored_dae_keeps_its_colours_and_rviz_place(tmp_path: Path) -> None:
    trimesh = require_module('trimesh')
    require_module('collada')
    mesh_judge.write_y_up_dae(tmp_path / 'part.dae')
    (tmp_path / 'arm.urdf').write_text(ARM.format(mesh='part.dae'))
    result = _mirror(tmp_path / 'arm.urdf', '-o', str(tmp_path / 'both.urdf'))
    assert 'warning' not in result.output  # no texture it does not have
    mirrored = tmp_path / 'part_mirror_xz.dae'
    assert _colours(mirrored) == _colours(tmp_path / 'part.dae')  # not white
    source = mesh_judge.rviz_vertices(tmp_path / 'part.dae')
    written = mesh_judge.rviz_vertices(mirrored)
    reflected = source * (1.0, -1.0, 1.0)
    mine, theirs = (numpy.unique(numpy.round(points, 6), axis=0)  # pycollada reads float32
                    for points in (written, reflected))
    assert mine.shape == theirs.shape and numpy.allclose(mine, theirs, rtol=0.0, atol=1e-8)
    volume = trimesh.load(str(mirrored), force='mesh').volume
    assert volume == pytest.approx(trimesh.load(str(tmp_path / 'part.dae'),
                                                force='mesh').volume * 1e-9, rel=1e-6)
    assert volume > 0  # wound outward


def test_pandas_hand_keeps_its_three_colours(tmp_path: Path) -> None:
    require_module('trimesh')
    from importlib import metadata
    try:
        hand = Path(str(metadata.distribution('example-robot-data').locate_file(
            'cmeel.prefix/share/example-robot-data/robots/panda_description/meshes/visual/'
            'hand.dae')))
    except metadata.PackageNotFoundError:
        pytest.skip('example-robot-data is not installed (pip install example-robot-data)')
    (tmp_path / 'arm.urdf').write_text(ARM.format(mesh=hand))
    _mirror(tmp_path / 'arm.urdf', '--mesh-folder', str(tmp_path / 'mf'), '-o',
            str(tmp_path / 'both.urdf'))
    mine = sorted(set(_colours(tmp_path / 'mf' / 'hand_mirror_xz.dae')))
    assert mine == sorted(set(_colours(hand))) and len(mine) == 3


def test_mesh_folder_uris_are_package_or_file_uris(tmp_path: Path) -> None:
    require_module('trimesh')
    yourdfpy = require_module('yourdfpy')
    mesh_judge.write_y_up_dae(tmp_path / 'part.dae')
    (tmp_path / 'arm.urdf').write_text(ARM.format(mesh='part.dae'))
    package = tmp_path / 'ws' / 'my_meshes'
    package.mkdir(parents=True)
    (package / 'package.xml').write_text('<package format="3"><name>my_meshes</name>'
                                         '</package>')
    _mirror(tmp_path / 'arm.urdf', '--mesh-folder', str(package / 'meshes'), '-p',
            str(tmp_path / 'ws'), '-o', str(tmp_path / 'in_package.urdf'))
    _mirror(tmp_path / 'arm.urdf', '--mesh-folder', str(tmp_path / 'loose'), '-o',
            str(tmp_path / 'loose.urdf'))
    packaged = Robot.from_urdf(tmp_path / 'in_package.urdf').get_link('right_arm')
    loose = Robot.from_urdf(tmp_path / 'loose.urdf').get_link('right_arm')
    assert packaged.visuals[0].geometry.filename == \
        'package://my_meshes/meshes/part_mirror_xz.dae'
    uri = loose.visuals[0].geometry.filename
    assert uri == (tmp_path / 'loose' / 'part_mirror_xz.dae').as_uri()
    model = yourdfpy.URDF.load(str(tmp_path / 'loose.urdf'), load_meshes=True,
                               build_scene_graph=True)
    assert len(model.scene.geometry) >= 2  # another reader opens the file:// URI


def test_a_mirror_image_is_taken_from_the_cache(tmp_path: Path, monkeypatch) -> None:
    require_module('trimesh')
    from urdfgenpy_ros import mesh_cache
    from urdfgenpy_ros.reshape import mirror_mesh
    monkeypatch.setenv('URDFGENPY_CACHE_DIR', str(tmp_path / 'cache'))
    monkeypatch.setattr(mesh_cache, '_memory', {})
    mesh_judge.write_y_up_dae(tmp_path / 'part.dae')
    (tmp_path / 'arm.urdf').write_text(ARM.format(mesh='part.dae'))
    _mirror(tmp_path / 'arm.urdf', '--mesh-folder', str(tmp_path / 'a'), '-o',
            str(tmp_path / 'a.urdf'))

    def refuse(path: Path, axis: int) -> bytes:
        raise AssertionError(f'{path} reflected again')
    monkeypatch.setattr(mirror_mesh, '_reflected_dae', refuse)
    monkeypatch.setattr(mesh_cache, '_memory', {})  # another process: the folder only
    _mirror(tmp_path / 'arm.urdf', '--mesh-folder', str(tmp_path / 'b'), '-o',
            str(tmp_path / 'b.urdf'))
    assert (tmp_path / 'a' / 'part_mirror_xz.dae').read_bytes() == \
        (tmp_path / 'b' / 'part_mirror_xz.dae').read_bytes()


def test_a_mirror_written_again_loads_no_mesh_library(tmp_path: Path) -> None:
    require_module('collada')
    mesh_judge.write_y_up_dae(tmp_path / 'part.dae')
    (tmp_path / 'arm.urdf').write_text(ARM.format(mesh='part.dae'))
    run = ('import sys\nfrom urdfgenpy_ros.cli import main\n'
           'main.main(sys.argv[1:], standalone_mode=False)\n'
           "print(sorted(m for m in ('trimesh', 'scipy') if m in sys.modules))")
    arguments = ['mirror', str(tmp_path / 'arm.urdf'), '--root', 'left_arm', '--mesh-folder',
                 str(tmp_path / 'meshes'), '-o', str(tmp_path / 'both.urdf'), '--force']
    environment = {**os.environ, 'URDFGENPY_CACHE_DIR': str(tmp_path / 'cache')}
    for _ in range(2):  # the second finds its mirror image in the folder, byte for byte
        result = subprocess.run([sys.executable, '-c', run, *arguments], capture_output=True,
                                text=True, env=environment, timeout=120)
        assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[-1] == '[]'
    assert (tmp_path / 'meshes' / 'part_mirror_xz.dae').exists()
