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
Time from a 7-row DH table (Franka Panda, Craig's convention) to a URDF string.

    python bench/bench_dh.py [--repeat 7] [--number 200]
"""

from __future__ import annotations

import argparse
from math import pi
import statistics
import timeit

from urdfgenpy_ros import Origin
from urdfgenpy_ros.dh import DHConvention, DHRow, DHTable

PANDA = DHTable(DHConvention.MODIFIED, [
    DHRow(1, 0, 0, 0.333), DHRow(2, 0, -pi / 2, 0), DHRow(3, 0, pi / 2, 0.316),
    DHRow(4, 0.0825, pi / 2, 0), DHRow(5, -0.0825, -pi / 2, 0.384), DHRow(6, 0, pi / 2, 0),
    DHRow(7, 0.088, pi / 2, 0)], tool=Origin((0, 0, 0.107)))


def main() -> None:
    """Print the median time per conversion, in microseconds."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=7)
    parser.add_argument('--number', type=int, default=200)
    args = parser.parse_args()
    steps = {'to_robot': lambda: PANDA.to_robot('panda'),
             'to_robot + to_urdf': lambda: PANDA.to_robot('panda').to_urdf(),
             'to_robot + to_xacro': lambda: PANDA.to_robot('panda').to_xacro()}
    print('| step | µs per 7-row table (median) |\n|---|---:|')
    for name, step in steps.items():
        runs = timeit.repeat(step, number=args.number, repeat=args.repeat)
        print(f'| {name} | {statistics.median(runs) / args.number * 1e6:.0f} |')


if __name__ == '__main__':
    main()
