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

"""Forward kinematics, Jacobians and gravity torques against pinocchio on real robots."""

from __future__ import annotations

import math
from pathlib import Path
import warnings

from helpers import require_module
import numpy
import pytest
from registry_robots import robot_id, robots, search_paths

from urdfgenpy_ros import Inertial, Joint, JointLimit, JointMimic, Link, ModelError, Origin
from urdfgenpy_ros import Robot
from urdfgenpy_ros.formats import load

CONFIGS = 100


def _read(path: Path) -> Robot:
    return load(path, {}, search_paths())


class Pinocchio:
    """A robot in pinocchio, its mimic joints moved by hand (``mimic=False``)."""

    def __init__(self, robot: Robot) -> None:
        self.pin = require_module('pinocchio')
        with warnings.catch_warnings():
            warnings.simplefilter('ignore')  # quaternions written as rpy: exact to rounding
            text = robot.to_urdf(version='1.0')
        self.model = self.pin.buildModelFromXML(text)
        self.data = self.model.createData()
        self.robot = robot
        self.names = robot.movable_joints
        self.followers = []  # (joint, leader column, multiplier, offset), chains resolved
        column = {name: number for number, name in enumerate(self.names)}
        for joint in robot.joints:
            if joint.is_movable and joint.name not in column:
                multiplier, offset, leader = 1.0, 0.0, joint
                while leader.mimic is not None:
                    multiplier, offset = (multiplier * leader.mimic.multiplier,
                                          offset + multiplier * leader.mimic.offset)
                    leader = robot.get_joint(leader.mimic.joint)
                self.followers.append((joint.name, column[leader.name], multiplier, offset))

    def q(self, values: numpy.ndarray) -> numpy.ndarray:
        """Return pinocchio's configuration (continuous joints as cos, sin)."""
        q = self.pin.neutral(self.model)
        moved = [*zip(self.names, values),
                 *((name, multiplier * values[column] + offset)
                   for name, column, multiplier, offset in self.followers)]
        for name, value in moved:
            joint = self.model.joints[self.model.getJointId(name)]
            if joint.nq == 2:
                q[joint.idx_q:joint.idx_q + 2] = numpy.cos(value), numpy.sin(value)
            else:
                q[joint.idx_q] = value
        return q

    def fold(self, matrix: numpy.ndarray) -> numpy.ndarray:
        """Return pinocchio's columns (or entries) over our movable joints, mimic added."""
        def column(name: str) -> numpy.ndarray:
            return matrix[..., self.model.joints[self.model.getJointId(name)].idx_v]
        result = numpy.stack([column(name) for name in self.names], axis=-1)
        for name, leader, multiplier, _ in self.followers:
            result[..., leader] += multiplier * column(name)
        return result


def _configurations(robot: Robot, count: int, seed: int) -> numpy.ndarray:
    rng = numpy.random.default_rng(seed)
    low, high = [], []
    for name in robot.movable_joints:
        joint = robot.get_joint(name)
        limit = joint.limit
        bounded = joint.type.needs_limit and limit is not None and limit.lower < limit.upper
        low.append(limit.lower if bounded else -numpy.pi)
        high.append(limit.upper if bounded else numpy.pi)
    return rng.uniform(low, high, (count, len(low)))


def _link(name: str, mass: float, com: tuple[float, float, float]) -> Link:
    inertial = Inertial(mass, 0.02, 0.001, 0.0, 0.03, 0.0, 0.01,
                        origin=Origin(com, (0.2, -0.1, 0.4)))
    return Link(name).set_inertial(inertial)


