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
The files a mirror writes: judged by trimesh (geometry), yourdfpy and check_urdf.

A re-run finds its own DAE files again (compared by geometry, as DAE files carry dates),
two meshes of one name get a mirrored file each, a failure leaves no file behind, and an
output in another folder still finds every mesh.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import assert_check_urdf_accepts, require_module
import pytest

from test_reshape_dh import example_robot

from urdfgenpy_ros import ModelError, Robot
from urdfgenpy_ros.cli import main

ARM = ('<robot name="r"><link name="base_link"/><link name="left_arm">{shapes}</link>'
       '<joint name="left_j" type="revolute"><parent link="base_link"/><child '
       'link="left_arm"/><origin xyz="0 0.2 0"/><axis xyz="1 0 0"/><limit lower="-1" '
       'upper="0" effort="1" velocity="1"/></joint></robot>')


def _shape(kind: str, filename: str) -> str:
    return f'<{kind}><geometry><mesh filename="{filename}"/></geometry></{kind}>'


def _box(path: Path, size: tuple[float, float, float], offset: tuple[float, float, float]):
    """Write an off-centre box (its mirror image differs from it) to ``path``."""
    trimesh = require_module('trimesh')
    path.parent.mkdir(parents=True, exist_ok=True)
    box = trimesh.creation.box(size)
    box.apply_translation(offset)
    box.export(path)
    return trimesh.load(path, force='mesh')


def _assert_reflection(mirrored_path: Path, original) -> None:
    trimesh = require_module('trimesh')
    numpy = require_module('numpy')
    mirrored = trimesh.load(mirrored_path, force='mesh')
    assert mirrored.volume == pytest.approx(original.volume, rel=1e-6)
    low, high = original.bounds
    assert numpy.allclose(mirrored.bounds, [[low[0], -high[1], low[2]],
                                            [high[0], -low[1], high[2]]], atol=1e-6)


def _mirror(*arguments: str):
    return CliRunner().invoke(main, ['mirror', *arguments])


def test_a_rerun_keeps_the_mirrored_dae_it_wrote_before(tmp_path: Path) -> None:
    original = _box(tmp_path / 'meshes' / 'arm.dae', (0.1, 0.2, 0.3), (0.01, 0.05, -0.1))
    source = tmp_path / 'robot.urdf'
    source.write_text(ARM.format(shapes=_shape('visual', 'meshes/arm.dae')))
    first = _mirror(str(source), '--root', 'left_arm', '-o', str(tmp_path / 'two.urdf'))
    assert first.exit_code == 0, first.output
    written = (tmp_path / 'meshes' / 'arm_mirror_xz.dae').read_bytes()
    for output in ('two_again.urdf', 'two.sdf'):  # again, and another format
        again = _mirror(str(source), '--root', 'left_arm', '-o', str(tmp_path / output))
        assert again.exit_code == 0, again.output
    assert (tmp_path / 'meshes' / 'arm_mirror_xz.dae').read_bytes() == written  # kept
    _assert_reflection(tmp_path / 'meshes' / 'arm_mirror_xz.dae', original)


def test_two_meshes_of_one_name_get_a_mirrored_file_each(tmp_path: Path) -> None:
    seen = _box(tmp_path / 'visual' / 'arm.stl', (0.1, 0.2, 0.3), (0.0, 0.05, 0.0))
    hit = _box(tmp_path / 'collision' / 'arm.stl', (0.1, 0.1, 0.2), (0.0, 0.08, 0.0))
    source = tmp_path / 'robot.urdf'
    source.write_text(ARM.format(shapes=_shape('visual', 'visual/arm.stl')
                                 + _shape('collision', 'collision/arm.stl')))
    for attempt in range(2):  # and a re-run finds both again
        result = _mirror(str(source), '--root', 'left_arm', '--mesh-folder',
                         str(tmp_path / 'mf'), '-o', str(tmp_path / f'two{attempt}.urdf'))
        assert result.exit_code == 0, result.output
    arm = Robot.from_urdf(tmp_path / 'two1.urdf').get_link('right_arm')
    visual, collision = arm.visuals[0].geometry.filename, arm.collisions[0].geometry.filename
    assert visual != collision and visual.startswith('file:///')  # never a bare path
    visual, collision = visual.removeprefix('file://'), collision.removeprefix('file://')
    _assert_reflection(Path(visual), seen)
    _assert_reflection(Path(collision), hit)


