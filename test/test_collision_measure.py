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
The measure on meshes that are no valid manifold, judged by trimesh's sampled points.

CAD meshes hold several overlapping bodies in one file, open shells and decimated meshes
with holes; the measure must count each volume once and never report an IoU above its
coverage or above 1.  The judge is trimesh alone: points drawn in the bounding box,
inside a solid when inside one of its bodies (hole-filled by trimesh).
"""

from __future__ import annotations

import json
import re

from helpers import require_module
import numpy
import pytest

from urdfgenpy_ros.collision.measure import measure
from urdfgenpy_ros.collision.parts import mesh_part

trimesh = require_module('trimesh')  # skips (naming it) without trimesh

SAMPLES = 60000


@pytest.fixture(autouse=True)
def _own_cache(tmp_path_factory, monkeypatch):
    monkeypatch.setenv('URDFGENPY_CACHE_DIR', str(tmp_path_factory.mktemp('cache')))


def _box(extents, center):
    made = trimesh.creation.box(extents)
    made.apply_translation(center)
    return made


def _judge_inside(mesh, points):
    """Return which points are inside some body of ``mesh`` (trimesh ray test)."""
    found = numpy.zeros(len(points), bool)
    for body in mesh.split(only_watertight=False):
        if not body.is_watertight:
            trimesh.repair.fill_holes(body)
        found |= body.contains(points)
    return found


def judged(original, new):
    """Return (IoU, coverage) of ``new`` against ``original`` by trimesh's points."""
    rng = numpy.random.default_rng(3)
    bounds = numpy.vstack([original.bounds, new.bounds])
    points = rng.uniform(bounds.min(axis=0), bounds.max(axis=0), size=(SAMPLES, 3))
    was, now = _judge_inside(original, points), _judge_inside(new, points)
    both = numpy.count_nonzero(was & now)
    return both / numpy.count_nonzero(was | now), both / numpy.count_nonzero(was)


def two_overlapping_boxes():
    """Return two boxes overlapping by half, in one mesh (not unioned), like CAD STLs."""
    return trimesh.util.concatenate([_box((0.1, 0.1, 0.1), (0, 0, 0)),
                                     _box((0.1, 0.1, 0.1), (0.05, 0, 0))])


def open_box():
    """Return a box with one side (two triangles) missing."""
    made = _box((0.1, 0.06, 0.04), (0, 0, 0))
    keep = numpy.ones(len(made.faces), bool)
    keep[:2] = False
    made.update_faces(keep)
    return made


def l_beam():
    """Return a closed L beam (two flanges unioned by manifold3d)."""
    return trimesh.boolean.union([_box((0.2, 0.03, 0.01), (0.1, 0, 0.005)),
                                  _box((0.01, 0.03, 0.2), (0.005, 0, 0.1))],
                                 engine='manifold')


def with_hole(mesh):
    """Return ``mesh`` with one triangle taken out (as a decimation can leave it)."""
    made = mesh.copy()
    keep = numpy.ones(len(made.faces), bool)
    keep[0] = False
    made.update_faces(keep)
    return made


def _check(measures, original, new):
    iou, coverage = judged(original, new)
    assert measures.iou <= measures.coverage + 1e-9 <= 1 + 1e-9
    assert measures.iou == pytest.approx(iou, abs=0.02)
    assert measures.coverage == pytest.approx(coverage, abs=0.02)


def test_overlapping_bodies_count_once():
    original = two_overlapping_boxes()
    hull = original.convex_hull
    _check(measure(original, [mesh_part(hull)]), original, hull)
    _check(measure(original, [mesh_part(original)]), original, original)


def test_an_open_mesh_is_measured_not_zero():
    original = open_box()
    hull = original.convex_hull
    _check(measure(original, [mesh_part(hull)]), original, hull)


def test_a_decimated_mesh_with_a_hole_is_measured():
    original = l_beam()
    holed = with_hole(original)
    measures = measure(original, [mesh_part(holed)])
    _check(measures, original, holed)
    assert measures.how in ('exact', 'sampled')


def test_a_hull_with_degenerate_faces_is_measured():
    original = l_beam()
    hull = original.convex_hull
    vertices = numpy.vstack([hull.vertices, hull.vertices[:1]])  # a zero-area triangle
    faces = numpy.vstack([hull.faces, [[0, len(vertices) - 1, 1]]])
    broken = trimesh.Trimesh(vertices, faces, process=False)
    _check(measure(original, [mesh_part(broken)]), original, hull)


