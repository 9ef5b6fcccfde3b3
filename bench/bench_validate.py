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
validate() against reading the same robot from its file, 100 to 10,000 links.

Robots are chains and wide trees like bench_build's (box visual, collision and inertial on
every link). For each size the script reports the median time of ``Robot.from_urdf_string``
and of ``robot.validate()`` on the read robot, and their ratio.

    python bench/bench_validate.py [--repeat 5]
"""

from __future__ import annotations

import argparse

from timing import median_seconds
from urdfgenpy_ros import (
    Box, Collision, Inertial, Joint, JointLimit, Link, Origin, Robot, Visual)


def build(count: int, shape: str) -> Robot:
    """Return a robot of ``count`` links."""
    robot = Robot('bench')
    for index in range(count):
        box = Box(0.1, 0.05, 0.2)
        origin = Origin.above(box)
        link = Link('base_link' if index == 0 else f'link_{index}')
        link.add_visual(Visual(box, origin=origin)).add_collision(Collision(box, origin=origin))
        if index:
            link.set_inertial(Inertial.from_box(1.0, 0.1, 0.05, 0.2, origin=origin))
            parent = 'base_link' if shape == 'wide' or index == 1 else f'link_{index - 1}'
            robot.add_link(link)
            robot.add_joint(Joint(f'joint_{index}', 'revolute', parent, link.name,
                                  origin=Origin((0, 0, 0.2)), axis=(0, 0, 1),
                                  limit=JointLimit(-1.57, 1.57, effort=10, velocity=1)))
        else:
            robot.add_link(link)
    return robot


def main() -> None:
    """Print a Markdown table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=5)
    args = parser.parse_args()
    print('| shape | links | read ms | validate ms | validate µs/link | validate / read |')
    print('|---|---:|---:|---:|---:|---:|')
    for shape in ('chain', 'wide'):
        for count in (100, 1000, 10000):
            text = build(count, shape).to_urdf().encode()
            robot = Robot.from_urdf_string(text)
            assert not [f for f in robot.validate() if str(f.severity) == 'error']
            read = median_seconds(lambda: Robot.from_urdf_string(text), args.repeat)
            check = median_seconds(lambda: robot.validate(), args.repeat)
            print(f'| {shape} | {count} | {read * 1e3:.1f} | {check * 1e3:.1f} | '
                  f'{check / count * 1e6:.1f} | {check / read:.2f} |')


if __name__ == '__main__':
    main()
