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
Read and write every corpus URDF with our reader and its peers, side by side.

Readers: ``Robot.from_urdf_string``, ``yourdfpy.URDF.load`` (no meshes, no scene
graph), ``urdf_parser_py`` (PyPI ``urdfdom-py``) and a bare ``lxml.etree.fromstring``
(the floor). Writers: ``Robot.to_urdf``, ``urdf_parser_py``'s ``to_xml_string`` and
``lxml.etree.tostring`` of the parsed tree (the floor). Everything works from bytes in
memory; each figure is the median of ``--repeat`` runs.

    python bench/bench_read.py [--corpus DIR] [--repeat 7] [--per-file]
"""

from __future__ import annotations

import argparse
import gc
import io
import os
from pathlib import Path
import re
import shutil
import subprocess
import tracemalloc
from typing import Any, Callable

from timing import median_seconds


def _readers() -> dict[str, Callable[[bytes], Any]]:
    from lxml import etree
    from urdf_parser_py.urdf import URDF as Parsed
    import yourdfpy

    from urdfgenpy_ros import Robot

    return {
        'lxml parse (floor)': lambda data: etree.fromstring(data),
        'urdfgenpy_ros': lambda data: Robot.from_urdf_string(data),
        'yourdfpy': lambda data: yourdfpy.URDF.load(
            io.BytesIO(data), load_meshes=False, build_scene_graph=False,
            build_collision_scene_graph=False),
        'urdf_parser_py': lambda data: Parsed.from_xml_string(data),
    }


def _quiet(function: Callable[[bytes], Any]) -> Callable[[bytes], Any]:
    import contextlib
    import logging
    import os

    def run(data: bytes) -> Any:
        logging.disable(logging.CRITICAL)
        with open(os.devnull, 'w') as sink, contextlib.redirect_stderr(sink):
            try:
                return function(data)
            finally:
                logging.disable(logging.NOTSET)
    return run


def corpus_files(corpus: Path) -> list[Path]:
    """Return the corpus URDFs that Debian's check_urdf accepts (all if it is absent)."""
    files = sorted(corpus.rglob('*.urdf'))
    if shutil.which('check_urdf') is None:
        return files
    return [path for path in files
            if subprocess.run(['check_urdf', str(path)], capture_output=True,
                              timeout=30).returncode == 0]


def main() -> None:
    """Print per-library totals (and per-file figures on request)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--corpus', type=Path, required='URDFGENPY_CORPUS' not in os.environ,
                        default=os.environ.get('URDFGENPY_CORPUS'),
                        help='a folder of robots (default: $URDFGENPY_CORPUS)')
    parser.add_argument('--repeat', type=int, default=7)
    parser.add_argument('--per-file', action='store_true')
    args = parser.parse_args()
    from lxml import etree

    from urdfgenpy_ros import Robot

    files = corpus_files(args.corpus)
    data = {path: re.sub(rb'^\s*<\?xml[^>]*\?>', b'', path.read_bytes()) for path in files}
    readers = {name: _quiet(function) for name, function in _readers().items()}
    usable = []
    for path in files:
        failing = []
        for name, function in readers.items():
            try:
                function(data[path])
            except Exception as error:  # noqa: B902 - a peer failing excludes the file
                failing.append(f'{name} ({type(error).__name__})')
        if failing:
            print(f'left out {path.relative_to(args.corpus)}: {", ".join(failing)} failed')
        else:
            usable.append(path)
    totals = dict.fromkeys(readers, 0.0)
    rows = []
    for path in usable:
        figures = {name: median_seconds(lambda: function(data[path]), args.repeat)
                   for name, function in readers.items()}
        for name, seconds in figures.items():
            totals[name] += seconds
        rows.append((path, figures))
    floor = totals['lxml parse (floor)']
    print(f'## Reading {len(usable)} corpus URDFs (median of {args.repeat})\n')
    print('| reader | total ms | x lxml parse |\n|---|---:|---:|')
    for name, seconds in totals.items():
        print(f'| {name} | {seconds * 1e3:.2f} | {seconds / floor:.1f}x |')
    if args.per_file:
        print('\n| file | ' + ' | '.join(readers) + ' |\n|---|' + '---:|' * len(readers))
        for path, figures in rows:
            cells = ' | '.join(f'{figures[name] * 1e3:.3f}' for name in readers)
            print(f'| {path.relative_to(args.corpus)} | {cells} |')

    robots = {path: Robot.from_urdf_string(data[path]) for path in usable}
    trees = {path: etree.fromstring(data[path]) for path in usable}
    from urdf_parser_py.urdf import URDF as Parsed
    parsed = {path: _quiet(Parsed.from_xml_string)(data[path]) for path in usable}
    writers = {
        'lxml tostring (floor)': lambda: [etree.tostring(tree) for tree in trees.values()],
        'urdfgenpy_ros': lambda: [robot.to_urdf() for robot in robots.values()],
        'urdf_parser_py': lambda: [model.to_xml_string() for model in parsed.values()],
    }
    written = {name: median_seconds(function, args.repeat) for name, function in writers.items()}
    floor = written['lxml tostring (floor)']
    print(f'\n## Writing the same {len(usable)} robots\n')
    print('| writer | total ms | x lxml tostring |\n|---|---:|---:|')
    for name, seconds in written.items():
        print(f'| {name} | {seconds * 1e3:.2f} | {seconds / floor:.1f}x |')

    links = sum(len(robot.links) for robot in robots.values())
    gc.collect()
    tracemalloc.start()
    kept = [Robot.from_urdf_string(data[path]) for path in usable]
    current = tracemalloc.get_traced_memory()[0]
    tracemalloc.stop()
    print(f'\nMemory held by the {len(kept)} read robots: {current / 2 ** 20:.2f} MiB for '
          f'{links} links = {current / links / 1024:.1f} KiB per link (tracemalloc; the '
          'lxml source trees kept for lossless writing are C memory it does not see).')


if __name__ == '__main__':
    main()
