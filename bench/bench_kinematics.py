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
Transforms of a 60-link humanoid per joint configuration: ours against yourdfpy.

``JointTransforms.moving`` is what ``publish_tf`` computes each tick (each joint's
parent-to-child transform); ``link_poses`` is full forward kinematics of every link. The
peer is yourdfpy: ``update_cfg`` plus ``get_transform`` of every link. Median of
``--repeat`` timings of 200 random configurations each.

``--talos`` (bench extra: example-robot-data, pin, roboticstoolbox-python) times
``robot.fk`` and ``robot.gravity_torques`` on TALOS (60 links, 32 movable joints), one
configuration at a time and 10,000 at once, against pinocchio and robotics-toolbox in the
same run (see bench_statics.py).

    python bench/bench_kinematics.py [--repeat 5] [--talos]
"""

from __future__ import annotations

import argparse
import io
import random
import statistics
import time

from urdfgenpy_ros import Box, Inertial, Joint, JointLimit, Link, Origin, Robot
from urdfgenpy_ros.dynamics.kinematics import JointTransforms, link_poses


def humanoid(links: int = 60) -> Robot:
    """Return a tree of ``links`` links: a torso with five chains of revolute joints."""
    robot = Robot('humanoid').add_link(Link('base_link'))
    shape = Box(0.05, 0.05, 0.2)
    for index in range(1, links):
        parent = 'base_link' if index <= 5 else f'link_{index - 5}'
        robot.add_link(Link(f'link_{index}').set_inertial(Inertial.from_geometry(1.0, shape)))
        robot.add_joint(Joint(f'joint_{index}', 'revolute', parent, f'link_{index}',
                              origin=Origin((0.1, 0.02 * index, 0.2), (0.1, 0.2, 0.3)),
                              axis=(0, 1, 0), limit=JointLimit(-2, 2, effort=10, velocity=2)))
    return robot


def main() -> None:
    """Print microseconds per configuration."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=5)
    parser.add_argument('--talos', action='store_true',
                        help='time robot.fk and gravity torques on TALOS instead')
    args = parser.parse_args()
    if args.talos:
        from bench_statics import main as talos
        talos(args.repeat)
        return
    robot = humanoid()
    names = [joint.name for joint in robot.joints]
    rng = random.Random(1)
    states = [{name: rng.uniform(-2, 2) for name in names} for _ in range(200)]
    transforms = JointTransforms(robot)
    import yourdfpy
    model = yourdfpy.URDF.load(io.StringIO(robot.to_urdf()), load_meshes=False,
                               build_scene_graph=True)
    links = [link.name for link in robot.links]

    def peer(state):
        model.update_cfg(state)
        return [model.get_transform(link, 'base_link') for link in links]

    contenders = {'urdfgenpy_ros JointTransforms.moving (publish_tf)': transforms.moving,
                  'urdfgenpy_ros link_poses (all 60 links)': lambda s: link_poses(robot, s),
                  'yourdfpy update_cfg + get_transform (all 60 links)': peer}
    print('| computation | µs per configuration |\n|---|---:|')
    for name, function in contenders.items():
        runs = []
        for _ in range(args.repeat):
            start = time.perf_counter()
            for state in states:
                function(state)
            runs.append((time.perf_counter() - start) / len(states))
        print(f'| {name} | {statistics.median(runs) * 1e6:.0f} |')


if __name__ == '__main__':
    main()
