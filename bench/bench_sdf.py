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
URDF to SDF: time per robot, ours against libsdformat's own URDF conversion.

Ours: read the URDF, then ``to_sdf(lump_fixed=True)`` (the frames, ``<gazebo>`` settings and
losses included), in this process. The peer: Debian's libsdformat 12 reading the same URDF
(its conversion) and printing the SDF, as test/sdf_checker/check_sdf.cc does, in a process
of its own; its start-up is measured apart (on an empty model) and subtracted.

    URDFGENPY_CORPUS=/path/to/corpus python bench/bench_sdf.py --repeat 5

Robots: the registry robots of the test extra and, with the corpus, its URDF files
libsdformat converts.
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path
import statistics
import subprocess
import sys
import tempfile
import warnings

from timing import median_seconds, p90

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / 'test'))


def _checker(folder: Path) -> Path:
    flags = subprocess.run(['pkg-config', '--cflags', '--libs', 'sdformat12'],
                           capture_output=True, text=True, check=True).stdout.split()
    binary = folder / 'check_sdf'
    subprocess.run(['g++', '-O1', '-o', str(binary),
                    str(REPO / 'test' / 'sdf_checker' / 'check_sdf.cc'), *flags], check=True)
    return binary


def _robots() -> list[Path]:
    from registry_robots import robots
    files = [path for path in robots() if path.suffix == '.urdf']
    corpus = os.environ.get('URDFGENPY_CORPUS')
    if corpus:
        files.extend(sorted(Path(corpus).rglob('*.urdf')))
    return files


def main() -> None:
    """Time both converters on every robot both convert; print the table's numbers."""
    parser = argparse.ArgumentParser()
    parser.add_argument('--repeat', type=int, default=5)
    repeat = parser.parse_args().repeat
    from urdfgenpy_ros import Robot
    warnings.simplefilter('ignore')
    with tempfile.TemporaryDirectory() as folder:
        binary = _checker(Path(folder))
        empty = Path(folder) / 'empty.urdf'
        empty.write_text('<robot name="e"><link name="a"><inertial><mass value="1"/><inertia '
                         'ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>'
                         '</robot>')
        start = median_seconds(lambda: subprocess.run([str(binary), '--sdf', str(empty)],
                                                      capture_output=True), repeat)
        ours, theirs, ratios = [], [], []
        for path in _robots():
            if subprocess.run([str(binary), '--sdf', str(path)],
                              capture_output=True).returncode != 0:
                continue
            try:
                Robot.from_urdf(path).to_sdf(lump_fixed=True, version='1.9')
            except Exception:  # noqa: B902 - not a robot we convert: left out of both
                continue
            mine = median_seconds(lambda: Robot.from_urdf(path).to_sdf(
                lump_fixed=True, version='1.9'), repeat)
            peer = max(median_seconds(lambda: subprocess.run(
                [str(binary), '--sdf', str(path)], capture_output=True), repeat) - start, 1e-4)
            ours.append(mine)
            theirs.append(peer)
            ratios.append(mine / peer)
    print(f'{len(ours)} robots; libsdformat start-up {start * 1e3:.0f} ms (subtracted)')
    for name, values in (('ours', ours), ('libsdformat', theirs)):
        print(f'{name}: median {statistics.median(values) * 1e3:.1f} ms, '
              f'p90 {p90(values) * 1e3:.1f} ms')
    print(f'ours / libsdformat: median {statistics.median(ratios):.2f}x, '
          f'p90 {p90(ratios):.2f}x')


if __name__ == '__main__':
    main()
