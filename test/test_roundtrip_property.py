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

"""Random valid robots survive writing and reading back (hypothesis)."""

from __future__ import annotations

import pytest

from urdfgenpy_ros import (
    Box, Collision, Cylinder, Inertial, Joint, JointDynamics, JointLimit, JointMimic, Link,
    Material, Mesh, Origin, Robot, SafetyController, Sphere, Visual)

hypothesis = pytest.importorskip('hypothesis')  # its decorators are needed at import
st = pytest.importorskip('hypothesis.strategies')

finite = st.floats(allow_nan=False, allow_infinity=False, min_value=-1e6, max_value=1e6)
positive = st.floats(min_value=1e-6, max_value=1e3, allow_nan=False)
vec3 = st.tuples(finite, finite, finite)
names = st.text(st.characters(codec='utf-8', exclude_categories=('Cs', 'Cc')), min_size=1,
                max_size=12).filter(lambda text: text.strip())
origins = st.builds(Origin, vec3, vec3)
scales = st.none() | st.tuples(positive, positive, positive)
shapes = st.one_of(st.builds(Box, positive, positive, positive),
                   st.builds(Cylinder, positive, positive), st.builds(Sphere, positive),
                   st.builds(Mesh, names, scales))
colours = st.tuples(*[st.floats(0, 1)] * 4)


@st.composite
def robots(draw) -> Robot:
    """Draw a valid robot: a random tree with random elements everywhere."""
    link_names = draw(st.lists(names, min_size=1, max_size=6, unique=True))
    robot = Robot(draw(names))
    materials = draw(st.lists(st.builds(Material, names, colours), max_size=2,
                              unique_by=lambda m: m.name))
    for material in materials:
        robot.add_material(material)
    for name in link_names:
        link = Link(name)
        for _ in range(draw(st.integers(0, 2))):
            material = draw(st.none() | st.sampled_from(materials)) if materials else None
            link.add_visual(Visual(draw(shapes), origin=draw(origins), material=material,
                                   name=draw(st.none() | names)))
        for _ in range(draw(st.integers(0, 2))):
            link.add_collision(Collision(draw(shapes), origin=draw(origins),
                                         name=draw(st.none() | names)))
        if draw(st.booleans()):
            link.set_inertial(Inertial(draw(positive), *draw(st.tuples(*[finite] * 6)),
                                       origin=draw(origins)))
        robot.add_link(link)
    joint_names = draw(st.lists(names, min_size=len(link_names) - 1,
                                max_size=len(link_names) - 1, unique=True))
    for index, (name, child) in enumerate(zip(joint_names, link_names[1:]), start=1):
        parent = link_names[draw(st.integers(0, index - 1))]
        kind = draw(st.sampled_from(['revolute', 'continuous', 'prismatic', 'fixed',
                                     'floating', 'planar']))
        lower, upper = sorted(draw(st.tuples(finite, finite)))
        limit = JointLimit(lower, upper, effort=draw(positive), velocity=draw(positive))
        robot.add_joint(Joint(
            name, kind, parent, child, origin=draw(origins),
            axis=draw(st.none() | st.sampled_from([(1, 0, 0), (0, 0, 1), (0.6, 0.8, 0)])),
            limit=limit if kind in ('revolute', 'prismatic') or draw(st.booleans()) else None,
            dynamics=draw(st.none() | st.builds(JointDynamics, finite, finite)),
            safety_controller=draw(st.none() | st.builds(SafetyController, finite, finite,
                                                         finite, finite)),
            mimic=(JointMimic(joint_names[0], draw(finite), draw(finite))
                   if index > 1 and draw(st.booleans()) else None)))
    return robot


@pytest.mark.slow  # 150 robots
@hypothesis.settings(max_examples=150, deadline=None)
@hypothesis.given(robots())
def test_write_then_read_gives_the_same_robot(robot: Robot) -> None:
    text = robot.to_urdf()
    again = Robot.from_urdf_string(text)
    assert again == robot
    assert again.to_urdf() == text
