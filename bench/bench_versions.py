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
Time read, write, chain-build and MJCF export with several versions of the package at once.

Each version is a git commit (or a folder holding ``urdfgenpy_ros/``); a commit is
unpacked with ``git archive`` into a scratch folder. Every workload runs in a subprocess
with that version first on ``PYTHONPATH``, the versions taking turns round after round
(``--rounds``), so a busy machine slows them alike; a file's time is the median of its
rounds. The table gives, per workload, each version's per-file median time and its ratio
to the first version's, as the median and the 90th percentile over files.

Workloads: ``read`` (``Robot.from_urdf`` of every URDF below, a fresh parse each time),
``write`` (``to_urdf()`` of what was read, unedited), ``edited`` (the first ``to_urdf()``
of a robot just read and edited: renamed, one mass and one effort set), ``build`` (a
1,000-link chain made with the public API and written), ``mjcf`` (``to_mjcf()`` of the
registry robots, the mesh cache warm).

``--cpu`` times each call in the CPU time of its process (``time.process_time``) instead
of wall time: time spent waiting for a core that other work holds is not counted.

    python bench/bench_versions.py 6684634 068406d HEAD [--rounds 5] [--corpus DIR] [--cpu]
"""

from __future__ import annotations

import argparse
import json
import os
from pathlib import Path
import statistics
import subprocess
import sys
import tempfile

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
WORKER = r"""
import json, sys, time, warnings
warnings.simplefilter('ignore')
from timing import median_seconds
from urdfgenpy_ros import Robot
files = json.loads(sys.argv[1])
search = json.loads(sys.argv[2])
timer = time.process_time if sys.argv[3] == 'cpu' else time.perf_counter
def clock(function):
    return median_seconds(function, 3, timer)
def chain():
    from urdfgenpy_ros import Box, Collision, Inertial, Joint, JointLimit, Link, Origin, Visual
    robot = Robot('bench')
    for index in range(1000):
        box = Box(0.1, 0.05, 0.2)
        origin = Origin(xyz=(0, 0, 0.1))
        link = Link(f'link_{index}')
        link.add_visual(Visual(geometry=box, origin=origin))
        link.add_collision(Collision(geometry=box, origin=origin))
        link.set_inertial(Inertial.from_box(1.0, 0.1, 0.05, 0.2, origin=origin))
        robot.add_link(link)
        if index:
            robot.add_joint(Joint(f'joint_{index}', 'revolute', f'link_{index - 1}',
                                  f'link_{index}', origin=Origin(xyz=(0, 0, 0.2)),
                                  axis=(0, 0, 1),
                                  limit=JointLimit(-1.57, 1.57, effort=10, velocity=1)))
    robot.to_urdf()
def edited(file):
    robot = Robot.from_urdf(file)
    robot.name += '_edited'
    for link in robot.links:
        if link.inertial is not None:
            link.inertial.mass = link.inertial.mass * 2 + 0.125
            break
    for joint in robot.joints:
        if joint.limit is not None:
            joint.limit.effort = 7.5
            break
    return robot
out = {'build': {'chain-1000': clock(chain)}, 'read': {}, 'write': {}, 'edited': {}, 'mjcf': {}}
for file in files:
    robot = Robot.from_urdf(file)
    out['read'][file] = clock(lambda: Robot.from_urdf(file))
    out['write'][file] = clock(robot.to_urdf)
    copies = [edited(file) for _ in range(3)]  # each written once: a first write
    out['edited'][file] = clock(lambda: copies.pop().to_urdf())
    if file in search:
        try:
            robot.to_mjcf(search_paths=search[file])  # the mesh cache warm
        except Exception:  # what MuJoCo refuses is refused alike by every version
            continue
        out['mjcf'][file] = clock(lambda: robot.to_mjcf(search_paths=search[file]))
print(json.dumps(out))
"""


def unpack(version: str, scratch: Path) -> Path:
    """Return a folder holding ``version``'s package (a commit is unpacked into scratch)."""
    if Path(version, 'urdfgenpy_ros').is_dir():
        return Path(version).resolve()
    folder = scratch / version.replace('/', '_')
    folder.mkdir()
    archive = subprocess.run(['git', '-C', str(REPO), 'archive', version, 'urdfgenpy_ros'],
                             check=True, capture_output=True).stdout
    subprocess.run(['tar', '-x', '-C', str(folder)], input=archive, check=True)
    return folder


