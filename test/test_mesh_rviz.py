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
Meshes in MJCF as RViz shows them: placed (up axis ignored, unit applied), coloured, read.

Judges: MuJoCo compiles every written model and its meshes; the geometry it compiled is
compared with the source meshes read as RViz reads them (mesh_judge: trimesh's vertices,
the unit read with lxml, yourdfpy's kinematics); colours with the DAE's own numbers.
"""

from __future__ import annotations

from pathlib import Path

from helpers import CORPUS, CORPUS_PACKAGES, require_module
import mesh_judge
import numpy
import pytest
import registry_robots

from urdfgenpy_ros import Inertial, Joint, Link, Origin, Robot
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.formats.mjcf import write_mjcf
from urdfgenpy_ros.model.geometry import Mesh
from urdfgenpy_ros.model.link import Collision, Visual

BAD_OBJ = """# a SolidWorks-style OBJ: faces name normal 7 of the file's 1
v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
vn 0 0 1
f 1//1 3//1 2//1
f 1//7 2//7 4//7
f 1//1 4//1 3//1
f 2//1 3//1 4//1
"""


def _robot(mesh: Path, collision: bool = False) -> Robot:
    visuals = [Visual(Mesh(str(mesh)), origin=Origin((0.1, 0.0, 0.2), (0.3, 0.2, 0.1)))]
    robot = Robot('part').add_link(Link('base_link', inertial=Inertial.from_box(
        1.0, 0.1, 0.1, 0.1))).add_link(Link(
            'part', inertial=Inertial.from_box(1.0, 0.1, 0.1, 0.1), visuals=visuals,
            collisions=[Collision(Mesh(str(mesh)))] if collision else []))
    robot.add_joint(Joint('weld', 'fixed', 'base_link', 'part',
                          origin=Origin((0.0, 0.0, 1.0), (0.0, 0.0, 0.5))))
    return robot


def _compiled(robot: Robot, out: Path, search_paths: list[Path] | None = None):
    import mujoco
    result = write_mjcf(robot, out / 'robot.xml', search_paths=search_paths or [])
    return mujoco.MjModel.from_xml_path(str(out / 'robot.xml')), result


def test_a_y_up_dae_is_placed_and_coloured_as_rviz_shows_it(tmp_path: Path) -> None:
    require_module('mujoco')
    require_module('trimesh')
    require_module('yourdfpy')
    mesh_judge.write_y_up_dae(tmp_path / 'part.dae')
    robot = _robot(tmp_path / 'part.dae', collision=True)
    robot.to_urdf(tmp_path / 'part.urdf')
    model, _ = _compiled(robot, tmp_path / 'out')
    theirs = mesh_judge.source_boxes(tmp_path / 'part.urdf', [])
    ours = mesh_judge.written_boxes(model)
    assert set(ours) == set(theirs) == {'part'}
    assert numpy.allclose(ours['part'], theirs['part'], rtol=0.0, atol=1e-6)  # float32
    colours = sorted(tuple(model.mat_rgba[model.geom_matid[geom]].tolist())
                     for geom in range(model.ngeom) if model.geom_group[geom] == 2)
    assert numpy.allclose(colours, sorted([mesh_judge.RED, mesh_judge.BLUE]), rtol=0.0,
                          atol=1e-7)  # one geom per colour, as float32 holds it
    collision = [geom for geom in range(model.ngeom) if model.geom_group[geom] == 3]
    assert len(collision) == 1  # the collision takes every triangle, one mesh


def test_a_dae_colour_wins_over_the_urdf_material_as_in_rviz(tmp_path: Path) -> None:
    require_module('mujoco')
    from urdfgenpy_ros.model.material import Material
    mesh_judge.write_y_up_dae(tmp_path / 'part.dae')
    robot = _robot(tmp_path / 'part.dae')
    robot.get_link('part').visuals[0].material = Material('grey', (0.5, 0.5, 0.5, 1.0))
    model, _ = _compiled(robot, tmp_path / 'out')
    rgba = sorted(tuple(model.mat_rgba[model.geom_matid[geom]].tolist()) for geom
                  in range(model.ngeom) if model.geom_group[geom] == 2)
    assert numpy.allclose(rgba, sorted([mesh_judge.RED, mesh_judge.BLUE]), rtol=0.0,
                          atol=1e-7)


def test_inertia_of_a_y_up_dae_is_not_turned(tmp_path: Path) -> None:
    trimesh = require_module('trimesh')
    mesh_judge.write_y_up_dae(tmp_path / 'part.dae')
    inertial = Inertial.from_mesh(str(tmp_path / 'part.dae'), density=1000.0)
    theirs = trimesh.load(str(tmp_path / 'part.dae'), force='mesh')
    theirs.apply_scale(0.001)  # the file's unit; its up axis ignored, as RViz
    assert inertial.mass == pytest.approx(theirs.volume * 1000.0, rel=1e-9)
    assert numpy.allclose(inertial.origin.xyz, theirs.center_mass, rtol=0.0, atol=1e-12)


def test_an_obj_mujoco_refuses_is_rewritten_and_said(tmp_path: Path) -> None:
    mujoco = require_module('mujoco')
    require_module('trimesh')
    (tmp_path / 'part.obj').write_text(BAD_OBJ)
    with pytest.raises(ValueError, match='normal index out of bounds'):  # as the vendor wrote
        mujoco.MjModel.from_xml_string('<mujoco><asset><mesh file="part.obj"/></asset>'
                                       '</mujoco>', {'part.obj': BAD_OBJ.encode()})
    robot = _robot(tmp_path / 'part.obj', collision=True)
    robot.to_urdf(tmp_path / 'part.urdf')
    model, result = _compiled(robot, tmp_path / 'out')
    said = [note for note in result.notes if 'part.obj' in note]
    assert len(said) == 1 and 'MuJoCo cannot read it as written' in said[0]
    assert 'normal index out of bounds' in said[0]
    ours = mesh_judge.written_boxes(model)
    theirs = mesh_judge.source_boxes(tmp_path / 'part.urdf', [])
    assert numpy.allclose(ours['part'], theirs['part'], rtol=0.0, atol=1e-6)  # float32
    assert model.nmesh == 1  # the rewrite serves the visual and the collision


def test_a_mesh_nobody_reads_is_refused_naming_the_file(tmp_path: Path) -> None:
    require_module('mujoco')
    require_module('trimesh')
    (tmp_path / 'part.obj').write_text('v 0 0 0\nf 1 5 9\n')
    model, result = _compiled(_robot(tmp_path / 'part.obj'), tmp_path / 'out')
    assert model.nmesh == 0  # its geom left out, the rest compiles
    assert [finding.code for finding in result.findings if 'part.obj' in finding.message] \
        == ['M809']


def test_a_texture_not_carried_is_said(tmp_path: Path) -> None:
    require_module('mujoco')
    text = mesh_judge.Y_UP_DAE.replace(
        '<effect id="red-fx"><profile_COMMON>', '<effect id="red-fx"><profile_COMMON>'
        '<newparam sid="s"><surface type="2D"><init_from>img</init_from></surface>'
        '</newparam><newparam sid="m"><sampler2D><source>s</source></sampler2D></newparam>'
        ).replace('<diffuse><color>0.8 0.1 0.2 1</color></diffuse>',
                  '<diffuse><texture texture="m" texcoord="uv"/></diffuse>').replace(
        '<library_effects>', '<library_images><image id="img"><init_from>part.png'
        '</init_from></image></library_images><library_effects>')
    mesh_judge.write_y_up_dae(tmp_path / 'plain.dae')
    geometry = (tmp_path / 'plain.dae').read_text()
    start = geometry.index('<library_geometries>')
    end = geometry.index('</library_geometries>') + len('</library_geometries>')
    (tmp_path / 'part.dae').write_text(text.replace(
        '<library_geometries>{geometries}</library_geometries>', geometry[start:end]))
    model, result = _compiled(_robot(tmp_path / 'part.dae'), tmp_path / 'out')
    said = [note for note in result.notes if 'texture' in note]
    assert len(said) == 1 and str(tmp_path / 'part.dae') in said[0]
    assert model.nmesh == 2


def test_a_conversion_is_taken_from_the_cache(tmp_path: Path, monkeypatch) -> None:
    require_module('trimesh')
    from urdfgenpy_ros import mesh_cache
    from urdfgenpy_ros.formats.mjcf import mesh_convert
    monkeypatch.setenv('URDFGENPY_CACHE_DIR', str(tmp_path / 'cache'))
    monkeypatch.setattr(mesh_cache, '_memory', {})
    mesh_judge.write_y_up_dae(tmp_path / 'part.dae')
    first = write_mjcf(_robot(tmp_path / 'part.dae'), tmp_path / 'a' / 'robot.xml')
    assert any((tmp_path / 'cache').rglob('obj*'))  # kept in the folder the variable names

    def refuse(path: Path) -> None:
        raise AssertionError(f'{path} converted again')
    monkeypatch.setattr(mesh_convert, '_convert', refuse)
    monkeypatch.setattr(mesh_cache, '_memory', {})  # another process: the folder only
    second = write_mjcf(_robot(tmp_path / 'part.dae'), tmp_path / 'b' / 'robot.xml')
    assert first.text == second.text
    files = sorted(path.name for path in (tmp_path / 'b' / 'assets').iterdir())
    assert files == sorted(path.name for path in (tmp_path / 'a' / 'assets').iterdir())
    for name in files:
        assert (tmp_path / 'a' / 'assets' / name).read_bytes() == \
            (tmp_path / 'b' / 'assets' / name).read_bytes()


def test_many_conversions_in_worker_processes_equal_one_by_one(
        tmp_path: Path, monkeypatch) -> None:
    trimesh = require_module('trimesh')
    from urdfgenpy_ros import mesh_cache
    from urdfgenpy_ros.formats.mjcf import mesh_convert
    paths = []
    for number in range(5):
        box = trimesh.creation.box((0.1 * (number + 1), 0.2, 0.3))
        paths.append(tmp_path / f'part{number}.ply')
        box.export(str(paths[-1]))
    monkeypatch.setenv('URDFGENPY_CACHE_DIR', 'off')
    monkeypatch.setattr(mesh_cache, '_memory', {})
    mesh_convert.convert_many(paths)
    if (__import__('os').cpu_count() or 1) < 2:
        pytest.skip('one processor: conversions run one by one')
    parallel = [mesh_cache.get(mesh_convert._key(path)) for path in paths]
    assert all(parallel)
    ones = [mesh_convert._convert(path).encode() for path in paths]
    assert parallel == ones


def _dae_robots() -> list:
    """Return the registry, example-robot-data and corpus robots whose visuals name a DAE."""
    found = [(path, registry_robots.search_paths(), []) for path in registry_robots.robots()]
    if CORPUS.is_dir():
        folders = sorted({(CORPUS / folder).parent for folder in CORPUS_PACKAGES.values()})
        found += [(path, folders, []) for path in sorted(CORPUS.rglob('*.urdf'))]
    from importlib import metadata
    try:
        share = Path(str(metadata.distribution('example-robot-data').locate_file(
            'cmeel.prefix/share')))
        found += [(share / 'example-robot-data/robots' / name, [share], [pytest.mark.slow])
                  for name in ('ur_description/urdf/ur5_robot.urdf',
                               'panda_description/urdf/panda.urdf',
                               'hextilt_description/urdf/hextilt_flying_arm_5.urdf',
                               'borinot_description/urdf/borinot_flying_arm_2.urdf')]
    except metadata.PackageNotFoundError:
        pass
    cases = [pytest.param(path, folders, marks=marks, id=f'{path.parent.name}/{path.name}')
             for path, folders, marks in found
             if path.is_file() and '.dae' in path.read_text(errors='replace').lower()]
    return cases or [pytest.param(
        None, [], marks=pytest.mark.skip('no robot with DAE meshes installed'))]


@pytest.mark.engine
@pytest.mark.parametrize(('path', 'search_paths'), _dae_robots())
def test_robots_with_dae_meshes_are_assembled_as_rviz_shows_them(
        path: Path, search_paths: list[Path], tmp_path: Path) -> None:
    require_module('mujoco')
    require_module('yourdfpy')
    require_module('trimesh')
    robot = load(path, {}, search_paths)
    if any(warning.code == 'X101' for warning in robot.read_warnings):
        pytest.skip('a Xacro file: yourdfpy reads URDF')
    from urdfgenpy_ros.formats.mjcf import MjcfRefusedError
    try:
        model, _ = _compiled(robot, tmp_path, search_paths)
    except MjcfRefusedError:
        pytest.skip('MuJoCo refuses its inertia (test_mjcf_robots.py judges that refusal)')
    ours = mesh_judge.written_boxes(model)
    theirs = mesh_judge.source_boxes(path, search_paths)
    assert set(theirs) <= set(ours) | {robot.root.name}
    for link, box in theirs.items():
        if link in ours:  # a link fused away keeps its geoms on its parent body
            size = float(numpy.max(box[1] - box[0])) or 1.0
            assert numpy.allclose(ours[link], box, rtol=0.0, atol=1e-6 * size), link
    written = numpy.array([model.mat_rgba[model.geom_matid[geom]] for geom
                           in range(model.ngeom) if model.geom_group[geom] == 2
                           and model.geom_matid[geom] >= 0]).reshape(-1, 4)
    for rgba in mesh_judge.dae_colours(path, search_paths):  # trimesh reads 8 bits
        assert (numpy.abs(written - rgba).max(axis=1) <= 0.5 / 255 + 1e-6).any(), rgba


def test_render_and_view_read_a_dae_as_rviz_does(tmp_path: Path) -> None:
    require_module('trimesh')
    from urdfgenpy_ros.viewer.scene import robot_parts
    mesh_judge.write_y_up_dae(tmp_path / 'part.dae')
    robot = Robot('part').add_link(Link('base_link', visuals=[Visual(Mesh(
        str(tmp_path / 'part.dae')))]))
    parts = robot_parts(robot)
    assert len(parts) == 1 and parts[0].textured  # the file's own colours are drawn
    theirs = mesh_judge.rviz_vertices(tmp_path / 'part.dae')
    mine = numpy.asarray(parts[0].mesh.vertices)
    assert numpy.allclose([mine.min(axis=0), mine.max(axis=0)],
                          [theirs.min(axis=0), theirs.max(axis=0)], rtol=0.0, atol=1e-9)
    colours = {tuple(row) for row in numpy.asarray(parts[0].mesh.visual.face_colors)}
    assert colours == {tuple(round(value * 255) for value in colour)
                       for colour in (mesh_judge.RED, mesh_judge.BLUE)}