def odd_robot() -> Robot:
    """Return a tree with quaternion origins, a floating joint, sliders and mimic chains."""
    robot = Robot('odd').add_link(Link('world')).add_link(_link('body', 3.0, (0, 0, 0.1)))
    robot.add_joint(Joint('free', 'floating', 'world', 'body',
                          origin=Origin((0.1, 0.2, 0.3), (0.1, 0.2, 0.3))))
    half = math.sqrt(0.5)  # parents are links: 'a' carries link_a
    specs = [('a', 'body', 'revolute', Origin((0.1, 0, 0.2), quat_xyzw=(0.1, 0.2, 0.3, 0.9)),
              (0.3, 0.4, 0.5), None),
             ('b', 'link_a', 'prismatic', Origin((0, 0.2, 0), (0.3, 0, 0.1)), (0, 0, 2), None),
             ('c', 'link_b', 'continuous', Origin((0.05, 0, 0.1), quat_xyzw=(half, 0, 0, half)),
              (1, 0, 0), JointMimic('a', 1.5, 0.2)),
             ('d', 'link_c', 'revolute', Origin((0.2, 0, 0)), (0, 1, 0),
              JointMimic('c', -0.5, 0.1)),
             ('e', 'body', 'revolute', Origin((-0.1, 0, 0.2), (0, 0.5, 0)), (0, 0, 1), None),
             ('f', 'link_e', 'prismatic', Origin((0, 0, 0.1)), (1, 0, 0),
              JointMimic('b', 2.0, 0)),
             ('g', 'link_f', 'fixed', Origin((0, 0.1, 0), quat_xyzw=(0, 0, half, half)), None,
              None)]
    for name, parent, kind, origin, axis, mimic in specs:
        robot.add_link(_link(f'link_{name}', 0.5, (0.05, 0.02, -0.03)))
        robot.add_joint(Joint(name, kind, parent, f'link_{name}', origin=origin, axis=axis,
                              limit=JointLimit(-1, 1, effort=10, velocity=1), mimic=mimic))
    return robot


ROBOTS = [pytest.param(path, id=robot_id(path)) for path in robots()] + ['odd']


def _robot(path: Path | str) -> Robot:
    return odd_robot() if path == 'odd' else _read(Path(path))


@pytest.mark.parametrize('path', ROBOTS)
@pytest.mark.engine
def test_fk_and_jacobians_equal_pinocchio_at_random_configurations(path: Path) -> None:
    robot = _robot(path)
    judge = Pinocchio(robot)
    pin, model, data = judge.pin, judge.model, judge.data
    configurations = _configurations(robot, CONFIGS, 7)
    poses = robot.fk(configurations)  # all at once; single ones below
    links = [link for link in poses if model.existFrame(link)]
    assert links
    jacobians = {(link, frame): robot.jacobian(link, configurations, frame=frame)
                 for link in links for frame in ('world', 'local')}  # every link's
    reference = {'world': pin.LOCAL_WORLD_ALIGNED, 'local': pin.LOCAL}
    worst = 0.0
    for number, values in enumerate(configurations):
        q = judge.q(values)
        pin.framesForwardKinematics(model, data, q)
        single = robot.fk(values) if number % 25 == 0 else None
        for link in links:
            expected = data.oMf[model.getFrameId(link)].homogeneous
            worst = max(worst, abs(poses[link][number] - expected).max())
            if single is not None:
                worst = max(worst, abs(single[link] - expected).max())
        pin.computeJointJacobians(model, data, q)
        for (link, frame), found in jacobians.items():
            theirs = pin.getFrameJacobian(model, data, model.getFrameId(link), reference[frame])
            expected = judge.fold(numpy.reshape(theirs, (6, model.nv)))  # nv 1 comes 1-D
            worst = max(worst, abs(found[number] - expected).max())
    assert worst < 1e-12


@pytest.mark.parametrize('path', ROBOTS)
def test_gravity_torques_equal_pinocchio(path: Path) -> None:
    robot = _robot(path)
    judge = Pinocchio(robot)
    configurations = _configurations(robot, CONFIGS, 11)
    torques = robot.gravity_torques(configurations)
    worst = 0.0
    for number, values in enumerate(configurations):
        expected = judge.fold(judge.pin.computeGeneralizedGravity(
            judge.model, judge.data, judge.q(values)))
        worst = max(worst, abs(torques[number] - expected).max())
    assert worst < 1e-9


