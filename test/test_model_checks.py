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
A mistake in building a model is one line naming the element, the field and the fix.

The constructors check in one pass and take a fast path for values that are already
finite floats; each case here goes down the path a user's value of that kind takes (ints,
strings, bools, NaN, a wrong length), so a fast path that let a mistake through, or said
it differently, fails here. Lists a link or joint holds are made on first use.
"""

from __future__ import annotations

import copy
import dataclasses
import math
import pickle
from typing import Any, Callable

from helpers import load_yourdfpy
import pytest

from urdfgenpy_ros import (Box, Collision, Inertial, Joint, JointLimit, Link, Mesh, ModelError,
                           Origin, Robot, Sphere, Visual)
from urdfgenpy_ros.model import checks
from urdfgenpy_ros.model.errors import ModelTypeError
from urdfgenpy_ros.model.extensions import Extension
from urdfgenpy_ros.model.sensors import Imu

NAN, INF = float('nan'), float('inf')
TYPES = 'revolute, continuous, prismatic, fixed, floating, planar'


def _robot_with(*links: str) -> Robot:
    robot = Robot('r')
    for name in links:
        robot.add_link(Link(name))
    return robot


MISTAKES: dict[str, tuple[Callable[[], Any], str]] = {
    'joint type': (lambda: Joint('j', 'hinge', 'a', 'b'),
                   f"joint 'j': unknown type 'hinge' (use one of {TYPES})"),
    'joint type before name': (lambda: Joint('', None, 'a', 'b'),
                               f"joint '': unknown type None (use one of {TYPES})"),
    'joint name': (lambda: Joint('', 'fixed', 'a', 'b'),
                   "joint: name must be a non-empty string, got ''"),
    'joint blank name': (lambda: Joint('  ', 'fixed', 'a', 'b'),
                         "joint: name must be a non-empty string, got '  '"),
    'joint name int': (lambda: Joint(3, 'fixed', 'a', 'b'),  # type: ignore[arg-type]
                       'joint: name must be a non-empty string, got 3'),
    'joint parent': (lambda: Joint('j', 'fixed', '', 'b'),
                     "joint 'j' parent: name must be a non-empty string, got ''"),
    'joint child': (lambda: Joint('j', 'fixed', 'a', None),  # type: ignore[arg-type]
                    "joint 'j' child: name must be a non-empty string, got None"),
    'axis zero': (lambda: Joint('j', 'revolute', 'a', 'b', axis=(0, 0, 0)),
                  "joint 'j': axis must not be zero for a revolute joint (give the direction "
                  'of motion, e.g. (0, 0, 1))'),
    'axis zero floats': (lambda: Joint('j', 'prismatic', 'a', 'b', axis=(0.0, 0.0, 0.0)),
                         "joint 'j': axis must not be zero for a prismatic joint (give the "
                         'direction of motion, e.g. (0, 0, 1))'),
    'axis length': (lambda: Joint('j', 'revolute', 'a', 'b', axis=(0, 0)),
                    "joint 'j': axis must have 3 numbers (x, y, z), got (0, 0)"),
    'axis text': (lambda: Joint('j', 'revolute', 'a', 'b', axis=('x', 0, 0)),
                  "joint 'j': axis must be a number, got 'x'"),
    'axis nan': (lambda: Joint('j', 'revolute', 'a', 'b', axis=(0, 0, NAN)),
                 "joint 'j': axis must be finite, got nan"),
    'axis inf': (lambda: Joint('j', 'revolute', 'a', 'b', axis=(INF, 0, 1)),
                 "joint 'j': axis must be finite, got inf"),
    'limit effort': (lambda: JointLimit(0, 1, effort=-1),
                     'limit: effort must be a finite number >= 0 (N m or N), got -1.0'),
    'limit velocity': (lambda: JointLimit(0.0, 1.0, effort=1.0, velocity=-1.0),
                       'limit: velocity must be a finite number >= 0 (rad/s or m/s), got -1.0'),
    'limit velocity inf': (lambda: JointLimit(0, 1, velocity=INF),
                           'limit: velocity must be finite, got inf'),
    'limit lower text': (lambda: JointLimit('x', 1),  # type: ignore[arg-type]
                         "limit: lower must be a number, got 'x'"),
    'limit lower nan': (lambda: JointLimit(NAN, 1), 'limit: lower must be finite, got nan'),
    'limit effort None': (lambda: JointLimit(0, 1, effort=None),  # type: ignore[arg-type]
                          'limit: effort must be a number, got None'),
    'limit jerk': (lambda: JointLimit(0, 1, jerk=-1),
                   'limit: jerk must be a finite number >= 0 , got -1.0'),
    'link name': (lambda: Link(''), "link: name must be a non-empty string, got ''"),
    'link name None': (lambda: Link(None),  # type: ignore[arg-type]
                       'link: name must be a non-empty string, got None'),
    'add_visual': (lambda: Link('a').add_visual(3),  # type: ignore[arg-type]
                   "link 'a': add_visual() takes a Visual, got int"),
    'box size': (lambda: Box(1, 0, 1), 'box: width must be a positive finite number of m, '
                 'got 0.0'),
    'box nan': (lambda: Box(1.0, 1.0, NAN), 'box: height must be a positive finite number of '
                'm, got nan'),
    'box text': (lambda: Box(1, 'a', 1),  # type: ignore[arg-type]
                 "box: width must be a number, got 'a'"),
    'origin length': (lambda: Origin(xyz=(1, 2)),
                      'origin: xyz must have 3 numbers (x, y, z), got (1, 2)'),
    'origin nan': (lambda: Origin(xyz=(1.0, 2.0, NAN)), 'origin: xyz must be finite, got nan'),
    'origin rpy text': (lambda: Origin(rpy=('a', 0, 0)),  # type: ignore[arg-type]
                        "origin: rpy must be a number, got 'a'"),
    'origin None': (lambda: Origin(xyz=None),  # type: ignore[arg-type]
                    'origin: xyz must have 3 numbers (x, y, z), got None'),
    'above a mesh': (lambda: Origin.above(Mesh('a.stl')),
                     "Origin.above(): the height of mesh 'a.stl' is unknown; give the origin "
                     'explicitly, e.g. Origin(xyz=(0, 0, h / 2))'),
    'inertial mass': (lambda: Inertial(-1.0), 'inertial: mass must be a finite number >= 0 kg, '
                      'got -1.0'),
    'inertial nan': (lambda: Inertial(1.0, ixx=NAN), 'inertial: ixx must be finite, got nan'),
    'from_box size': (lambda: Inertial.from_box(1.0, -1.0, 1.0, 1.0),
                      'Inertial.from_box: length must be a positive finite number of m, '
                      'got -1.0'),
    'from_box mass': (lambda: Inertial.from_box(-1.0, 1.0, 1.0, 1.0),
                      'Inertial.from_box: mass must be a finite number >= 0 kg, got -1.0'),
    'from_box mass text': (lambda: Inertial.from_box('a', 1, 1, 1),  # type: ignore[arg-type]
                           "Inertial.from_box: mass must be a number, got 'a'"),
    'add_link twice': (lambda: _robot_with('a', 'a'),
                       "robot 'r': link 'a' already exists (link names must be unique: "
                       'rename one)'),
    'add_link a joint': (lambda: Robot('r').add_link(Joint('j', 'fixed', 'a', 'b')),  # type: ignore[arg-type]  # noqa: E501
                         "robot 'r': add_link() takes a Link, got Joint"),
    'parent missing': (lambda: _robot_with('base', 'b').add_joint(Joint('j', 'fixed', 'bse',
                                                                        'b')),
                       "joint 'j': parent link 'bse' is not in robot 'r' (did you mean 'base'?) "
                       '(add the link before the joint)'),
    'child missing': (lambda: _robot_with('base').add_joint(Joint('j', 'fixed', 'base', 'b')),
                      "joint 'j': child link 'b' is not in robot 'r' (add the link before the "
                      'joint)'),
    'parent is child': (lambda: _robot_with('base').add_joint(Joint('j', 'fixed', 'base',
                                                                    'base')),
                        "joint 'j': parent and child are both 'base' (a joint connects two "
                        'different links)'),
}


@pytest.mark.parametrize('case', MISTAKES, ids=list(MISTAKES))
def test_a_mistake_is_one_line_naming_the_field(case: str) -> None:
    build, message = MISTAKES[case]
    with pytest.raises((ModelError, ModelTypeError)) as raised:
        build()
    assert str(raised.value) == message
    assert '\n' not in str(raised.value)


def test_values_are_coerced_to_floats_on_every_path() -> None:
    joint = Joint('j', 'revolute', 'a', 'b', axis=(0, 0, 1), origin=Origin((0, 0, 1)))
    assert joint.axis == (0.0, 0.0, 1.0) and all(type(v) is float for v in joint.axis)
    assert all(type(v) is float for v in joint.origin.xyz)
    assert Joint('j', 'revolute', 'a', 'b', axis=[True, 0, '0']).axis == (1.0, 0.0, 0.0)
    limit = JointLimit(-1, 1, effort=10, velocity='2')  # type: ignore[arg-type]
    assert (limit.lower, limit.upper, limit.effort, limit.velocity) == (-1.0, 1.0, 10.0, 2.0)
    assert all(type(v) is float for v in (limit.lower, limit.upper, limit.effort,
                                          limit.velocity))
    assert Box(1, 2, 3).size == (1.0, 2.0, 3.0)
    assert Origin((0, 0, 1)).xyz == (0.0, 0.0, 1.0)  # ints: converted once, then shared
    assert math.copysign(1.0, Origin((-0.0, 0, 1)).xyz[0]) == -1.0  # -0.0 is not 0
    assert math.copysign(1.0, Joint('j', 'fixed', 'a', 'b', axis=(0, -0.0, 1)).axis[1]) == -1.0
    assert Origin.above(Box(1, 2, 3)) == Origin((0, 0, 1.5))
    assert Origin.above(Box(1, 2, 3), xy=(1, 2), rpy=(0, 0, 1)) == Origin((1, 2, 1.5), (0, 0, 1))
    assert Inertial.from_box(1, 1, 2, 3).ixx == pytest.approx((4 + 9) / 12)


def test_a_reader_builds_faulty_elements_unchecked() -> None:
    with checks.unchecked():
        assert Joint('j', 'revolute', 'a', 'b', axis=(0, 0, 0)).axis == (0.0, 0.0, 0.0)
        assert Link('').name == ''
        limit = JointLimit(NAN, 1, effort=-1, velocity=INF)
        assert (limit.effort, limit.velocity) == (-1.0, INF)
        assert Origin((NAN, 0, 0)).xyz[0] != Origin((NAN, 0, 0)).xyz[0]
        robot = _robot_with('a')
        assert robot.add_joint(Joint('j', 'fixed', 'a', 'a')).joints[0].child == 'a'
        with pytest.raises(ModelError, match="unknown type 'x'"):  # the type is never unchecked
            Joint('j', 'x', 'a', 'b')


def test_lists_made_on_first_use_behave_as_lists() -> None:
    link = Link('a')
    assert link.extensions_if_any is None and link.sensors_if_any is None
    assert link == Link('a') and Link('a') == link  # one side's lists made by comparing
    block = Extension('<gazebo><mu1>0.5</mu1></gazebo>')
    link.extensions.append(block)
    assert link.extensions_if_any == [block] and link.extensions == [block]
    assert link != Link('a')
    joint = Joint('j', 'fixed', 'a', 'b', sensors=[Imu('imu')])
    assert joint.sensors_if_any is not None and joint.sensors[0].name == 'imu'
    assert Joint('j', 'fixed', 'a', 'b').extensions == []
    assert dataclasses.replace(link, name='b').extensions == [block]
    twin = copy.deepcopy(link)
    assert twin == link and twin.extensions is not link.extensions
    bare = pickle.loads(pickle.dumps(Joint('j', 'fixed', 'a', 'b', axis=(1, 0, 0))))
    assert bare == Joint('j', 'fixed', 'a', 'b', axis=(1, 0, 0)) and bare.sensors == []
    link.extensions = []
    assert link.extensions_if_any == []


def test_a_chain_built_in_python_reads_back_in_yourdfpy(tmp_path: Any) -> None:
    robot = Robot('chain')
    for index in range(50):
        box = Box(0.1, 0.05, 0.2 + index / 100)
        origin = Origin.above(box)
        link = Link(f'link_{index}').add_visual(Visual(box, origin=origin))
        link.add_collision(Collision(Sphere(0.05 + index / 1000), origin=origin))
        robot.add_link(link.set_inertial(Inertial.from_box(1.0 + index, 0.1, 0.05, 0.2,
                                                           origin=origin)))
        if index:
            robot.add_joint(Joint(f'joint_{index}', 'revolute', f'link_{index - 1}',
                                  f'link_{index}', origin=Origin(xyz=(0, 0, 0.2)),
                                  axis=(0, 0, 1), limit=JointLimit(-1.57, 1.57, effort=10,
                                                                   velocity=1)))
    path = tmp_path / 'chain.urdf'
    robot.to_urdf(path)
    theirs = load_yourdfpy(path)
    assert [link.name for link in theirs.links] == [link.name for link in robot.links]
    for ours, their in zip(robot.links, theirs.links):
        assert tuple(their.visuals[0].geometry.box.size) == ours.visuals[0].geometry.size
        assert their.collisions[0].geometry.sphere.radius == ours.collisions[0].geometry.radius
        assert their.visuals[0].origin[2][3] == ours.visuals[0].origin.xyz[2]
        assert their.inertial.mass == ours.inertial.mass
        assert their.inertial.inertia[0][0] == ours.inertial.ixx
    for ours_joint, their_joint in zip(robot.joints, theirs.joints):
        assert (their_joint.parent, their_joint.child) == (ours_joint.parent, ours_joint.child)
        assert tuple(their_joint.axis) == ours_joint.axis
        assert (their_joint.limit.lower, their_joint.limit.upper, their_joint.limit.effort,
                their_joint.limit.velocity) == (-1.57, 1.57, 10.0, 1.0)
