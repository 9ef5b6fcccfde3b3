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
Origins and shapes are values: changing one in place is one line saying what to assign.

The error stays a ``dataclasses.FrozenInstanceError`` (code that caught it still does) and
is a ``UrdfgenpyError``; doing what it says gives the pose yourdfpy reads back.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

from helpers import require_module
import pytest

from urdfgenpy_ros import (
    Box, Cylinder, Joint, JointLimit, Link, Mesh, Origin, Robot, Sphere, UrdfgenpyError,
    Visual)


def _arm() -> Robot:
    robot = Robot('arm').add_link(Link('base_link')).add_link(Link('upper'))
    return robot.add_joint(Joint('shoulder', 'revolute', 'base_link', 'upper',
                                 axis=(0.0, 0.0, 1.0),
                                 limit=JointLimit(-1.0, 1.0, effort=1.0, velocity=1.0)))


def test_changing_an_origin_in_place_says_to_assign_a_new_one(tmp_path: Path) -> None:
    robot = _arm()
    joint = robot.get_joint('shoulder')
    with pytest.raises(dataclasses.FrozenInstanceError) as caught:
        joint.origin.xyz = (0.0, 0.0, 0.3)  # type: ignore[misc]
    assert isinstance(caught.value, UrdfgenpyError) and isinstance(caught.value,
                                                                   AttributeError)
    message = str(caught.value)
    assert '\n' not in message and "field 'xyz'" in message
    assert 'joint.origin = Origin(...)' in message
    joint.origin = Origin((0.0, 0.0, 0.3))  # as it says
    yourdfpy = require_module('yourdfpy')
    robot.to_urdf(tmp_path / 'arm.urdf')
    read = yourdfpy.URDF.load(str(tmp_path / 'arm.urdf'), load_meshes=False,
                              build_scene_graph=True)
    assert read.get_transform('upper', 'base_link')[2][3] == 0.3
    link = Link('part').add_visual(Visual(Box(0.1, 0.2, 0.3)))
    link.visuals[0].geometry = dataclasses.replace(link.visuals[0].geometry, length=0.5)
    assert link.visuals[0].geometry == Box(0.5, 0.2, 0.3)


@pytest.mark.parametrize('value, field', [
    (Box(0.1, 0.2, 0.3), 'length'), (Cylinder(0.1, 0.2), 'radius'), (Sphere(0.1), 'radius'),
    (Mesh('arm.stl'), 'filename'), (Origin(), 'rpy')])
def test_every_value_refuses_in_one_line(value: object, field: str) -> None:
    with pytest.raises(UrdfgenpyError, match=f"cannot assign to field '{field}': "
                       f'{type(value).__name__} is a value type'):
        setattr(value, field, 1.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        delattr(value, field)