def robots(corpus: Path | None) -> tuple[list[str], dict[str, list[str]]]:
    """Return the URDF files, and the registry ones with their package folders (for MJCF)."""
    sys.path.insert(0, str(REPO / 'test'))
    import registry_robots
    registry = [path for path in registry_robots.robots() if path.suffix == '.urdf']
    folders = [str(folder) for folder in registry_robots.search_paths()]
    files = [str(path) for path in registry]
    if corpus is not None:
        files += sorted(str(path) for path in corpus.rglob('*.urdf'))
    return files, {str(path): folders for path in registry}


def run(folder: Path, files: list[str], search: dict[str, list[str]], clock: str = 'wall'
        ) -> dict:
    """Run the workloads once with the package in ``folder``; return their times."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join((str(folder), str(HERE))))  # + timing
    done = subprocess.run([sys.executable, '-c', WORKER, json.dumps(files), json.dumps(search),
                           clock], env=env, capture_output=True, text=True, cwd=folder)
    if done.returncode:
        sys.exit(f'{folder}: the workloads failed:\n{done.stderr[-2000:]}')
    return json.loads(done.stdout)


def readable(folders: dict[str, Path], files: list[str]) -> list[str]:
    """Return the files every version reads (a file one refuses is left out)."""
    check = ('import sys, json, warnings\nwarnings.simplefilter("ignore")\n'
             'from urdfgenpy_ros import Robot\nok = []\n'
             'for f in json.loads(sys.argv[1]):\n    try:\n        Robot.from_urdf(f)\n'
             '        ok.append(f)\n    except Exception:\n        pass\n'
             'print(json.dumps(ok))')
    kept = set(files)
    for folder in folders.values():
        done = subprocess.run([sys.executable, '-c', check, json.dumps(files)],
                              env=dict(os.environ, PYTHONPATH=str(folder)),
                              capture_output=True, text=True, check=True, cwd=folder)
        kept &= set(json.loads(done.stdout))
    return [file for file in files if file in kept]


def p90(values: list[float]) -> float:
    """Return the 90th percentile (nearest rank)."""
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(0.9 * (len(ordered) - 1)))]


def table(times: dict[str, list[dict]]) -> str:
    """Return the Markdown table: per workload and version, time and ratio to the first."""
    versions = list(times)
    first = versions[0]
    lines = ['| workload | files | ' + ' | '.join(
        f'{version} (ms, median)' for version in versions) + ' | ' + ' | '.join(
        f'{version} / {first} (median, p90)' for version in versions[1:]) + ' |',
        '|---|---:|' + '---:|' * (2 * len(versions) - 1)]
    for workload in ('read', 'write', 'edited', 'build', 'mjcf'):
        keys = list(times[first][0][workload])
        if not keys:
            continue
        per = {version: {key: statistics.median(r[workload][key] for r in runs)
                         for key in keys} for version, runs in times.items()}
        cells = [f'{1e3 * statistics.median(per[v].values()):.2f}' for v in versions]
        ratios = []
        for version in versions[1:]:
            each = [per[version][key] / per[first][key] for key in keys]
            ratios.append(f'{statistics.median(each):.2f}x, {p90(each):.2f}x')
        lines.append(f'| {workload} | {len(keys)} | ' + ' | '.join(cells + ratios) + ' |')
    return '\n'.join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('versions', nargs='+', help='git commits or folders, first = yardstick')
    parser.add_argument('--rounds', type=int, default=5)
    parser.add_argument('--corpus', type=Path, default=os.environ.get('URDFGENPY_CORPUS'))
    parser.add_argument('--cpu', action='store_true', help='CPU time instead of wall time')
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        folders = {version: unpack(version, Path(scratch)) for version in args.versions}
        files, search = robots(args.corpus)
        files = readable(folders, files)
        search = {file: paths for file, paths in search.items() if file in files}
        times: dict[str, list[dict]] = {version: [] for version in folders}
        for _ in range(args.rounds):
            for version, folder in folders.items():
                times[version].append(run(folder, files, search,
                                          'cpu' if args.cpu else 'wall'))
    print(table(times))


if __name__ == '__main__':
    main()