def test_mjcf_decimate_is_measured_as_the_hull_mujoco_collides_with(tmp_path):
    from click.testing import CliRunner
    from collision_fixtures import l_beam as beam, write_fixtures

    from urdfgenpy_ros.cli import main
    source = write_fixtures(tmp_path, ('l_beam',))
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'robot.xml'),
                                       '--collision', 'decimate'])
    assert result.exit_code == 0, result.output
    iou = float(re.search(r'decimate: IoU ([0-9.]+)', result.output).group(1))
    solid = beam()
    assert iou == pytest.approx(solid.volume / solid.convex_hull.volume, abs=0.01)


def test_auto_says_when_no_method_reaches_the_floor(tmp_path):
    from collision_fixtures import l_beam as beam, write_fixtures

    from urdfgenpy_ros import Robot
    require_module('coacd')
    robot = Robot.from_urdf(write_fixtures(tmp_path, ('l_beam',)))
    report = robot.simplify_collisions('auto', hulls=True, max_hulls=1)
    solid = beam()
    assert solid.volume / solid.convex_hull.volume < 0.5  # trimesh: one hull cannot fit
    assert report.floor == 0.9
    line = next(line for line in report.lines() if 'K911' in line)
    assert 'no method reaches IoU 0.9' in line
    assert f'the best is {report.results[0].method}: IoU' in line


def test_auto_json_shows_the_floor_used(tmp_path):
    from click.testing import CliRunner
    from collision_fixtures import write_fixtures

    from urdfgenpy_ros.cli import main
    source = write_fixtures(tmp_path, ('cylinder_link',))
    result = CliRunner().invoke(main, ['collision', str(source), '-o', str(tmp_path / 'o.urdf'),
                                       '--method', 'auto', '--json'])
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)['min_iou'] == 0.9


def test_decompose_parts_stay_within_the_face_budget(tmp_path):
    from collision_fixtures import dense_torus

    from urdfgenpy_ros.collision.methods import decompose, Options
    require_module('coacd')
    torus = dense_torus()
    options = Options(max_faces=400, max_hulls=8)
    parts = decompose(torus, options)
    hulls = [trimesh.Trimesh(part.vertices, part.faces).convex_hull for part in parts]
    assert len(torus.faces) > 400
    assert sum(len(hull.faces) for hull in hulls) <= 400  # trimesh's (qhull's) hulls
    assert max(len(hull.vertices) for hull in hulls) <= 400 // 16 + 2


def test_a_heavier_result_is_not_called_light(tmp_path):
    from click.testing import CliRunner
    from collision_fixtures import u_bracket, write_fixtures

    from urdfgenpy_ros.cli import main
    require_module('coacd')
    source = write_fixtures(tmp_path, ('u_bracket',))
    result = CliRunner().invoke(main, ['collision', str(source), '-o', str(tmp_path / 'o.urdf'),
                                       '--method', 'decompose'])
    assert result.exit_code == 0, result.output
    written = sum(len(trimesh.load(path).faces) for path in tmp_path.glob('u_bracket_*.stl'))
    assert written > len(u_bracket().faces)  # trimesh: the parts have more faces
    assert '0 collision mesh(es) made light' in result.output
    assert 'more faces than its source had' in result.output


def _cli(*arguments):
    from click.testing import CliRunner

    from urdfgenpy_ros.cli import main
    return CliRunner().invoke(main, [str(argument) for argument in arguments])


def test_a_run_with_other_options_writes_other_files(tmp_path):
    from collision_fixtures import robot_text
    source = tmp_path / 'robot.urdf'
    trimesh.creation.icosphere(subdivisions=4, radius=0.05).export(tmp_path / 'ball.stl')
    source.write_text(robot_text({'ball': 'ball.stl'}))
    for faces in (200, 300):
        result = _cli('collision', source, '-o', tmp_path / f'o{faces}.urdf', '--method',
                      'decimate', '--max-faces', faces)
        assert result.exit_code == 0, result.output
    written = sorted(tmp_path.glob('ball_decimate_*.stl'))
    assert [len(trimesh.load(path).faces) <= 300 for path in written] == [True, True]
    assert sorted(len(trimesh.load(path).faces) for path in written)[0] <= 200


def test_a_clash_names_the_cli_option_and_prints_no_json(tmp_path):
    from collision_fixtures import write_fixtures
    source = write_fixtures(tmp_path, ('l_beam',))
    (tmp_path / 'l_beam_hull.stl').write_bytes(b'not this')
    result = _cli('collision', source, '-o', tmp_path / 'o.urdf', '--method', 'hull', '--json')
    assert result.exit_code == 2
    assert '--mesh-folder' in result.output and 'mesh_folder=' not in result.output
    assert result.stdout == ''
    assert (tmp_path / 'l_beam_hull.stl').read_bytes() == b'not this'
