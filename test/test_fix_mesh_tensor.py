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

"""--fix takes a bad tensor from a closed collision mesh, as trimesh computes it."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import require_module, xacro_expand
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.scaffold.command import main as init

ARM = """<?xml version="1.0"?>
<robot name="m">
  <link name="base_link"/>
  <link name="arm">
    <inertial><origin xyz="0.05 0 0"/><mass value="2"/>
      <inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/></inertial>
    <collision><origin rpy="0 0 0.3"/><geometry><mesh filename="part.stl"/></geometry></collision>
  </link>
  <link name="tip">
    <inertial><mass value="0.5"/>
      <inertia ixx="-1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>
  </link>
  <joint name="j" type="revolute"><parent link="base_link"/><child link="arm"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="k" type="revolute"><parent link="arm"/><child link="tip"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


@pytest.fixture
def arm(tmp_path: Path) -> Path:
    """Write the arm and its closed, off-centre box mesh."""
    trimesh = require_module('trimesh')
    box = trimesh.creation.box(extents=(0.2, 0.1, 0.4))
    box.apply_translation((0.05, 0.0, 0.0))
    box.export(tmp_path / 'part.stl')
    (tmp_path / 'arm.urdf').write_text(ARM)
    return tmp_path / 'arm.urdf'


def _trimesh_tensor(folder: Path, mass: float, yaw: float) -> list[list[float]]:
    """Return trimesh's tensor of the mesh with ``mass``, turned by ``yaw`` about z."""
    trimesh = require_module('trimesh')
    numpy = require_module('numpy')
    mesh = trimesh.load(folder / 'part.stl', force='mesh')
    mesh.density = mass / mesh.volume
    turn = trimesh.transformations.rotation_matrix(yaw, (0, 0, 1))[:3, :3]
    return (turn @ numpy.asarray(mesh.moment_inertia) @ turn.T).tolist()


def test_check_fix_takes_the_tensor_from_the_collision_mesh(arm: Path) -> None:
    result = CliRunner().invoke(main, ['check', str(arm), '--fix'])
    assert "fixed I202 link 'arm': inertia replaced by that of its collision mesh " \
        "'part.stl' with mass 2" in result.output, result.output
    inertial = Robot.from_urdf(arm).get_link('arm').inertial
    assert inertial is not None
    expected = _trimesh_tensor(arm.parent, 2.0, 0.3)
    for row, want in zip(inertial.tensor, expected):
        assert list(row) == pytest.approx(want, abs=1e-12)


def test_convert_and_init_fix_take_it_too_and_mujoco_compiles_the_result(
        arm: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    mujoco = require_module('mujoco')
    out = tmp_path / 'fixed.urdf'
    result = CliRunner().invoke(main, ['convert', str(arm), str(out), '--fix'])
    assert result.exit_code == 0, result.output
    assert "'arm': inertia replaced by that of its collision mesh 'part.stl'" in result.output
    model = mujoco.MjModel.from_xml_path(str(out))  # the mesh is found beside it
    arm_body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, 'arm')
    moments = sorted(model.body_inertia[arm_body])
    numpy = require_module('numpy')
    assert moments == pytest.approx(sorted(numpy.linalg.eigvalsh(
        _trimesh_tensor(arm.parent, 2.0, 0.3))), rel=1e-6)
    code = init(['m_description', '--from', str(arm), '--fix', '--fix-radius', '0.02',
                 '--destination-directory', str(tmp_path / 'src')])
    err = capsys.readouterr().err
    assert code == 0, err
    assert "'arm': inertia replaced by that of its collision mesh 'part.stl'" in err
    assert "'tip': inertia replaced by that of a solid sphere of radius 0.02 m" in err
    assert '(it has no shape to take one from: --fix-radius sets the size)' in err


def test_an_open_mesh_is_named_in_the_reason_nothing_was_fixed(arm: Path) -> None:
    trimesh = require_module('trimesh')
    box = trimesh.creation.box(extents=(0.2, 0.1, 0.4))
    box.update_faces([True] * (len(box.faces) - 1) + [False])
    box.export(arm.parent / 'part.stl')
    text = arm.read_text()
    result = CliRunner().invoke(main, ['check', str(arm), '--fix'])
    assert "I202 not fixed for link 'arm': no box, cylinder, sphere or capsule, nor a closed " \
        "mesh, with a positive mass to take a tensor from (collision mesh 'part.stl': " \
        'part.stl: the mesh is not closed' in result.output, result.output
    assert arm.read_text() == text


XACRO = """<?xml version="1.0"?>
<robot name="x" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base_link"/>
  <link name="a">
    <inertial><mass value="1"/><inertia ixx="0" ixy="0" ixz="0" iyy="0" iyz="0" izz="0"/>
    </inertial>
  </link>
  <joint name="j" type="revolute"><parent link="base_link"/><child link="a"/>
    <axis xyz="0 0 2"/><limit lower="1" upper="-1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_check_fix_on_xacro_repairs_in_place_and_counts_what_stays(tmp_path: Path) -> None:
    """J102 and J104 are edits of the Xacro's own lines; the shapeless I202 stays, listed."""
    path = tmp_path / 'x.urdf.xacro'
    path.write_text(XACRO)
    result = CliRunner().invoke(main, ['check', str(path), '--fix', '--no-meshes'])
    fixed = [line for line in result.output.splitlines() if ': fixed J10' in line]
    listed = [line for line in result.output.splitlines()
              if (' error ' in line or ' warning ' in line) and line.startswith(str(path))]
    assert len(fixed) == 2 and len(listed) == 1 and ' I202 ' in listed[0], result.output
    assert '1 error(s), 0 warning(s), 0 unreadable, 2 fixed' in result.output
    expanded = xacro_expand(path)
    assert 'xyz="0 0 1"' in expanded and 'lower="-1" upper="1"' in expanded
