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
``render -j`` outside a joint's limits: one warning naming them, drawn at the limit.

yourdfpy reads the limit from the URDF; the picture at the asked value must be the one at
that limit.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from helpers import require_module
import pytest
from test_render import _marker_robot

from urdfgenpy_ros.cli import main


def test_a_value_outside_the_limits_is_clamped_with_one_warning(tmp_path: Path) -> None:
    pytest.importorskip('vtkmodules')
    pytest.importorskip('trimesh')
    yourdfpy = require_module('yourdfpy')
    urdf = tmp_path / 'markers.urdf'
    _marker_robot().to_urdf(urdf)
    upper = yourdfpy.URDF.load(str(urdf), load_meshes=False).joint_map['slide'].limit.upper
    pictures = []
    for value in (9.0, upper):
        picture = tmp_path / f'slide_{value}.png'
        result = CliRunner().invoke(main, ['render', str(urdf), '-j', f'slide={value}',
                                           '-o', str(picture)])
        assert result.exit_code == 0, result.output
        pictures.append((picture.read_bytes(), result.output))
    assert pictures[0][0] == pictures[1][0]  # drawn at the limit
    said = [line for line in pictures[0][1].splitlines() if line.startswith('warning:')]
    assert said == [f"warning: joint 'slide': 9 is outside its limits [-{upper:g}, {upper:g}]: "
                    f'drawn at {upper:g} (clamped, as the publisher does)']
    assert 'warning' not in pictures[1][1]