def test_the_ways_to_give_q_agree_and_mistakes_are_named() -> None:
    robot = odd_robot()
    assert robot.movable_joints == ['a', 'b', 'e']
    by_name = robot.fk({'a': 0.3, 'b': -0.2})
    by_array = robot.fk([0.3, -0.2, 0.0])
    assert all((by_name[link] == by_array[link]).all() for link in by_array)
    assert (robot.fk(None)['link_g'] == robot.fk([0, 0, 0])['link_g']).all()
    # a few configurations are composed by pointer jumping, many link by link: both agree
    few = numpy.random.default_rng(2).uniform(-1, 1, (5, 3))
    many = numpy.concatenate([few, numpy.zeros((40, 3))])
    assert abs(robot.fk(few).array - robot.fk(many).array[:5]).max() < 1e-15
    assert abs(robot.fk(few[3]).array - robot.fk(many).array[3]).max() < 1e-15
    with pytest.raises(ModelError, match="q names 'z', which is not a joint of the robot "
                                         r'\(movable joints: a, b, e\)'):
        robot.fk({'z': 1.0})
    with pytest.raises(ModelError, match=r'q has shape \(2,\): give 3 values'):
        robot.fk([1.0, 2.0])


def test_q_names_only_joints_it_moves_and_only_finite_numbers() -> None:
    robot = odd_robot()
    # a mimic joint follows its leader (d follows c, which follows a): with strict, a value
    # that disagrees is a mistake (test_a_joint_state_names_mimic_joints: a warning without)
    with pytest.raises(ModelError, match=r"q gives mimic joint 'c' a value that does not "
                                         r"follow 'a' \(q\['c'\] is 99, .*\): leave 'c' out"):
        robot.fk({'a': 0.3, 'c': 99.0}, strict=True)
    with pytest.raises(ModelError, match="q gives mimic joint 'd' a value that does not "
                                         "follow 'a'"):
        robot.gravity_torques({'d': 0.1}, strict=True)
    with pytest.raises(ModelError, match="q names 'g', a joint q does not move "
                                         r'\(fixed, floating or planar; movable joints: '
                                         r'a, b, e\)'):
        robot.fk({'g': 1.0})
    with pytest.raises(ModelError, match="q names 'free', a joint q does not move"):
        robot.jacobian('link_a', {'free': 1.0})
    for bad in (math.nan, math.inf):
        with pytest.raises(ModelError, match=r"q\['a'\] is (nan|inf): give a finite number"):
            robot.fk({'a': bad})
        with pytest.raises(ModelError, match='not a finite number'):
            robot.gravity_torques([bad, 0.0, 0.0])
    with pytest.raises(ModelError, match=r"q\['a'\] is 'up': give a finite number"):
        robot.fk({'a': 'up'})
    with pytest.raises(ModelError, match='q must be numbers'):
        robot.fk(['up', 0.0, 0.0])
    with pytest.raises(ModelError, match="frame must be 'world' or 'local'"):
        robot.jacobian('link_d', [0, 0, 0], frame='base')
    with pytest.raises(ModelError, match="'hand' is not a link of the robot"):
        robot.jacobian('hand', [0, 0, 0])
    with pytest.raises(ModelError, match="payload: 'hand' is not a link of the robot"):
        robot.gravity_torques([0, 0, 0], payload={'link': 'hand', 'mass': 1.0})
    with pytest.raises(ModelError, match='mass must be a finite number >= 0'):
        robot.gravity_torques([0, 0, 0], payload={'link': 'link_d', 'mass': -1.0})


