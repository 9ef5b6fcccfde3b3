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
Edits to a read file are never lost: random edits through the public API, checked in yourdfpy.

Each edit is applied twice: to our model (then written) and to yourdfpy's model of the
original file (the expectation). yourdfpy then reads what we wrote: every edited value
must be exactly what was set, every other field what the file had.
"""

from __future__ import annotations

from pathlib import Path
import tempfile

from helpers import CORPUS, corpus_cases, load_yourdfpy, pose_matrix, require_module, snapshot
import pytest

from urdfgenpy_ros import Box, Cylinder, Origin, Robot, Sphere, Visual

hypothesis = require_module('hypothesis')
st = require_module('hypothesis.strategies')

FIXTURES = Path(__file__).parent / 'fixtures' / 'io'
LAYOUTS = sorted(FIXTURES.glob('*.urdf'))

small = st.floats(min_value=-10.0, max_value=10.0, allow_nan=False, allow_subnormal=False)
positive = st.floats(min_value=1e-4, max_value=10.0, allow_nan=False)
vec3 = st.tuples(small, small, small)
origins = st.builds(Origin, vec3, vec3)
shapes = st.one_of(st.builds(Box, positive, positive, positive),
                   st.builds(Cylinder, positive, positive), st.builds(Sphere, positive))
KINDS = ('origin_twice', 'geometry', 'mass', 'limit', 'joint_origin', 'replace_visual',
         'rename_link', 'block')


def _their_geometry(yourdfpy, shape):
    """Return yourdfpy's Geometry for one of our shapes."""
    import numpy
    if isinstance(shape, Box):
        return yourdfpy.Geometry(box=yourdfpy.Box(size=numpy.array(shape.size)))
    if isinstance(shape, Cylinder):
        return yourdfpy.Geometry(cylinder=yourdfpy.Cylinder(radius=shape.radius,
                                                            length=shape.length))
    return yourdfpy.Geometry(sphere=yourdfpy.Sphere(radius=shape.radius))


def _apply(data, kind: str, robot: Robot, theirs, yourdfpy) -> None:
    """Apply one random edit of ``kind`` to our model and to yourdfpy's alike."""
    links = {link.name: link for link in theirs.links}
    joints = {joint.name: joint for joint in theirs.joints}
    if kind in ('origin_twice', 'geometry', 'replace_visual'):
        owners = [link for link in robot.links if link.visuals or kind == 'replace_visual']
        link = data.draw(st.sampled_from(owners), label='link')
        their_link = links[link.name]
        if kind == 'replace_visual':
            if link.visuals:
                index = data.draw(st.integers(0, len(link.visuals) - 1), label='removed')
                del link.visuals[index]
                del their_link.visuals[index]
            origin, shape = data.draw(origins, label='origin'), data.draw(shapes, label='shape')
            link.add_visual(Visual(shape, origin=origin))
            their_link.visuals.append(yourdfpy.Visual(
                name=None, origin=pose_matrix(origin),
                geometry=_their_geometry(yourdfpy, shape), material=None))
            return
        index = data.draw(st.integers(0, len(link.visuals) - 1), label='visual')
        visual, their_visual = link.visuals[index], their_link.visuals[index]
        if kind == 'origin_twice':
            visual.origin = data.draw(origins, label='first origin')
            visual.origin = last = data.draw(origins, label='second origin')
            their_visual.origin = pose_matrix(last)
        else:
            visual.geometry = shape = data.draw(shapes, label='shape')
            their_visual.geometry = _their_geometry(yourdfpy, shape)
    elif kind == 'mass':
        link = data.draw(st.sampled_from([link for link in robot.links
                                          if link.inertial is not None]), label='link')
        link.inertial.mass = mass = data.draw(positive, label='mass')
        links[link.name].inertial.mass = mass
    elif kind == 'limit':
        joint = data.draw(st.sampled_from([joint for joint in robot.joints
                                           if joint.limit is not None]), label='joint')
        name = data.draw(st.sampled_from(['lower', 'upper', 'effort', 'velocity']),
                         label='attribute')
        value = data.draw(positive, label='value')
        setattr(joint.limit, name, value)
        setattr(joints[joint.name].limit, name, value)
    elif kind == 'block':  # edited in place, as lxml lets a user: an attribute, a child
        block = data.draw(st.sampled_from(_blocks(robot)), label='block')
        element = block.element
        for node in element.iter():
            if isinstance(node.tag, str) and data.draw(st.booleans(), label='touch'):
                node.set('edited', str(data.draw(positive, label='value')))
        if data.draw(st.booleans(), label='insert'):
            from lxml import etree
            element.insert(0, etree.Element('inserted', {'edited': 'first'}))
    elif kind == 'joint_origin':
        joint = data.draw(st.sampled_from(robot.joints), label='joint')
        joint.origin = origin = data.draw(origins, label='origin')
        joints[joint.name].origin = pose_matrix(origin)
    else:
        link = data.draw(st.sampled_from(robot.links), label='renamed')
        old, new = link.name, f'renamed_{len(robot.links)}_{link.name}'
        robot.rename_link(old, new)
        links[old].name = new
        for joint in theirs.joints:
            joint.parent = new if joint.parent == old else joint.parent
            joint.child = new if joint.child == old else joint.child


