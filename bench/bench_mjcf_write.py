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
The MJCF writer alone: ``write_mjcf(robot)`` to text, CPU time per robot, per code tree.

The robots are ``bench_mjcf.py``'s (registry robots, and the corpus files check_urdf
accepts), each read once; its meshes are converted by a first write that is not timed,
so the times are the writer's own (bodies, assets, actuators, keyframe, losses, ...).
Each code tree given (``--code DIR``) runs in a process of its own, the trees in turn,
``--rounds`` times; a robot's time is the median of its ``--repeat`` writes in a round,
then of the rounds. CPU time (``time.process_time``), not the wall clock: the machine is
shared. The table gives each tree's median and total over the robots every tree wrote,
and the median of the per-robot ratios to the first tree.

    URDFGENPY_CORPUS=/path/to/corpus python bench/bench_mjcf_write.py \
        --code /work/base-6684634 --code . --repeat 11 --rounds 3
"""

from __future__ import annotations

import argparse
import json
import os
from pathlib import Path
import statistics
import subprocess
import sys

WORKER = r"""
import json, os, statistics, sys, tempfile, time, warnings
sys.path[:0] = [sys.argv[1] + '/bench']
os.environ['URDFGENPY_CACHE_DIR'] = tempfile.mkdtemp(prefix='mesh-cache-')
import bench_mjcf
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.formats.mjcf import write_mjcf
warnings.simplefilter('ignore')
times = {}
for source, folders in bench_mjcf._robots():
    with bench_mjcf._silent():
        try:
            robot = load(source, {}, folders)
            write_mjcf(robot, search_paths=folders)
        except Exception:
            continue
        runs = []
        for _ in range(int(sys.argv[2])):
            start = time.process_time()
            write_mjcf(robot, search_paths=folders)
            runs.append(time.process_time() - start)
    times[str(source)] = statistics.median(runs)
json.dump(times, sys.stdout)
"""


def _round(code: Path, repeat: int) -> dict[str, float]:
    """Return each robot's median write time with the package at ``code``."""
    environment = dict(os.environ, PYTHONPATH=str(code))
    done = subprocess.run([sys.executable, '-c', WORKER, str(code), str(repeat)],
                          env=environment, capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def main() -> None:
    """Time every tree in turn; print a Markdown table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--code', type=Path, action='append', required=True)
    parser.add_argument('--repeat', type=int, default=11)
    parser.add_argument('--rounds', type=int, default=3)
    arguments = parser.parse_args()
    codes = [code.resolve() for code in arguments.code]
    rounds: dict[Path, list[dict[str, float]]] = {code: [] for code in codes}
    for _ in range(arguments.rounds):
        for code in codes:
            rounds[code].append(_round(code, arguments.repeat))
    robots = set.intersection(*(set(run) for runs in rounds.values() for run in runs))
    median = {code: {robot: statistics.median(run[robot] for run in runs)
                     for robot in robots} for code, runs in rounds.items()}
    first = median[codes[0]]
    print(f'{len(robots)} robots, median of {arguments.repeat} writes, then of '
          f'{arguments.rounds} rounds\n')
    print('| code | median ms | total ms | vs first (median of ratios) |')
    print('|---|---:|---:|---:|')
    for code in codes:
        mine = median[code]
        ratio = statistics.median(mine[robot] / first[robot] for robot in robots)
        print(f'| {code} | {statistics.median(mine.values()) * 1000:.1f} | '
              f'{sum(mine.values()) * 1000:.0f} | {ratio:.3f}x |')


if __name__ == '__main__':
    main()