@pytest.mark.parametrize('source', ['kinova_robotiq.urdf', 'odd'])
def test_a_joint_state_names_mimic_joints(source: str) -> None:
    """
    A JointState's names and positions, mimic joints included, as robot_state_publisher.

    It computes each mimic joint from its leader; pinocchio (mimic joints moved by hand by
    the leader's formula) judges the poses. A value that disagrees is one warning line and
    the leader's value wins; with ``strict`` a ModelError.
    """
    robot = odd_robot() if source == 'odd' else _robot(
        next(path for path in robots() if path.name == source))
    judge = Pinocchio(robot)
    if not judge.followers:
        pytest.skip(f'{source} has no mimic joints')
    pin, model, data = judge.pin, judge.model, judge.data
    values = _configurations(robot, 1, 3)[0]
    names = [*judge.names, *(name for name, *_ in judge.followers)]
    given = [*values, *(multiplier * values[column] + offset
                        for _, column, multiplier, offset in judge.followers)]
    state = dict(zip(names, given))
    with warnings.catch_warnings():
        warnings.simplefilter('error')
        poses = robot.fk(state, strict=True)
    pin.framesForwardKinematics(model, data, judge.q(values))
    links = [link for link in poses if model.existFrame(link)]
    expected = {link: data.oMf[model.getFrameId(link)].homogeneous for link in links}
    assert max(abs(poses[link] - expected[link]).max() for link in links) < 1e-12
    follower = judge.followers[0][0]
    state[follower] += 0.25
    with pytest.warns(UserWarning) as caught:
        poses = robot.fk(state)
    assert len(caught) == 1 and '\n' not in str(caught[0].message)
    assert f'mimic joint {follower!r} follows' in str(caught[0].message)
    assert max(abs(poses[link] - expected[link]).max() for link in links) < 1e-12
    with pytest.raises(ModelError, match=f'q gives mimic joint {follower!r} a value'):
        robot.fk(state, strict=True)


def test_an_edited_robot_is_compiled_again() -> None:
    robot = odd_robot()
    before = robot.fk([0.1, 0.2, 0.3])['link_g'].copy()
    robot.get_joint('e').origin = Origin((-0.1, 0, 0.5), (0, 0.5, 0))
    after = robot.fk([0.1, 0.2, 0.3])['link_g']
    assert after[2, 3] != pytest.approx(before[2, 3])
    robot.get_joint('e').type = 'fixed'
    assert robot.movable_joints == ['a', 'b']
    robot.get_joint('e').type = 'revolute'
    assert robot.movable_joints == ['a', 'b', 'e']
    robot.get_link('link_d').inertial.mass = 5.0  # masses are read on every call
    heavier = robot.gravity_torques([0.1, 0.2, 0.3])
    robot.get_link('link_d').inertial.mass = 0.5
    assert abs(heavier - robot.gravity_torques([0.1, 0.2, 0.3])).max() > 1.0


def test_a_base_pose_moves_every_link_and_the_world_jacobian() -> None:
    robot = odd_robot()
    base = numpy.eye(4)
    base[:3, :3] = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]
    base[:3, 3] = (1.0, 2.0, 3.0)
    q = [0.2, 0.1, -0.4]
    moved, still = robot.fk(q, base=base), robot.fk(q)
    assert all(abs(moved[link] - base @ still[link]).max() < 1e-14 for link in still)
    world, local = robot.jacobian('link_d', q, base=base), robot.jacobian('link_d', q)
    assert abs(world[:3] - base[:3, :3] @ local[:3]).max() < 1e-14
    assert abs(robot.jacobian('link_d', q, 'local', base) - robot.jacobian(
        'link_d', q, 'local')).max() < 1e-14