def _blocks(robot: Robot) -> list:
    """Return every <gazebo>/<transmission>/<ros2_control> block of the robot."""
    return [*robot.extensions, *[block for owner in [*robot.links, *robot.joints]
                                 for block in owner.extensions]]


def _content(element) -> list:
    """Return a block's elements as (tag, attributes), its reference aside (renames)."""
    return sorted((str(node.tag), sorted((key, value) for key, value in node.attrib.items()
                                         if not (node is element and key == 'reference')))
                  for node in element.iter() if isinstance(node.tag, str))


def _normal(value):
    """Return yourdfpy's model as plain values; a missing origin is the identity."""
    import numpy
    plain = snapshot(value)

    def visit(item):
        if isinstance(item, dict):
            for key, sub in item.items():
                if key == 'origin' and sub is None:
                    item[key] = numpy.eye(4).tolist()
                else:
                    visit(sub)
        elif isinstance(item, list):
            for sub in item:
                visit(sub)
    visit(plain)
    plain.pop('gazebo', None)
    return plain


def _check_edits(path: Path, data, write_between: bool = False) -> None:
    yourdfpy = require_module('yourdfpy')
    robot = Robot.from_urdf(path)
    theirs = load_yourdfpy(path)
    kinds = data.draw(st.lists(st.sampled_from(KINDS), min_size=1, max_size=4), label='edits')
    for kind in kinds:
        usable = {'mass': any(link.inertial for link in robot.links),
                  'limit': any(joint.limit for joint in robot.joints),
                  'joint_origin': bool(robot.joints),
                  'origin_twice': any(link.visuals for link in robot.links),
                  'geometry': any(link.visuals for link in robot.links),
                  'block': bool(_blocks(robot))}
        if usable.get(kind, bool(robot.links)):
            _apply(data, kind, robot, theirs, yourdfpy)
        if write_between:  # what a write keeps of the file's text must not outlive an edit
            robot.to_urdf()
    with tempfile.TemporaryDirectory() as folder:
        written = Path(folder) / path.name
        robot.to_urdf(written)
        assert _normal(load_yourdfpy(written)) == _normal(theirs)
        assert Robot.from_urdf(written) == robot
        from lxml import etree
        root = etree.parse(str(written)).getroot()
        blocks = [node for node in root if node.tag in ('gazebo', 'transmission', 'ros2_control')]
        assert sorted(_content(node) for node in blocks) == \
            sorted(_content(block.element) for block in _blocks(robot))


