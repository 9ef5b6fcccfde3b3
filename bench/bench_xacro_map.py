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
What the Xacro source map costs: xacro's expansion with and without it, same files, same run.

For each vendor description the tests read (the corpus' Xacro files with their arguments,
the registry's Franka and UR Xacro files), ``expand_xacro`` runs plain (the real xacro's
``process_file`` and ``toprettyxml``, nothing recorded) and with the map, alternately,
``--repeat`` times; each figure is a median. The budget is 1.3x.

    URDFGENPY_CORPUS=<corpus> python bench/bench_xacro_map.py [--repeat 9]
"""

from __future__ import annotations

import argparse
import gc
import os
from pathlib import Path
import statistics
import sys
import time
from typing import Any

_ROOT = Path(__file__).resolve().parent.parent
_CASES = [
    ('urdf_tutorial/urdf/08-macroed.urdf.xacro', {}),
    ('turtlebot3/turtlebot3_description/urdf/turtlebot3_waffle.urdf', {'namespace': 'tb3_0/'}),
    *[('ur_description/urdf/ur.urdf.xacro', {'name': 'ur', 'ur_type': kind})
      for kind in ('ur5e', 'ur10e', 'ur30')],
    ('husky/husky_description/urdf/husky.urdf.xacro', {'is_sim': 'true'}),
    ('kortex/kortex_description/robots/gen3.xacro', {'dof': '7', 'vision': 'true'}),
    ('kortex/kortex_description/robots/kinova.urdf.xacro',
     {'name': 'kinova', 'arm': 'gen3', 'dof': '7'}),
]


def _cases(corpus: Path) -> list[tuple[str, Path, dict[str, str]]]:
    cases = [(Path(name).name + ''.join(f' {k}:={v}' for k, v in mappings.items()),
              corpus / name, mappings) for name, mappings in _CASES if (corpus / name).exists()]
    sys.path.insert(0, str(_ROOT / 'test'))
    from registry_robots import robots
    cases += [(path.name, path, {}) for path in robots() if 'xmlns:xacro' in path.read_text()]
    return cases


def _time(function: Any) -> float:
    gc.collect()
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def main() -> None:
    """Print a Markdown table: per file the medians, plain and mapped, and their ratio."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--corpus', type=Path, default=Path(os.environ.get(
        'URDFGENPY_CORPUS', '/nonexistent')))
    parser.add_argument('--repeat', type=int, default=9)
    options = parser.parse_args()
    from urdfgenpy_ros.formats.xacro_read import expand_xacro
    from urdfgenpy_ros.resources import PackageResolver
    resolver = PackageResolver([options.corpus])
    print('| file | elements | xacro (ms) | xacro + map (ms) | ratio |')
    print('|---|---:|---:|---:|---:|')
    totals = [0.0, 0.0]
    for name, path, mappings in _cases(options.corpus):
        maps: list[Any] = []
        expand_xacro(path, mappings, resolver, maps=maps)  # warm: imports, file cache
        plain, mapped = [], []
        for _ in range(options.repeat):  # alternate, so that drift hits both alike
            plain.append(_time(lambda: expand_xacro(path, mappings, resolver)))
            mapped.append(_time(lambda: expand_xacro(path, mappings, resolver, maps=[])))
        one, two = statistics.median(plain), statistics.median(mapped)
        totals[0] += one
        totals[1] += two
        print(f'| {name} | {len(maps[0].lines)} | {one * 1e3:.1f} | {two * 1e3:.1f} '
              f'| {two / one:.2f}x |')
    print(f'| **all (sum of medians)** | | {totals[0] * 1e3:.1f} | {totals[1] * 1e3:.1f} '
          f'| **{totals[1] / totals[0]:.2f}x** |')


if __name__ == '__main__':
    main()
