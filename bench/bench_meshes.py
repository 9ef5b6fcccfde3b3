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
Meshes converted once: `mirror`, `init --fix` and `convert` of a 20-mesh arm, as processes.

The arm: example-robot-data's Panda (ten coloured DAE visuals and ten STL collisions, as a
left arm with ``left_`` names) written to a temporary folder. Each command runs as a
process, timed by the wall clock, for each code tree given (``--code DIR``: the package
at that folder on PYTHONPATH; e.g. 6684634 installed beside), with an empty mesh cache
(cold: every run its own cache folder) and with the cache a first run filled (warm).
Medians of ``--repeat`` runs, and the spread (min-max); the CPU seconds the process used
(user + system) say what it costs on a machine others share.

    python bench/bench_meshes.py --repeat 5 --code /work/base-6684634 --code .
"""

from __future__ import annotations

import argparse
from importlib import metadata
import os
from pathlib import Path
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

PANDA = ('link0', 'link1', 'link2', 'link3', 'link4', 'link5', 'link6', 'link7', 'hand',
         'finger')


def write_arm(folder: Path) -> Path:
    """Write the 20-mesh arm (a package ``arm_description``) in ``folder``; return its URDF."""
    share = Path(str(metadata.distribution('example-robot-data').locate_file(
        'cmeel.prefix/share/example-robot-data/robots/panda_description')))
    package = folder / 'arm_description'
    for kind, suffix in (('visual', 'dae'), ('collision', 'stl')):
        (package / 'meshes' / kind).mkdir(parents=True, exist_ok=True)
        for name in PANDA:
            shutil.copy(share / 'meshes' / kind / f'{name}.{suffix}',
                        package / 'meshes' / kind / f'{name}.{suffix}')
    (package / 'package.xml').write_text(
        '<package format="3"><name>arm_description</name><version>0.0.0</version>'
        '<description>arm</description><maintainer email="a@b.c">a</maintainer>'
        '<license>BSD</license></package>\n')
    links, joints, parent = [], [], 'base_link'
    for number, name in enumerate(PANDA):
        mesh = 'package://arm_description/meshes/{}/' + name + '.{}'
        links.append(
            f'<link name="left_{name}"><inertial><mass value="1"/><inertia ixx="0.01" '
            'ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>'
            f'<visual><geometry><mesh filename="{mesh.format("visual", "dae")}"/></geometry>'
            f'</visual><collision><geometry><mesh filename="{mesh.format("collision", "stl")}"'
            '/></geometry></collision></link>')
        joints.append(
            f'<joint name="left_joint{number}" type="revolute"><parent link="{parent}"/>'
            f'<child link="left_{name}"/><origin xyz="0 {0.3 if not number else 0} 0.1"/>'
            '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="10" velocity="1"/>'
            '</joint>')
        parent = f'left_{name}'
    urdf = package / 'urdf' / 'arm.urdf'
    urdf.parent.mkdir()
    urdf.write_text('<robot name="arm"><link name="base_link"><inertial><mass value="1"/>'
                    '<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>'
                    '</inertial></link>' + ''.join(links) + ''.join(joints) + '</robot>\n')
    return urdf


COMMANDS = {
    'mirror': lambda urdf, out: ['mirror', str(urdf), '--root', 'left_link0', '-o',
                                 str(out / 'both.urdf'), '-p', str(urdf.parents[2])],
    'init --fix': lambda urdf, out: ['init', 'arm_copy_description', '--from', str(urdf),
                                     '--fix', '--destination-directory', str(out),
                                     '--package-path', str(urdf.parents[2])],
    'convert (MJCF)': lambda urdf, out: ['convert', str(urdf), str(out / 'arm.xml'),
                                         '-p', str(urdf.parents[2])],
}


def run(code: Path, command: list[str], cache: Path, folder: Path) -> tuple[float, float]:
    """Return the wall and CPU seconds of one ``urdfgenpy`` process, the package at ``code``."""
    environment = dict(os.environ, PYTHONPATH=str(code), URDFGENPY_CACHE_DIR=str(cache))
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, '-c', 'import sys; sys.argv[0] = "urdfgenpy"; '
                           'from urdfgenpy_ros.cli import main; main()', *command],
                          cwd=folder, env=environment, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise SystemExit(f'{code}: urdfgenpy {" ".join(command)} failed:\n{done.stderr}')
    return seconds, (after.ru_utime - used.ru_utime) + (after.ru_stime - used.ru_stime)


def main() -> None:
    """Time each command on the arm for each code tree; print a Markdown table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=5)
    parser.add_argument('--code', type=Path, action='append', required=True)
    arguments = parser.parse_args()
    print('| command | code | cache | median wall s | spread s | median CPU s |')
    print('|---|---|---|---:|---:|---:|')
    for name, make in COMMANDS.items():
        for code in arguments.code:
            for warm in (False, True):
                times, cpu = [], []
                with tempfile.TemporaryDirectory() as temporary:
                    root = Path(temporary)
                    urdf = write_arm(root / 'src')
                    cache = root / 'cache'
                    if warm:
                        run(code.resolve(), make(urdf, root / 'first'), cache, root)
                    for number in range(arguments.repeat):
                        out = root / f'run{number}'
                        out.mkdir()
                        use = cache if warm else root / f'cache{number}'
                        wall, spent = run(code.resolve(), make(urdf, out), use, root)
                        times.append(wall)
                        cpu.append(spent)
                        for made in (urdf.parent.parent / 'meshes' / 'visual').glob('*mirror*'):
                            made.unlink()  # mirror writes beside the originals
                        for made in (urdf.parent.parent / 'meshes' / 'collision').glob(
                                '*mirror*'):
                            made.unlink()
                print(f'| {name} | {code} | {"warm" if warm else "cold"} | '
                      f'{statistics.median(times):.2f} | {min(times):.2f}-{max(times):.2f} | '
                      f'{statistics.median(cpu):.2f} |',
                      flush=True)


if __name__ == '__main__':
    main()