def test_a_mimic_of_a_missing_joint_moves_on_its_own_and_j107_says_why() -> None:
    """As documented: it is a column of q (pinocchio without mimic moves it freely too)."""
    pin = require_module('pinocchio')
    robot = Robot('hand').add_link(_link('palm', 0.5, (0, 0, 0.05)))
    robot.add_link(_link('finger', 0.1, (0.03, 0, 0)))
    robot.add_joint(Joint('finger_joint', 'revolute', 'palm', 'finger', axis=(0, 1, 0),
                          origin=Origin((0.05, 0, 0.1)),
                          limit=JointLimit(-1, 1, effort=10, velocity=1),
                          mimic=JointMimic('index_q1', 2.0)))
    assert robot.movable_joints == ['finger_joint']
    assert [finding.code for finding in robot.validate(check_meshes=False)
            if finding.code.startswith('J10')] == ['J107']
    free = Robot.from_urdf_string(robot.to_urdf())
    free.get_joint('finger_joint').mimic = None
    model = pin.buildModelFromXML(free.to_urdf())
    data = model.createData()
    expected = pin.computeGeneralizedGravity(model, data, numpy.array([0.4]))
    assert robot.gravity_torques({'finger_joint': 0.4}) == pytest.approx(expected, abs=1e-12)
    assert model.nq == 1


def _agrees_with_pinocchio(robot: Robot, q: list[float]) -> bool:
    """Return whether FK, gravity and a Jacobian at ``q`` equal pinocchio's on ``robot``."""
    judge = Pinocchio(robot)
    pin, model, data = judge.pin, judge.model, judge.data
    pin.framesForwardKinematics(model, data, judge.q(numpy.asarray(q)))
    poses = robot.fk(q)
    worst = max(abs(poses[link] - data.oMf[model.getFrameId(link)].homogeneous).max()
                for link in poses if model.existFrame(link))
    gravity = judge.fold(pin.computeGeneralizedGravity(model, data, judge.q(numpy.asarray(q))))
    pin.computeJointJacobians(model, data, judge.q(numpy.asarray(q)))
    tip = robot.links[-1].name
    theirs = pin.getFrameJacobian(model, data, model.getFrameId(tip), pin.LOCAL_WORLD_ALIGNED)
    jacobian = judge.fold(numpy.reshape(theirs, (6, model.nv)))
    return bool(worst < 1e-12 and abs(robot.gravity_torques(q) - gravity).max() < 1e-9
                and abs(robot.jacobian(tip, q) - jacobian).max() < 1e-12)


def test_every_edit_after_a_call_is_seen_by_the_next_call() -> None:
    robot = odd_robot()
    q = [0.1, 0.2, 0.3]
    edits = [lambda: setattr(robot.get_joint('e'), 'origin', Origin((0.3, 0, 0.1), (0, 0.2, 1))),
             lambda: setattr(robot.get_joint('a'), 'axis', (0.0, 1.0, 0.0)),
             lambda: setattr(robot.get_joint('d'), 'mimic', JointMimic('a', -2.0, 0.3)),
             lambda: setattr(robot.get_joint('d'), 'mimic', None),
             lambda: setattr(robot.get_joint('f'), 'type', 'revolute'),
             lambda: setattr(robot.get_joint('e'), 'parent', 'link_a'),
             lambda: robot.remove_link('link_g'),
             lambda: robot.add_link(_link('tip', 1.0, (0, 0, 0.2))).add_joint(Joint(
                 'h', 'fixed', 'link_f', 'tip', origin=Origin((0, 0, 0.4)))),
             lambda: setattr(robot.get_link('tip'), 'name', 'tool')]
    assert _agrees_with_pinocchio(robot, q)
    for edit in edits:
        edit()
        q = [0.1 * (number + 1) for number in range(len(robot.movable_joints))]
        assert _agrees_with_pinocchio(robot, q)
    assert 'tool' in robot.fk(q) and 'tip' not in robot.fk(q)


