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
Build and write robots of 10 to 10,000 links with three libraries, side by side.

Each link has a box visual, a box collision and a box inertial; links hang from a
revolute joint with limits, as a chain or as a wide tree (every link on the root). For
each library, shape and size the script reports the median wall time of build + write
over several runs and the peak Python memory of one run (tracemalloc).

    python bench/bench_build.py [--repeat 7] [--json out.json]
"""

from __future__ import annotations

import argparse
import functools
import gc
import importlib
import json
import statistics
import time
import tracemalloc


def _parent(shape: str, index: int) -> int:
    return index - 1 if shape == 'chain' else 0


def seed_api(library: str, count: int, shape: str) -> str:
    """Build and write with the seeds' API, which urdfgenpy_ros and urdfgenpy 0.4.0 share."""
    m = importlib.import_module(library)
    robot = m.Robot('bench')
    for index in range(count):
        box = m.Box(0.1, 0.05, 0.2)
        origin = m.Origin.above(box)
        link = m.Link(f'link_{index}')
        link.add_visual(m.Visual(geometry=box, origin=origin))
        link.add_collision(m.Collision(geometry=box, origin=origin))
        link.set_inertial(m.Inertial.from_box(1.0, 0.1, 0.05, 0.2, origin=origin))
        robot.add_link(link)
        if index:
            robot.add_joint(m.Joint(f'joint_{index}', 'revolute',
                                    f'link_{_parent(shape, index)}', f'link_{index}',
                                    origin=m.Origin(xyz=(0, 0, 0.2)), axis=(0, 0, 1),
                                    limit=m.JointLimit(-1.57, 1.57, effort=10, velocity=1)))
    return robot.to_urdf()


def yourdfpy_(count: int, shape: str) -> str:
    """Build and write with yourdfpy's dataclasses and its XML writer."""
    import numpy
    import yourdfpy as y
    links, joints = [], []
    lifted = numpy.eye(4)
    lifted[2, 3] = 0.1
    moments = [1.0 * (0.05 ** 2 + 0.2 ** 2) / 12, 1.0 * (0.1 ** 2 + 0.2 ** 2) / 12,
               1.0 * (0.1 ** 2 + 0.05 ** 2) / 12]
    for index in range(count):
        geometry = y.Geometry(box=y.Box(size=numpy.array([0.1, 0.05, 0.2])))
        links.append(y.Link(
            name=f'link_{index}',
            inertial=y.Inertial(origin=lifted.copy(), mass=1.0,
                                inertia=numpy.diag(moments)),
            visuals=[y.Visual(origin=lifted.copy(), geometry=geometry)],
            collisions=[y.Collision(name=None, origin=lifted.copy(), geometry=geometry)]))
        if index:
            up = numpy.eye(4)
            up[2, 3] = 0.2
            joints.append(y.Joint(name=f'joint_{index}', type='revolute',
                                  parent=f'link_{_parent(shape, index)}',
                                  child=f'link_{index}', origin=up,
                                  axis=numpy.array([0.0, 0.0, 1.0]),
                                  limit=y.Limit(effort=10, velocity=1, lower=-1.57,
                                                upper=1.57)))
    urdf = y.URDF(y.Robot(name='bench', links=links, joints=joints),
                  build_scene_graph=False, load_meshes=False)
    return urdf.write_xml_string().decode()


LIBRARIES = {'urdfgenpy_ros': functools.partial(seed_api, 'urdfgenpy_ros'),
             'urdfgenpy 0.4.0': functools.partial(seed_api, 'urdfgenpy'),
             'yourdfpy': yourdfpy_}


def measure(function, count: int, shape: str, repeat: int) -> tuple[float, float]:
    """Return (median seconds, peak MiB) of build + write."""
    function(10, shape)  # warm up imports
    times = []
    for _ in range(repeat):
        gc.collect()
        start = time.perf_counter()
        function(count, shape)
        times.append(time.perf_counter() - start)
    gc.collect()
    tracemalloc.start()
    function(count, shape)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return statistics.median(times), peak / 2 ** 20


def main() -> None:
    """Run the comparison and print a Markdown table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=7)
    parser.add_argument('--sizes', type=int, nargs='+', default=[10, 100, 1000, 10000])
    parser.add_argument('--json', help='also write the figures to this file')
    args = parser.parse_args()
    rows = []
    print('| shape | links | library | median build+write (ms) | us/link | peak MiB |'
          ' vs urdfgenpy 0.4.0 |')
    print('|---|---:|---|---:|---:|---:|---:|')
    for shape in ('chain', 'wide'):
        for count in args.sizes:
            figures = {name: measure(function, count, shape, args.repeat)
                       for name, function in LIBRARIES.items()}
            base = figures['urdfgenpy 0.4.0'][0]
            for name, (seconds, peak) in figures.items():
                rows.append({'shape': shape, 'links': count, 'library': name,
                             'seconds': seconds, 'peak_mib': peak})
                print(f'| {shape} | {count} | {name} | {seconds * 1e3:.2f} | '
                      f'{seconds / count * 1e6:.1f} | {peak:.1f} | {base / seconds:.2f}x |')
    if args.json:
        with open(args.json, 'w', encoding='utf-8') as stream:
            json.dump(rows, stream, indent=1)


if __name__ == '__main__':
    main()
