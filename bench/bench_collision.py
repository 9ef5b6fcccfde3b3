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
Collision geometry made light: time per face, a run from the cache, obj2mjcf beside it.

    python bench/bench_collision.py --repeat 3

Meshes: the test fixtures (a U bracket, an L beam, a gripper finger, a cylinder-like link,
a dense torus of 20,000 faces) and the collision meshes of gym-ignition's Panda (a
registry robot of the test extra; roboplan's SO-101 CAD meshes take CoACD minutes each).
Each timed run of ours reads the robot, makes every collision mesh light, measures it and
writes the meshes, with an empty cache (a fresh folder each run); "cached" is the same run
again over a filled cache. obj2mjcf (PyPI) runs in the same run on the same meshes written
as OBJ files (not timed), as its command line: ``--decompose`` (CoACD, as our decompose)
and without it (its plain processing);
its start-up (``--help``) is timed apart and given beside it.
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path
import shutil
import subprocess
import sys
import tempfile

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE.parent), str(HERE.parent / 'test')]

import collision_fixtures  # noqa: E402
import registry_robots  # noqa: E402, I100
from timing import median_seconds  # noqa: E402, I100
import trimesh  # noqa: E402, I100

from urdfgenpy_ros.formats import load  # noqa: E402, I100
from urdfgenpy_ros.model.geometry import Mesh  # noqa: E402
from urdfgenpy_ros.resources import PackageResolver  # noqa: E402

METHODS = ('hull', 'decompose', 'primitive', 'decimate')


def _robots(folder: Path) -> list[Path]:
    """Return the benchmark robots: the fixtures' and two registry robots."""
    shapes = dict(collision_fixtures.SHAPES, torus=collision_fixtures.dense_torus)
    for name, make in shapes.items():
        make().export(folder / f'{name}.stl')
    fixtures = folder / 'fixtures.urdf'
    fixtures.write_text(collision_fixtures.robot_text({name: f'{name}.stl' for name in shapes}))
    wanted = ('panda.urdf',)
    return [fixtures, *[path for path in registry_robots.robots() if path.name in wanted]]


def _meshes(robots: list[Path]) -> list[Path]:
    """Return every collision mesh file of the robots, once each."""
    found: dict[Path, None] = {}
    for path in robots:
        robot = load(path, {}, registry_robots.search_paths())
        resolver = PackageResolver(registry_robots.search_paths())
        for link in robot.links:
            for item in link.collisions:
                if isinstance(item.geometry, Mesh):
                    found[resolver.resolve(item.geometry.filename, path.parent)] = None
    return list(found)


def _ours(robots: list[Path], method: str, cache: Path | None) -> None:
    """Make every robot's collisions light once (a fresh cache unless ``cache``)."""
    os.environ['URDFGENPY_CACHE_DIR'] = str(cache or tempfile.mkdtemp())
    with tempfile.TemporaryDirectory() as out:
        for number, path in enumerate(robots):
            robot = load(path, {}, registry_robots.search_paths())
            robot.simplify_collisions(method, mesh_folder=Path(out) / str(number),
                                      search_paths=registry_robots.search_paths())
    if cache is None:
        shutil.rmtree(os.environ['URDFGENPY_CACHE_DIR'])


def _obj2mjcf(folder: Path, *flags: str) -> None:
    command = [str(Path(sys.executable).parent / 'obj2mjcf'), '--obj-dir', str(folder),
               '--overwrite', *flags]
    subprocess.run(command, check=True, capture_output=True)


def main() -> None:
    """Print the table of times (medians of ``--repeat`` runs)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=3)
    repeat = parser.parse_args().repeat
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        robots = _robots(folder)
        meshes = _meshes(robots)
        faces = 0
        objs = folder / 'obj'
        objs.mkdir()
        for number, path in enumerate(meshes):
            mesh = trimesh.load(str(path), force='mesh')
            faces += len(mesh.faces)
            mesh.export(objs / f'mesh{number}.obj')
        print(f'{len(meshes)} meshes, {faces} faces, {len(robots)} robots, median of {repeat}')
        print('| method | ours, s | per 1,000 faces, ms | cached, s | cached / first |')
        print('|---|---|---|---|---|')
        for method in METHODS:
            first = median_seconds(lambda: _ours(robots, method, None), repeat)
            cache = Path(tempfile.mkdtemp())
            _ours(robots, method, cache)
            cached = median_seconds(lambda: _ours(robots, method, cache), repeat)
            shutil.rmtree(cache)
            print(f'| {method} | {first:.2f} | {1e6 * first / faces:.1f} | {cached:.2f} | '
                  f'{cached / first:.3f} |')
        start = median_seconds(lambda: subprocess.run(
            [str(Path(sys.executable).parent / 'obj2mjcf'), '--help'], capture_output=True),
            repeat)
        plain = median_seconds(lambda: _obj2mjcf(objs), repeat)
        decomposed = median_seconds(lambda: _obj2mjcf(objs, '--decompose'), repeat)
        print(f'| obj2mjcf (no decompose) | {plain:.2f} | {1e6 * plain / faces:.1f} | | |')
        print(f'| obj2mjcf --decompose | {decomposed:.2f} | {1e6 * decomposed / faces:.1f} '
              '| | |')
        print(f'obj2mjcf start-up (--help): {start:.2f} s, included in its rows')


if __name__ == '__main__':
    main()
