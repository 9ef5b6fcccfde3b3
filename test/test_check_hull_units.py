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
M504 gives the hull's volume in m^3 with the URDF's mesh scale applied.

MuJoCo is the judge: a body of density 1000 whose geom is the scaled mesh's convex hull
(``inertia="convex"``) weighs 1000 times the hull's volume in m^3.
"""

from __future__ import annotations

from pathlib import Path
import re

from helpers import require_module
import pytest
from test_check_preflight import _write_l_shape, INERTIAL

from urdfgenpy_ros import Robot
from urdfgenpy_ros.validation.preflight import preflight

ROBOT = """<?xml version="1.0"?>
<robot name="bent">
  <link name="base_link">
    {inertial}
    <collision><geometry><mesh filename="{mesh}" scale="0.001 0.001 0.001"/></geometry>
    </collision>
  </link>
</robot>
"""


def test_m504_gives_the_hull_volume_in_cubic_metres_of_the_scaled_mesh(
        tmp_path: Path) -> None:
    mujoco = require_module('mujoco')
    trimesh = require_module('trimesh')
    _write_l_shape(tmp_path / 'metres.obj')
    millimetres = trimesh.load(tmp_path / 'metres.obj', force='mesh')
    millimetres.apply_scale(1000.0)  # a CAD export in millimetres, as crane_plus's
    millimetres.export(tmp_path / 'bent.obj')
    path = tmp_path / 'bent.urdf'
    path.write_text(ROBOT.format(inertial=INERTIAL, mesh='bent.obj'))
    found = [f for f in preflight(Robot.from_urdf(path), ['mujoco']) if f.code == 'M504']
    assert len(found) == 1
    hull, volume = (float(value) for value in re.findall(
        r'holds ([0-9.e+-]+) m\^3, the mesh ([0-9.e+-]+) m\^3', found[0].message)[0])
    model = mujoco.MjModel.from_xml_string(f"""<mujoco>
      <asset><mesh name="bent" file="{tmp_path / 'bent.obj'}" scale="0.001 0.001 0.001"
        inertia="convex"/></asset>
      <worldbody><body><freejoint/><geom type="mesh" mesh="bent" density="1000"/></body>
      </worldbody></mujoco>""")
    assert hull == pytest.approx(model.body_mass[1] / 1000.0, rel=1e-3)
    assert volume == pytest.approx(0.003, rel=1e-3)  # the L: three 0.1 m cubes
