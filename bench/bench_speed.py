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
What users wait for (issue 41): statics, start-up and kinematics, against their yardsticks.

Every contender runs as its own Python process, rounds interleaved (each round runs every
contender once, so the shared machine's load hits all alike); a figure is the median of
``--repeat`` rounds with the smallest and largest beside it. ``--baseline`` is a source
tree of an older version (``git worktree add /tmp/base 6684634``), run with
``PYTHONPATH`` set to it; given again, more versions join every table (statics' ratio
is to the first). Bytecode is cached for all (``PYTHONPYCACHEPREFIX`` in a temporary folder,
``PYTHONDONTWRITEBYTECODE`` dropped), as in any installed package.

- **Statics**: ``robot.validate(statics=True)`` on TALOS, TIAGo and TIAGo dual
  (example-robot-data, the bench extra): the seconds of CPU inside the process, and the
  T801 findings of both versions compared line by line.
- **Start-up**: ``urdfgenpy check`` of a two-link file as a process, CPU time (user +
  system), against ``python -c "import lxml.etree"``, the floor of any reader; beside it
  how many modules each process loads (the package's, and all), counted in one more run.
- **Kinematics** on TALOS: one ``robot.fk``/``gravity_torques``/``jacobian`` per call
  (200 configurations) and 10,000 in one call, microseconds of CPU per configuration
  (the process's, every thread's: OpenBLAS's waiting threads count), against pinocchio's
  ``framesForwardKinematics``, ``computeGeneralizedGravity`` and
  ``computeJointJacobians`` + ``getFrameJacobian`` in the same process. CPU time, as
  the wall clock of a process the shared machine deschedules counts other sessions' work.

    python bench/bench_speed.py --baseline /tmp/base [--repeat 5]
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
from typing import Any

HERE = Path(__file__).resolve().parent.parent
ROBOTS = {'TALOS': 'talos_data/robots/talos_full_v2.urdf',
          'TIAGo': 'tiago_description/robots/tiago.urdf',
          'TIAGo dual': 'tiago_description/robots/tiago_dual.urdf'}
SMALL = """<?xml version="1.0"?>
<robot name="small">
  <link name="base"/>
  <link name="arm"><inertial><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="10" velocity="1"/></joint>
</robot>
"""
STATICS = """
import json, sys, time
from urdfgenpy_ros import Robot
robot = Robot.from_urdf(sys.argv[1])
start = time.process_time()
found = robot.validate(statics=True, check_meshes=False)
print(json.dumps([time.process_time() - start,
                  [f'{item.code} {item.message}' for item in found if item.code == 'T801']]))
"""
KINEMATICS = """
import json, statistics, sys, time
import numpy
from urdfgenpy_ros import Robot
robot = Robot.from_urdf(sys.argv[1])
dof = len(robot.movable_joints)
rng = numpy.random.default_rng(1)
few, many = rng.uniform(-1, 1, (200, dof)), rng.uniform(-1, 1, (10_000, dof))
link = 'arm_left_7_link'
def per(function, count):
    runs = []
    for _ in range(5):
        start = time.process_time()
        function()
        runs.append((time.process_time() - start) / count * 1e6)
    return statistics.median(runs)
result = {
    'fk': per(lambda: [robot.fk(q) for q in few], len(few)),
    'fk batch': per(lambda: robot.fk(many), len(many)),
    'gravity': per(lambda: [robot.gravity_torques(q) for q in few], len(few)),
    'gravity batch': per(lambda: robot.gravity_torques(many), len(many)),
    'jacobian': per(lambda: [robot.jacobian(link, q) for q in few], len(few)),
    'jacobian batch': per(lambda: robot.jacobian(link, many), len(many))}
if len(sys.argv) > 2:
    import pinocchio
    model = pinocchio.buildModelFromXML(robot.to_urdf())
    data = model.createData()
    configurations = [pinocchio.randomConfiguration(model) for _ in range(200)]
    frame = model.getFrameId(link)
    def jacobians():
        for q in configurations:
            pinocchio.computeJointJacobians(model, data, q)
            pinocchio.getFrameJacobian(model, data, frame, pinocchio.LOCAL_WORLD_ALIGNED)
    result.update({
        'pinocchio fk': per(lambda: [pinocchio.framesForwardKinematics(model, data, q)
                                     for q in configurations], 200),
        'pinocchio gravity': per(lambda: [pinocchio.computeGeneralizedGravity(model, data, q)
                                          for q in configurations], 200),
        'pinocchio jacobian': per(jacobians, 200)})
print(json.dumps(result))
"""


def _environment(tree: Path | None, cache: Path) -> dict[str, str]:
    environment = dict(os.environ)
    environment.pop('PYTHONDONTWRITEBYTECODE', None)
    environment['PYTHONPYCACHEPREFIX'] = str(cache / (tree.name if tree else 'floor'))
    environment['OPENBLAS_NUM_THREADS'] = '1'
    if tree is not None:
        environment['PYTHONPATH'] = str(tree)
    return environment


def _cpu(command: list[str], environment: dict[str, str], folder: Path) -> float:
    """Return the CPU seconds (user + system) of one run of ``command``."""
    process = subprocess.Popen(command, env=environment, cwd=folder,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, _, usage = os.wait4(process.pid, 0)
    return usage.ru_utime + usage.ru_stime


def _output(code: str, arguments: list[str], environment: dict[str, str],
            folder: Path) -> Any:
    done = subprocess.run([sys.executable, '-c', code, *arguments], env=environment,
                          cwd=folder, capture_output=True, text=True, check=True)
    return json.loads(done.stdout.splitlines()[-1])


def _spread(values: list[float], digits: int = 3) -> str:
    return (f'**{statistics.median(values):.{digits}f}** '
            f'({min(values):.{digits}f}-{max(values):.{digits}f})')


def _robots() -> dict[str, str]:
    from importlib import metadata
    share = 'cmeel.prefix/share/example-robot-data/robots'
    folder = Path(str(metadata.distribution('example-robot-data').locate_file(share)))
    return {name: str(folder / path) for name, path in ROBOTS.items()}


def statics(trees: dict[str, Path], cache: Path, folder: Path, repeat: int) -> None:
    """Print validate(statics=True) seconds per robot and version, and whether T801 agree."""
    print('| robot | ' + ' | '.join(f'{name} (s CPU)' for name in trees) + ' | ratio '
          '| T801 findings |\n|---|' + '---:|' * (len(trees) + 1) + '---|')
    for robot, path in _robots().items():
        seconds: dict[str, list[float]] = {name: [] for name in trees}
        findings = {}
        for _ in range(repeat):
            for name, tree in trees.items():
                took, found = _output(STATICS, [path], _environment(tree, cache), folder)
                seconds[name].append(took)
                findings[name] = found
        first, *others = trees
        same = all(findings[name] == findings[first] for name in others)
        ratio = (statistics.median(seconds[others[0]]) / statistics.median(seconds[first])
                 if others else 1.0)
        print(f'| {robot} | ' + ' | '.join(_spread(seconds[name], 2) for name in trees)
              + f' | {ratio:.0f}x | {len(findings[first])}, '
              + ('the same' if same else 'DIFFERENT') + ' |')


def _loaded(command: list[str], environment: dict[str, str], folder: Path) -> str:
    """Return how many modules ``command`` loads: the package's, and all (``64 / 183``)."""
    code = ('import atexit, sys\natexit.register(lambda: print(len([name for name in '
            "sys.modules if name.split('.')[0] == 'urdfgenpy_ros']), '/', len(sys.modules), "
            'file=sys.stderr))\n' + command[2])
    done = subprocess.run([command[0], '-c', code, *command[3:]], env=environment,
                          cwd=folder, capture_output=True, text=True)
    return done.stderr.splitlines()[-1]


def startup(trees: dict[str, Path], cache: Path, folder: Path, repeat: int) -> None:
    """Print the CPU seconds of a one-file check process and of the floor."""
    small = folder / 'small.urdf'
    small.write_text(SMALL)
    runs: dict[str, tuple[list[str], dict[str, str]]] = {
        'python -c "import lxml.etree" (floor)': (
            [sys.executable, '-c', 'import lxml.etree'], _environment(None, cache))}
    for name, tree in trees.items():
        runs[f'urdfgenpy check small.urdf ({name})'] = (
            [sys.executable, '-c', 'from urdfgenpy_ros.cli import main; main()', 'check',
             str(small)], _environment(tree, cache))
    for command, environment in runs.values():  # byte-compile first
        _cpu(command, environment, folder)
    seconds: dict[str, list[float]] = {label: [] for label in runs}
    for _ in range(repeat * 3):
        for label, (command, environment) in runs.items():
            seconds[label].append(_cpu(command, environment, folder))
    floor = statistics.median(next(iter(seconds.values())))
    print('| process | s CPU (median, min-max) | of the floor | modules loaded (package / all) |'
          '\n|---|---:|---:|---:|')
    for label, values in seconds.items():
        print(f'| {label} | {_spread(values)} | {statistics.median(values) / floor:.2f}x | '
              f'{_loaded(*runs[label], folder)} |')


def kinematics(trees: dict[str, Path], cache: Path, folder: Path, repeat: int) -> None:
    """Print µs per configuration on TALOS, each version and pinocchio."""
    path = _robots()['TALOS']
    found: dict[str, dict[str, list[float]]] = {name: {} for name in trees}
    for _ in range(repeat):
        for number, (name, tree) in enumerate(trees.items()):
            extra = ['pinocchio'] if number == 0 else []
            result = _output(KINEMATICS, [path, *extra], _environment(tree, cache), folder)
            for key, value in result.items():
                found[name].setdefault(key, []).append(value)
    first = next(iter(trees))
    print('| TALOS, µs per configuration | ' + ' | '.join(trees) + ' | pinocchio '
          '| ours / pinocchio |\n|---|' + '---:|' * (len(trees) + 2))
    for key in ('fk', 'fk batch', 'gravity', 'gravity batch', 'jacobian', 'jacobian batch'):
        peer = found[first][f'pinocchio {key.split()[0]}']
        print(f'| {key} | ' + ' | '.join(_spread(found[name][key], 1) for name in trees)
              + f' | {_spread(peer, 1)} | '
              f'{statistics.median(found[first][key]) / statistics.median(peer):.1f}x |')


def main() -> None:
    """Run the three comparisons and print markdown tables."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--baseline', type=Path, action='append', default=[],
                        help='source tree of an older version (repeatable: the first is '
                             '"baseline", the others go by their folder\'s name)')
    parser.add_argument('--repeat', type=int, default=5)
    parser.add_argument('--only', choices=('statics', 'startup', 'kinematics'))
    arguments = parser.parse_args()
    trees = {'this tree': HERE}
    for number, tree in enumerate(arguments.baseline):
        trees['baseline' if number == 0 else tree.name] = tree.resolve()
    with tempfile.TemporaryDirectory() as folder:
        cache = Path(folder) / 'pycache'
        for part in (statics, startup, kinematics):
            if arguments.only in (None, part.__name__):
                print(f'\n### {part.__name__}\n')
                part(trees, cache, Path(folder), arguments.repeat)


if __name__ == '__main__':
    main()
