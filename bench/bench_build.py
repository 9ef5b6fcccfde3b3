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
each library, shape and size the script reports the median wall times of building and of
writing over several interleaved runs (each round runs every library once) and the peak
Python memory of one build + write (tracemalloc).

    python bench/bench_build.py [--repeat 7] [--json out.json]
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
import functools
import gc
import importlib
import json
import os
import statistics
import time
import tracemalloc
from typing import Any


def _parent(shape: str, index: int) -> int:
    return index - 1 if shape == 'chain' else 0


def seed_build(library: str, count: int, shape: str) -> Any:
    """Build with the seeds' API, which urdfgenpy_ros and urdfgenpy 0.4.0 share."""
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
    return robot


def yourdfpy_build(count: int, shape: str) -> Any:
    """Build with yourdfpy's dataclasses."""
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
    return y.URDF(y.Robot(name='bench', links=links, joints=joints),
                  build_scene_graph=False, load_meshes=False)


LIBRARIES: dict[str, tuple[Callable[[int, str], Any], Callable[[Any], str]]] = {
    'urdfgenpy_ros': (functools.partial(seed_build, 'urdfgenpy_ros'),
                      lambda robot: robot.to_urdf()),
    'urdfgenpy 0.4.0': (functools.partial(seed_build, 'urdfgenpy'),
                        lambda robot: robot.to_urdf()),
    'yourdfpy': (yourdfpy_build, lambda urdf: urdf.write_xml_string().decode()),
    # no checks, one f-string per element: what CPython alone costs (floor_model.py)
    'floor (no checks)': (functools.partial(seed_build, 'floor_model'),
                          lambda robot: robot.to_urdf())}


def _once(library: tuple[Callable[[int, str], Any], Callable[[Any], str]], count: int,
          shape: str) -> tuple[float, float]:
    """Return the seconds of one build and of writing what it built."""
    build, write = library
    gc.collect()
    start = time.perf_counter()
    model = build(count, shape)
    built = time.perf_counter()
    write(model)
    return built - start, time.perf_counter() - built


def measure(count: int, shape: str, repeat: int) -> dict[str, tuple[float, float, float]]:
    """
    Return, per library, the median build and write seconds and the peak MiB.

    The runs are interleaved (each round runs every library once), so that the load of a
    shared machine falls on all of them alike; the peak memory of build + write comes
    from one more run each, under tracemalloc.
    """
    for build, write in LIBRARIES.values():
        write(build(10, shape))  # warm up imports
    times: dict[str, list[tuple[float, float]]] = {name: [] for name in LIBRARIES}
    for _ in range(repeat):
        for name, library in LIBRARIES.items():
            times[name].append(_once(library, count, shape))
    figures = {}
    for name, (build, write) in LIBRARIES.items():
        gc.collect()
        tracemalloc.start()
        write(build(count, shape))
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        runs = times[name]
        figures[name] = (statistics.median(b for b, _ in runs),
                         statistics.median(w for _, w in runs),
                         peak / 2 ** 20)
    return figures


def _load() -> str:
    """Return the machine's load averages, which the figures depend on."""
    return ' '.join(f'{load:.2f}' for load in os.getloadavg())


def main() -> None:
    """Run the comparison and print a Markdown table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=7)
    parser.add_argument('--sizes', type=int, nargs='+', default=[10, 100, 1000, 10000])
    parser.add_argument('--json', help='also write the figures to this file')
    args = parser.parse_args()
    rows = []
    print(f'load average at the start: {_load()} (1, 5, 15 min)')
    print('| shape | links | library | median build (ms) | median write (ms) | build+write (ms) |'
          ' us/link | peak MiB | vs urdfgenpy 0.4.0 |')
    print('|---|---:|---|---:|---:|---:|---:|---:|---:|')
    for shape in ('chain', 'wide'):
        for count in args.sizes:
            figures = measure(count, shape, args.repeat)
            base = sum(figures['urdfgenpy 0.4.0'][:2])
            for name, (build, write, peak) in figures.items():
                seconds = build + write
                rows.append({'shape': shape, 'links': count, 'library': name,
                             'build_seconds': build, 'write_seconds': write,
                             'seconds': seconds, 'peak_mib': peak})
                print(f'| {shape} | {count} | {name} | {build * 1e3:.1f} | {write * 1e3:.1f} | '
                      f'{seconds * 1e3:.1f} | {seconds / count * 1e6:.1f} | {peak:.1f} | '
                      f'{base / seconds:.2f}x |')
    print(f'load average at the end: {_load()}')
    if args.json:
        with open(args.json, 'w', encoding='utf-8') as stream:
            json.dump(rows, stream, indent=1)


if __name__ == '__main__':
    main()
