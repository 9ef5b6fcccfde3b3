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
Forward kinematics and gravity torques of TALOS: ours against pinocchio and robotics-toolbox.

TALOS is example-robot-data's ``talos_full_v2.urdf`` (60 links, 32 movable joints and 12
mimic ones in the grippers), in the bench extra. Each figure is the median of
``--repeat`` timings, in microseconds per configuration: one configuration per call
(200 random ones within the limits), or 10,000 in one call. pinocchio (C++) and
robotics-toolbox (``gravload``, ``fkine_all``; on a copy without meshes, which its URDF
reader cannot resolve) run in the same process on the same configurations; the largest
difference of their gravity torques from ours is printed beside them.

    python bench/bench_statics.py [--repeat 5]
"""

from __future__ import annotations

import argparse
from importlib import metadata
from pathlib import Path
import statistics
import tempfile
import time
from typing import Any, Callable

import numpy

from urdfgenpy_ros import Robot
from urdfgenpy_ros.dynamics.kinematics import link_poses

TALOS = 'cmeel.prefix/share/example-robot-data/robots/talos_data/robots/talos_full_v2.urdf'


def _per_config(function: Callable[[], Any], count: int, repeat: int) -> float:
    runs = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        runs.append((time.perf_counter() - start) / count)
    return statistics.median(runs) * 1e6


def _configurations(robot: Robot, count: int) -> numpy.ndarray:
    low, high = [], []
    for name in robot.movable_joints:
        limit = robot.get_joint(name).limit
        bounded = limit is not None and limit.lower < limit.upper
        low.append(limit.lower if bounded else -numpy.pi)
        high.append(limit.upper if bounded else numpy.pi)
    return numpy.random.default_rng(1).uniform(low, high, (count, len(low)))


def _pinocchio(robot: Robot) -> tuple[Any, Any, Any, Callable[[numpy.ndarray], Any]]:
    import pinocchio
    model = pinocchio.buildModelFromXML(robot.to_urdf())
    data = model.createData()
    followers = [(joint.name, robot.movable_joints.index(joint.mimic.joint),
                  joint.mimic.multiplier, joint.mimic.offset)
                 for joint in robot.joints if joint.is_movable and joint.mimic is not None]
    moved = [(model.joints[model.getJointId(name)].idx_q, number)
             for number, name in enumerate(robot.movable_joints)]
    mimic = [(model.joints[model.getJointId(name)].idx_q, column, factor, shift)
             for name, column, factor, shift in followers]
    velocity = [model.joints[model.getJointId(name)].idx_v for name in robot.movable_joints]
    folded = [(model.joints[model.getJointId(name)].idx_v, column, factor)
              for name, column, factor, _ in followers]

    def q_of(values: numpy.ndarray) -> numpy.ndarray:
        q = pinocchio.neutral(model)
        for index, number in moved:
            q[index] = values[number]
        for index, column, factor, shift in mimic:
            q[index] = factor * values[column] + shift
        return q

    def fold(torques: numpy.ndarray) -> numpy.ndarray:
        result = torques[velocity].copy()
        for index, column, factor in folded:
            result[column] += factor * torques[index]
        return result

    return pinocchio, model, data, (q_of, fold)


def _toolbox(robot: Robot, folder: Path) -> tuple[Any, Callable[[numpy.ndarray], Any]]:
    import roboticstoolbox
    from roboticstoolbox.models.URDF.URDFRobot import URDF_file
    bare = Robot.from_urdf_string(robot.to_urdf())
    for link in bare.links:
        link.visuals.clear()
        link.collisions.clear()
    bare.to_urdf(folder / 'talos_bare.urdf')
    links, name, _ = URDF_file(str(folder / 'talos_bare.urdf'))
    model = roboticstoolbox.Robot(links, name=name)
    by_child = {joint.child: joint for joint in robot.joints}
    order = {link.jindex: by_child[link.name] for link in model.links if link.isjoint}
    columns = [robot.movable_joints.index(order[index].name)
               if order[index].mimic is None else None for index in range(model.n)]
    mimic = [(index, robot.movable_joints.index(order[index].mimic.joint),
              order[index].mimic.multiplier, order[index].mimic.offset)
             for index in range(model.n) if order[index].mimic is not None]

    def q_of(values: numpy.ndarray) -> numpy.ndarray:
        q = numpy.array([values[column] if column is not None else 0.0
                         for column in columns])
        for index, column, factor, shift in mimic:
            q[index] = factor * values[column] + shift
        return q

    def fold(torques: numpy.ndarray) -> numpy.ndarray:
        result = numpy.zeros(len(robot.movable_joints))
        for index, column in enumerate(columns):
            if column is not None:
                result[column] += torques[index]
        for index, column, factor, _ in mimic:
            result[column] += factor * torques[index]
        return result

    return model, (q_of, fold)


def main(repeat: int = 5) -> None:
    """Print the table of microseconds per configuration."""
    path = Path(str(metadata.distribution('example-robot-data').locate_file(TALOS)))
    robot = Robot.from_urdf(path)
    many = _configurations(robot, 10_000)
    few = many[:200]
    names = robot.movable_joints
    pinocchio, model, data, (pin_q, pin_fold) = _pinocchio(robot)
    pin_few = [pin_q(values) for values in few]
    rows: list[tuple[str, float, str]] = []

    def ours_fk_single() -> None:
        for values in few:
            robot.fk(values)

    def ours_link_poses() -> None:
        for values in few[:50]:
            link_poses(robot, dict(zip(names, values)))

    def pin_fk() -> None:
        for q in pin_few:
            pinocchio.framesForwardKinematics(model, data, q)

    rows.append(('FK, every link, one configuration per call: `robot.fk(q)`',
                 _per_config(ours_fk_single, len(few), repeat), ''))
    rows.append(('FK, 10,000 configurations in one call: `robot.fk(Q)`',
                 _per_config(lambda: robot.fk(many), len(many), repeat), ''))
    rows.append(('FK, `kinematics.link_poses` (pure Python, before)',
                 _per_config(ours_link_poses, 50, repeat), ''))
    rows.append(('FK, pinocchio `framesForwardKinematics` (C++)',
                 _per_config(pin_fk, len(few), repeat), ''))
    ours = robot.gravity_torques(few)
    pin_torques = numpy.array([pin_fold(pinocchio.computeGeneralizedGravity(model, data, q))
                               for q in pin_few])

    def ours_gravity_single() -> None:
        for values in few:
            robot.gravity_torques(values)

    def pin_gravity() -> None:
        for q in pin_few:
            pinocchio.computeGeneralizedGravity(model, data, q)

    rows.append(('gravity torques, one configuration per call: `robot.gravity_torques(q)`',
                 _per_config(ours_gravity_single, len(few), repeat), ''))
    rows.append(('gravity torques, 10,000 configurations in one call',
                 _per_config(lambda: robot.gravity_torques(many), len(many), repeat), ''))
    rows.append(('gravity torques, pinocchio `computeGeneralizedGravity` (C++)',
                 _per_config(pin_gravity, len(few), repeat),
                 f'{abs(pin_torques - ours).max():.1e}'))
    with tempfile.TemporaryDirectory() as folder:
        toolbox, (rtb_q, rtb_fold) = _toolbox(robot, Path(folder))
    rtb_few = [rtb_q(values) for values in few[:20]]
    rtb_torques = numpy.array([rtb_fold(toolbox.gravload(q)) for q in rtb_few])

    def rtb_gravity() -> None:
        for q in rtb_few:
            toolbox.gravload(q)

    def rtb_fk() -> None:
        for q in rtb_few:
            toolbox.fkine_all(q)

    rows.insert(4, ('FK, robotics-toolbox `fkine_all`',
                    _per_config(rtb_fk, len(rtb_few), repeat), ''))
    rows.append(('gravity torques, robotics-toolbox `gravload`',
                 _per_config(rtb_gravity, len(rtb_few), repeat),
                 f'{abs(rtb_torques - ours[:20]).max():.1e}'))
    start = time.perf_counter()
    found = robot.validate(statics=True, check_meshes=False)
    search = time.perf_counter() - start
    print('| computation (TALOS, 60 links, 32 movable joints) | µs per configuration '
          '| largest difference from ours (N m) |\n|---|---:|---:|')
    for name, value, difference in rows:
        print(f'| {name} | {value:.1f} | {difference} |')
    statics = sum(finding.code == 'T801' for finding in found)
    print(f'\n`validate(statics=True)` (the worst case of all 32 joints): {search:.1f} s, '
          f'{statics} T801 finding(s)')


if __name__ == '__main__':
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=5)
    main(parser.parse_args().repeat)
