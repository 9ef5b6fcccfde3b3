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
The collision matrix of Panda and TALOS at 10,000 samples: ours against the floor.

The floor is the plain loop any tool needs at least: for every state, pinocchio's
forward kinematics and coal's ``computeCollisions`` (C++) over every pair that sampling
has to decide (the pairs of links with collision geometry that are not adjacent), with
nothing decided early. It runs on the very states our computation draws (its rounds of
200, then the 10,000), in the same process. Ours is ``robot.to_srdf`` whole: the groups,
all four steps, and the Default pairs' collision rates over the 10,000 states.
example-robot-data's ``panda.urdf`` and ``talos_reduced.urdf``; medians of ``--repeat``.

    python bench/bench_srdf.py [--repeat 3] [--samples 10000]
"""

from __future__ import annotations

import argparse
from importlib import metadata
from pathlib import Path

import numpy
from timing import median_seconds

from urdfgenpy_ros import Robot
from urdfgenpy_ros.moveit import sampling
from urdfgenpy_ros.moveit.collision_matrix import adjacent_pairs, compute_matrix

ROBOTS = {'Panda': 'panda_description/urdf/panda.urdf',
          'TALOS': 'talos_data/robots/talos_reduced.urdf'}


def _share() -> Path:
    return Path(str(metadata.distribution('example-robot-data').locate_file(
        'cmeel.prefix/share')))


class Floor:
    """pinocchio FK + coal computeCollisions over the open pairs, every state."""

    def __init__(self, path: Path, robot: Robot, samples: int, seed: int) -> None:
        import pinocchio
        self.pin = pinocchio
        self.model, self.geometry, _ = pinocchio.buildModelsFromUrdf(str(path),
                                                                     [str(_share())])
        self.data = self.model.createData()
        link = [self.model.frames[g.parentFrame].name for g in self.geometry.geometryObjects]
        solid = set(link)
        adjacent = adjacent_pairs(robot, solid)
        for a in range(len(link)):
            for b in range(a + 1, len(link)):
                key = tuple(sorted((link[a], link[b])))
                if link[a] != link[b] and key not in adjacent:
                    self.geometry.addCollisionPair(pinocchio.CollisionPair(a, b))
        self.placed = pinocchio.GeometryData(self.geometry)
        matrix = compute_matrix(robot, samples, seed, search_paths=[_share()])
        generator, ranges = sampling.generator(seed), sampling.bounds(robot)
        rows = sampling.random_states(ranges, sampling.ROUND * matrix.rounds + samples,
                                      generator)
        self.states = [self._q(robot, row) for row in rows]

    def _q(self, robot: Robot, row: numpy.ndarray) -> numpy.ndarray:
        values = dict(zip(robot.movable_joints, row))
        for joint in robot.joints:
            if joint.mimic is not None and joint.type.is_movable:
                values[joint.name] = joint.mimic.multiplier * values.get(
                    joint.mimic.joint, 0.0) + joint.mimic.offset
        q = self.pin.neutral(self.model)
        for index in range(1, self.model.njoints):
            joint, value = self.model.joints[index], values.get(self.model.names[index], 0.0)
            if joint.nq == 1:
                q[joint.idx_q] = value
            elif joint.nq == 2:
                q[joint.idx_q:joint.idx_q + 2] = (numpy.cos(value), numpy.sin(value))
        return q

    def run(self) -> None:
        for q in self.states:
            self.pin.computeCollisions(self.model, self.data, self.geometry, self.placed, q,
                                       False)


def main(repeat: int, samples: int) -> None:
    print('| robot | links with geometry | pairs to decide | ours (s) | floor (s) | '
          'ours / floor |\n|---|---|---|---|---|---|')
    for name, relative in ROBOTS.items():
        path = _share() / 'example-robot-data' / 'robots' / relative
        robot = Robot.from_urdf(path)
        floor = Floor(path, robot, samples, 0)
        ours = median_seconds(lambda: robot.to_srdf(samples=samples, seed=0,
                                                    search_paths=[_share()]), repeat)
        theirs = median_seconds(floor.run, repeat)
        links = len({floor.model.frames[g.parentFrame].name
                     for g in floor.geometry.geometryObjects})
        print(f'| {name} | {links} | {len(floor.geometry.collisionPairs)} object pairs | '
              f'{ours:.2f} | {theirs:.2f} | {ours / theirs:.2f} |')


if __name__ == '__main__':
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=3)
    parser.add_argument('--samples', type=int, default=10000)
    arguments = parser.parse_args()
    main(arguments.repeat, arguments.samples)
