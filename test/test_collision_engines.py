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
Collision geometry made light, judged by MuJoCo and on the registry robots.

MuJoCo compiles every output (the URDF itself, and ``convert --collision``'s MJCF) and
simulates a ball dropped into the U bracket's gap: it comes to rest inside the gap with
``decompose`` and on top of the block with a single hull. On every registry robot, every
line outside ``<collision>`` is kept, and each hull holds points drawn inside its mesh.
"""

from __future__ import annotations

from pathlib import Path
import re
import subprocess

from click.testing import CliRunner
from collision_fixtures import coverage_inside, SHAPES, write_fixtures
from helpers import build_sdf_checker, pose_matrix, require_module
import numpy
import pytest
from registry_robots import robot_id, robots, search_paths

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.model.geometry import Mesh
from urdfgenpy_ros.resources import PackageResolver

trimesh = require_module('trimesh')  # skips (naming it) without trimesh

METHODS = ('hull', 'decompose', 'primitive', 'decimate', 'auto')


@pytest.fixture(autouse=True)
def _own_cache(tmp_path_factory, monkeypatch):
    monkeypatch.setenv('URDFGENPY_CACHE_DIR', str(tmp_path_factory.mktemp('cache')))


def _compile_urdf(path: Path):
    """Compile a URDF with MuJoCo's own importer, its meshes given as assets."""
    mujoco = require_module('mujoco')
    text = path.read_text()
    files = set(re.findall(r'filename="([^"]+)"', text))
    assets = {Path(name).name: (path.parent / name).read_bytes() for name in files}
    return mujoco.MjModel.from_xml_string(text, assets)


@pytest.mark.engine
@pytest.mark.parametrize('method', METHODS)
def test_mujoco_compiles_the_urdf_and_the_mjcf(tmp_path, method):
    require_module('coacd')
    source = write_fixtures(tmp_path)
    output = tmp_path / f'{method}.urdf'
    result = CliRunner().invoke(main, ['collision', str(source), '-o', str(output),
                                       '--method', method, '--max-faces', '200'])
    assert result.exit_code == 0, result.output
    model = _compile_urdf(output)
    assert model.ngeom >= len(SHAPES)  # its importer drops the visuals
    mjcf = tmp_path / 'mjcf' / f'{method}.xml'
    result = CliRunner().invoke(main, ['convert', str(source), str(mjcf), '--collision',
                                       method])
    assert result.exit_code == 0, result.output
    assert "warning K911 link 'u_bracket'" in result.stderr
    mujoco = require_module('mujoco')
    compiled = mujoco.MjModel.from_xml_path(str(mjcf))
    collision_geoms = [index for index in range(compiled.ngeom)
                       if compiled.geom_contype[index] or compiled.geom_conaffinity[index]]
    assert len(collision_geoms) >= len(SHAPES)
    assert source.read_text() == Robot.from_urdf(source).to_urdf()  # the source untouched


def _resting_height(robot: Robot, folder: Path) -> float:
    """Drop a 2 cm ball into the bracket's gap in MuJoCo; return where it comes to rest."""
    mujoco = require_module('mujoco')
    assets, geoms = {}, []
    for index, item in enumerate(robot.get_link('u_bracket').collisions):
        assert isinstance(item.geometry, Mesh)
        assets[f'part{index}.stl'] = (folder / item.geometry.filename).read_bytes()
        matrix = pose_matrix(item.origin)
        quat = trimesh.transformations.quaternion_from_matrix(matrix)  # w x y z
        position = ' '.join(map(str, matrix[:3, 3]))
        geoms.append(f'<geom type="mesh" mesh="part{index}" pos="{position}" '
                     f'quat="{" ".join(map(str, quat))}"/>')
    meshes = ''.join(f'<mesh name="{name[:-4]}" file="{name}"/>' for name in assets)
    xml = (f'<mujoco><option timestep="0.001"/><asset>{meshes}</asset><worldbody>'
           f'{"".join(geoms)}<body pos="0 0 0.2"><freejoint/><geom type="sphere" '
           'size="0.02" mass="0.05"/></body></worldbody></mujoco>')
    model = mujoco.MjModel.from_xml_string(xml, assets)
    data = mujoco.MjData(model)
    mujoco.mj_step(model, data, nstep=2000)
    assert abs(data.qvel).max() < 1e-2  # at rest
    return float(data.qpos[2])


@pytest.mark.engine
def test_a_ball_falls_into_the_gap_only_with_decompose(tmp_path):
    require_module('coacd')
    heights = {}
    for method in ('decompose', 'hull'):
        robot = Robot.from_urdf(write_fixtures(tmp_path, ('u_bracket',)))
        robot.simplify_collisions(method)
        heights[method] = _resting_height(robot, tmp_path)
    # the collision sits 1 cm up: base top at 0.03, arm tops (and the hull's top) at 0.11
    assert 0.045 < heights['decompose'] < 0.06  # on the base, between the arms
    assert 0.125 < heights['hull'] < 0.135  # on top of the block


def _outside_collisions(text: str) -> list[str]:
    return re.sub(r'<collision\b.*?</collision>', '', text, flags=re.S).splitlines()


@pytest.mark.slow
@pytest.mark.parametrize('path', [pytest.param(path, id=robot_id(path)) for path in robots()])
def test_registry_robots_keep_every_line_outside_collisions(tmp_path, path):
    robot = load(path, {}, search_paths())
    before = path.read_text() if path.suffix == '.urdf' and '<xacro:' not in path.read_text() \
        else robot.to_urdf()
    meshes = {(link.name, index): item.geometry for link in robot.links
              for index, item in enumerate(link.collisions)}
    report = robot.simplify_collisions('hull', mesh_folder=tmp_path,
                                       search_paths=search_paths())
    after = robot.to_urdf()
    assert _outside_collisions(after) == _outside_collisions(before)
    resolver = PackageResolver(search_paths())
    judged = 0
    for result in report.results:  # a hull holds what its mesh holds (sampled points)
        given = meshes[(result.link, result.index)]
        original = trimesh.load(str(resolver.resolve(given.filename, path.parent)),
                                force='mesh')
        if not original.is_watertight or original.volume <= 0 or judged == 2:
            continue
        original.apply_transform(numpy.diag([*(given.scale or (1.0, 1.0, 1.0)), 1.0]))
        written = robot.get_link(result.link).collisions[result.index].geometry
        hull = trimesh.load(str(tmp_path / Path(written.filename).name), force='mesh')
        assert coverage_inside(original, [hull]) == 1.0, result.link
        judged += 1


@pytest.mark.engine
@pytest.mark.parametrize('method', ['primitive', 'decompose'])
def test_libsdformat_loads_the_sdf_output(tmp_path, method):
    require_module('coacd')
    (tmp_path / 'checker').mkdir()
    binary = build_sdf_checker(tmp_path / 'checker')
    source = write_fixtures(tmp_path, ('u_bracket', 'cylinder_link'))
    output = tmp_path / 'out' / 'robot.sdf'
    output.parent.mkdir()
    result = CliRunner().invoke(main, ['collision', str(source), '-o', str(output),
                                       '--method', method])
    assert result.exit_code == 0, result.output
    checked = subprocess.run([str(binary), str(output)], capture_output=True, text=True,
                             timeout=120)
    assert checked.returncode == 0, checked.stderr
    assert output.read_text().count('<collision') >= 2