def test_a_refused_mirror_leaves_no_mirrored_file_behind(tmp_path: Path) -> None:
    _box(tmp_path / 'meshes' / 'a.stl', (0.1, 0.2, 0.3), (0.0, 0.05, 0.0))
    _box(tmp_path / 'meshes' / 'b.stl', (0.1, 0.1, 0.2), (0.0, 0.08, 0.0))
    (tmp_path / 'meshes' / 'b_mirror_xz.stl').write_bytes(b'solid mine\nendsolid\n')
    source = tmp_path / 'robot.urdf'
    source.write_text(ARM.format(shapes=_shape('visual', 'meshes/a.stl')
                                 + _shape('collision', 'meshes/b.stl')))
    robot = Robot.from_urdf(source)
    with pytest.raises(ModelError, match='b_mirror_xz.stl exists and is not the mirror'):
        robot.mirror('left_arm')
    assert not (tmp_path / 'meshes' / 'a_mirror_xz.stl').exists()
    assert not robot.has_link('right_arm')


def test_an_output_in_another_folder_still_finds_every_mesh(tmp_path: Path) -> None:
    yourdfpy = require_module('yourdfpy')
    _box(tmp_path / 'src' / 'meshes' / 'arm.stl', (0.1, 0.2, 0.3), (0.0, 0.05, 0.0))
    source = tmp_path / 'src' / 'robot.urdf'
    source.write_text(ARM.format(shapes=_shape('visual', 'meshes/arm.stl')))
    target = tmp_path / 'out' / 'two.urdf'
    target.parent.mkdir()
    result = _mirror(str(source), '--root', 'left_arm', '-o', str(target))
    assert result.exit_code == 0, result.output
    assert_check_urdf_accepts(target)
    model = yourdfpy.URDF.load(str(target), load_meshes=True, build_scene_graph=True)
    for link in ('left_arm', 'right_arm'):
        filename = model.link_map[link].visuals[0].geometry.mesh.filename
        assert (target.parent / filename).is_file(), filename
    assert len(model.scene.geometry) == 2  # yourdfpy found and loaded both files


def test_an_obj_keeps_its_texture_and_a_dae_says_it_loses_it(tmp_path: Path) -> None:
    numpy = require_module('numpy')
    trimesh = require_module('trimesh')
    pil = require_module('PIL.Image')
    box = trimesh.creation.box((0.1, 0.2, 0.3))
    box.apply_translation((0.0, 0.05, 0.0))
    uv = numpy.random.default_rng(1).random((len(box.vertices), 2))
    image = pil.new('RGB', (4, 4), (200, 30, 30))
    box.visual = trimesh.visual.TextureVisuals(uv=uv, image=image)
    (tmp_path / 'meshes').mkdir()
    box.export(tmp_path / 'meshes' / 'arm.obj')
    hip = example_robot('anymal_c_simple_description/meshes/hip_l.dae')
    source = tmp_path / 'robot.urdf'
    source.write_text(ARM.format(shapes=_shape('visual', 'meshes/arm.obj')
                                 + _shape('visual', str(hip))))
    for attempt in range(2):  # a re-run finds the OBJ, its material and image again
        result = _mirror(str(source), '--root', 'left_arm', '--mesh-folder',
                         str(tmp_path / 'mf'), '-o', str(tmp_path / f'two{attempt}.urdf'))
        assert result.exit_code == 0, result.output
        lines = [line for line in result.output.splitlines() if line.startswith('warning:')]
        assert len(lines) == 1 and 'hip_l.dae' in lines[0] and 'texture' in lines[0], lines
    mirrored = trimesh.load(tmp_path / 'mf' / 'arm_mirror_xz.obj', force='mesh')
    assert numpy.array_equal(numpy.asarray(mirrored.visual.material.image.convert('RGB')),
                             numpy.asarray(image))  # the texture came along, in mf/
    assert numpy.allclose(mirrored.visual.uv, box.visual.uv)
    before = {path.name: path.read_bytes() for path in (tmp_path / 'meshes').iterdir()}
    beside = _mirror(str(source), '--root', 'left_arm', '-o', str(tmp_path / 'beside.urdf'))
    assert beside.exit_code == 0, beside.output  # beside the original: its files untouched
    assert all((tmp_path / 'meshes' / name).read_bytes() == data
               for name, data in before.items())
    assert trimesh.load(tmp_path / 'meshes' / 'arm_mirror_xz.obj',
                        force='mesh').visual.material.image is not None


def test_mirror_command_speaks_of_its_own_options(tmp_path: Path) -> None:
    source = tmp_path / 'robot.urdf'
    source.write_text(ARM.format(shapes=_shape('visual', 'package://nowhere_pkg/arm.stl')))
    result = _mirror(str(source), '--root', 'left_arm', '-o', str(tmp_path / 'two.urdf'))
    assert result.exit_code == 2
    assert '-p/--package-path' in result.output and 'search_paths' not in result.output
    assert "the robot's root link" in ' '.join(_mirror('--help').output.split())
