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

"""Mesh inertia: exact on closed solids, equal to trimesh's on real meshes, MeshLab's too."""

from __future__ import annotations

from pathlib import Path
import re
import warnings

from click.testing import CliRunner
from helpers import CORPUS, REPO, require_module
import pytest

from urdfgenpy_ros import Inertial, UrdfgenpyError
from urdfgenpy_ros.cli import main

trimesh = require_module('trimesh')
numpy = require_module('numpy')


def _tensor(inertial: Inertial):
    return numpy.array(inertial.tensor)


def _box_obj(path: Path, size: tuple[float, float, float],
             centre: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> Path:
    """Write a closed box as OBJ text (STL would round the vertices to float32)."""
    box = trimesh.creation.box(extents=size)
    lines = [f'v {x + centre[0]!r} {y + centre[1]!r} {z + centre[2]!r}'
             for x, y, z in box.vertices.tolist()]
    lines += [f'f {a + 1} {b + 1} {c + 1}' for a, b, c in box.faces.tolist()]
    path.write_text('\n'.join(lines) + '\n')
    return path


def test_closed_box_mesh_equals_the_closed_form_box(tmp_path: Path) -> None:
    path = _box_obj(tmp_path / 'box.obj', (0.2, 0.3, 0.5), (1.0, -2.0, 0.5))
    inertial = Inertial.from_mesh(str(path), mass=3.0)
    expected = Inertial.from_box(3.0, 0.2, 0.3, 0.5)
    scale = abs(_tensor(expected)).max()  # relative to the tensor (its zeros have no scale)
    assert abs(_tensor(inertial) - _tensor(expected)).max() <= 1e-9 * scale
    assert inertial.origin.xyz == pytest.approx((1.0, -2.0, 0.5), abs=1e-12)
    by_density = Inertial.from_mesh(str(path), density=100.0)
    assert by_density.mass == pytest.approx(100.0 * 0.2 * 0.3 * 0.5, rel=1e-12)


@pytest.mark.parametrize('name', ['pybullet_data/cube.obj',
                                  'pybullet_data/quadruped/tmotor3.obj',
                                  'urdf_tutorial/meshes/l_finger.dae',
                                  'urdf_tutorial/meshes/l_finger_tip.dae'])
def test_corpus_meshes_agree_with_trimesh_mass_properties(name: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter('ignore')
        inertial = Inertial.from_mesh(str(CORPUS / name), mass=2.0)
        theirs = trimesh.load(str(CORPUS / name), force='mesh')
    theirs.density = 2.0 / theirs.volume
    scale = abs(theirs.moment_inertia).max()
    assert abs(_tensor(inertial) - theirs.moment_inertia).max() <= 1e-9 * scale
    assert numpy.allclose(inertial.origin.xyz, theirs.center_mass, rtol=0, atol=1e-12)


def test_open_mesh_is_refused_with_the_fix() -> None:
    with pytest.raises(UrdfgenpyError, match=r'l_finger\.stl: the mesh is not closed '
                                             r'\(\d+ open edge\(s\)\).*Close Holes'):
        Inertial.from_mesh(str(CORPUS / 'pybullet_data/l_finger.stl'), mass=1.0)


def test_millimetre_sized_mesh_gets_a_hint(tmp_path: Path) -> None:
    path = _box_obj(tmp_path / 'part_mm.obj', (200.0, 300.0, 500.0))
    with pytest.warns(UserWarning, match='millimetres.*scale=\\(0.001'):
        Inertial.from_mesh(str(path), mass=1.0)
    scaled = Inertial.from_mesh(str(path), mass=1.0, scale=(0.001, 0.001, 0.001))
    assert _tensor(scaled) == pytest.approx(_tensor(Inertial.from_box(1.0, 0.2, 0.3, 0.5)))


def test_seed_meshlab_example_reproduces_every_printed_digit() -> None:
    seed = (REPO.parent / 'shared' / 'seeds' / '002_b9e7bb39b77f9ff8.txt')
    if not seed.is_file():
        pytest.skip('seed not found')
    text = seed.read_text()
    rows = re.search(r'Inertia Tensor is :\n((?:\s+[-\d. ]+\n){3})', text).group(1)
    tensor = [[float(v) for v in row.split()] for row in rows.strip().splitlines()]
    printed = dict(re.findall(r'(i[xyz]{2})="([-\d.]+)"', text))
    inertial = Inertial.from_meshlab(0.0105, 15253.618164, tensor)
    for name, value in printed.items():
        assert f'{getattr(inertial, name):.16f}' == value, name


def test_cli_inertia_for_a_mesh_and_for_meshlab(tmp_path: Path) -> None:
    path = _box_obj(tmp_path / 'box.obj', (0.1, 0.1, 0.1))
    result = CliRunner().invoke(main, ['inertia', str(path), '--mass', '1'])
    assert result.exit_code == 0, result.output
    assert '<mass value="1"/>' in result.stdout and 'ixx="0.0016666666666666' in result.stdout
    meshlab = CliRunner().invoke(main, [
        'inertia', '--meshlab', '--mass', '0.0105', '--volume', '15253.618164', '--tensor',
        '8171479.5 -1091.582153 858.932007 -1091.582153 6636559.0 29447.435547 858.932007 '
        '29447.435547 2481984.75'])
    assert meshlab.exit_code == 0 and 'ixx="5.6249300216847885e-06"' in meshlab.stdout
    refused = CliRunner().invoke(main, ['inertia', str(CORPUS / 'pybullet_data/l_finger.stl'),
                                        '--mass', '1'])
    assert refused.exit_code == 2 and 'not closed' in refused.stderr