@pytest.mark.parametrize('path', LAYOUTS, ids=[path.name for path in LAYOUTS])
def test_random_edits_are_all_written(path: Path) -> None:
    """Every edit survives writing, and nothing else changes (files of every layout)."""
    @hypothesis.settings(max_examples=60, deadline=None, derandomize=True)
    @hypothesis.given(data=st.data())
    def check(data) -> None:
        _check_edits(path, data)
    check()


@pytest.mark.parametrize('path', LAYOUTS, ids=[path.name for path in LAYOUTS])
def test_edits_between_writes_are_all_written(path: Path) -> None:
    """A robot written after each edit still writes every edit (nothing kept goes stale)."""
    @hypothesis.settings(max_examples=15, deadline=None, derandomize=True)
    @hypothesis.given(data=st.data())
    def check(data) -> None:
        _check_edits(path, data, write_between=True)
    check()


def _edit_blocks(robot: Robot) -> None:
    """Edit what lxml holds: each block gets a child and an attribute."""
    from lxml import etree
    for number, block in enumerate(_blocks(robot)):
        etree.SubElement(block.element, 'kept').text = f'block {number}'
        block.element.set('edited', 'yes')


def _edit_values(robot: Robot) -> None:
    """Edit the model: every limit's effort, the last link's name."""
    for joint in robot.joints:
        if joint.limit is not None:
            joint.limit.effort = 3.5
    robot.links[-1].name = 'renamed_last'


@pytest.mark.parametrize('path', LAYOUTS, ids=[path.name for path in LAYOUTS])
def test_writes_between_edits_change_nothing_written_after(path: Path) -> None:
    """Written between its edits or not, a robot writes the same (yourdfpy sees the edits)."""
    once = Robot.from_urdf(path)
    _edit_blocks(once)
    _edit_values(once)
    expected = once.to_urdf()
    twice = Robot.from_urdf(path)
    twice.to_urdf()
    _edit_blocks(twice)
    twice.to_urdf()
    _edit_values(twice)
    with tempfile.TemporaryDirectory() as folder:
        written = Path(folder) / path.name
        assert twice.to_urdf(written) == expected
        theirs = load_yourdfpy(written)
    assert 'renamed_last' in [link.name for link in theirs.links]
    assert {joint.limit.effort for joint in theirs.joints if joint.limit is not None} <= {3.5}
    assert expected.count('<kept>') == len(_blocks(once))


def test_a_copy_of_a_written_robot_writes_as_a_robot_never_written() -> None:
    """What a write keeps of the file stays with the robot written, not with its copies."""
    import copy
    path = FIXTURES / 'crlf.urdf'
    original = Robot.from_urdf(path)
    _edit_values(original)
    written = original.to_urdf()
    twin = copy.deepcopy(original)
    _edit_blocks(twin)
    expected = Robot.from_urdf(path)
    _edit_values(expected)
    _edit_blocks(expected)
    assert twin.to_urdf() == expected.to_urdf() != written
    assert original.to_urdf() == written


def _corpus_files() -> list[Path]:
    if not CORPUS.is_dir():
        return []
    return sorted(path for path in CORPUS.rglob('*.urdf') if 'fail' not in path.name)


@pytest.mark.parametrize('path', corpus_cases(_corpus_files(),
                                              [path.name for path in _corpus_files()]))
@pytest.mark.slow
def test_random_edits_on_corpus(path: Path, corpus: Path) -> None:
    """The same on every real robot of the corpus that both readers accept."""
    try:
        Robot.from_urdf(path)
        load_yourdfpy(path)
    except Exception as error:  # noqa: B902 - files either reader refuses are not the subject
        pytest.skip(f'not readable by both readers: {error}')

    @hypothesis.settings(max_examples=15, deadline=None, derandomize=True)
    @hypothesis.given(data=st.data())
    def check(data) -> None:
        _check_edits(path, data)
    check()