@pytest.mark.parametrize('path', ROBOTS)
def test_the_pinocchio_path_gives_the_numpy_paths_numbers(path: Path) -> None:
    require_module('pinocchio')
    from urdfgenpy_ros.dynamics import compiled
    from urdfgenpy_ros.dynamics.accelerated import accelerated
    from urdfgenpy_ros.dynamics.forward import jacobian, link_matrices
    from urdfgenpy_ros.dynamics.gravity import gravity_torques, mass_model
    robot = _robot(path)
    model = compiled(robot)
    assert accelerated(model, robot, masses=True) is not None  # the path is taken
    configurations = _configurations(robot, 20, 5)
    tip = model.links[-1]
    torques = robot.gravity_torques(configurations)  # pinocchio's, where it is installed
    expected = gravity_torques(model, mass_model(robot, model), configurations)
    assert abs(torques - expected).max() <= 1e-12 * max(1.0, abs(expected).max())
    for frame in ('world', 'local'):
        found = robot.jacobian(tip, configurations, frame)
        assert abs(found - jacobian(model, tip, configurations, frame)).max() < 1e-12
        assert abs(robot.jacobian(tip, configurations[3], frame) - found[3]).max() < 1e-15
    for q in configurations[:4]:  # one configuration's poses are pinocchio's placements
        expected = link_matrices(model, q[None, :])[0]
        poses = robot.fk(q)
        assert max(abs(poses[link] - expected[number]).max()
                   for number, link in enumerate(model.links)) < 1e-12
        assert abs(poses.array - expected).max() < 1e-12
    tilted = (0.5, -9.0, -2.0)
    assert abs(robot.gravity_torques(configurations[0], tilted) - gravity_torques(
        model, mass_model(robot, model), configurations[:1], tilted)[0]).max() < 1e-12 * max(
            1.0, abs(expected).max())


@pytest.mark.parametrize('gravity', [(0.0, 0.0, math.nan), (1.0, 2.0), 'down'])
def test_a_gravity_that_is_not_three_finite_numbers_is_refused(gravity: object) -> None:
    with pytest.raises(ModelError, match='gravity must be three finite numbers'):
        odd_robot().gravity_torques([0.1, 0.2, 0.3], gravity)  # type: ignore[arg-type]


@pytest.mark.parametrize('base, message', [
    (numpy.full((4, 4), math.nan), 'not a finite number'),
    (numpy.diag([2.0, 2.0, 2.0, 1.0]), 'rigid pose'),  # a scaling
    (numpy.diag([1.0, 1.0, -1.0, 1.0]), 'rigid pose'),  # a mirror
    (numpy.ones((4, 4)), 'rigid pose')])
def test_a_base_that_is_not_a_rigid_pose_is_refused(base: numpy.ndarray, message: str) -> None:
    robot = odd_robot()
    for call in (lambda: robot.fk([0.1, 0.2, 0.3], base=base),
                 lambda: robot.jacobian('link_g', [0.1, 0.2, 0.3], base=base)):
        with pytest.raises(ModelError, match=message):
            call()


def test_a_pose_read_is_a_view_of_the_array_as_on_the_numpy_path() -> None:
    robot = odd_robot()
    poses = robot.fk([0.3, -0.2, 0.5])
    tool = poses['link_g']
    assert numpy.shares_memory(tool, poses.array)
    tool[0, 3] += 1.0  # written through, as into a numpy view
    assert poses.array[list(poses).index('link_g'), 0, 3] == tool[0, 3] == poses['link_g'][0, 3]
    with pytest.raises(KeyError, match="'nowhere' is not a link of the robot"):
        poses['nowhere']
    assert list(poses) == [link.name for link in robot.links] and len(poses) == len(robot.links)


def test_without_pinocchio_the_numpy_path_answers(monkeypatch: pytest.MonkeyPatch) -> None:
    from urdfgenpy_ros.dynamics import accelerated, compiled
    robot = odd_robot()
    q = [0.3, -0.2, 0.5]
    with_it = robot.gravity_torques(q), robot.jacobian('link_g', q, 'local'), robot.fk(q).array
    monkeypatch.setattr(accelerated, '_MODULE', [None])  # as if it were not installed
    assert accelerated.accelerated(compiled(robot), robot, True) is None
    without = robot.gravity_torques(q), robot.jacobian('link_g', q, 'local'), robot.fk(q).array
    for found, expected in zip(with_it, without):
        assert abs(found - expected).max() < 1e-12
