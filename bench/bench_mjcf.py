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
URDF to MuJoCo: time per robot and how many robots each converter loads.

Peers, in one process on the same files: MuJoCo's own URDF import (``MjModel.from_xml_path``
then ``mj_saveLastXML``), given the file as it is and given a copy whose mesh URIs are
absolute paths (it cannot open ``package://``); xacrodoc's ``to_mjcf_file`` (MuJoCo's
import behind its own package resolution); kscalelabs' urdf2mjcf; truerig. "Loads" means
the converter wrote a file and MuJoCo compiles it. Ours is timed twice: convert (read,
write MJCF and its meshes) and convert-and-verify (the same, then MuJoCo compiles it).

    URDFGENPY_CORPUS=<corpus> python bench/bench_mjcf.py --repeat 3 [--cold --fresh-mujoco --cpu]

Converted meshes are kept in a mesh cache (issue 41): this run uses a cache folder of its
own, empty at the start, so the first of the repeats converts and the others reuse;
``--cold`` gives each of our runs an empty cache (every mesh converted every time).
``--fresh-mujoco`` empties MuJoCo's own in-process mesh cache before every timed run of
every converter, as a new process starts: without it, MuJoCo's import reads the package's
mesh files at the same paths every run and compiles them from that cache after the first,
while our verify reads the files just written, at new paths, so never from it. ``--cpu``
times by the process's CPU time (a machine shared with other work), not the wall clock.

Robots: the registry robots of the test extra and, with the corpus, its URDF files that
check_urdf accepts.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import os
from pathlib import Path
import statistics
import sys
import tempfile
import time

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE.parent), str(HERE.parent / 'test')]

import registry_robots  # noqa: E402
from helpers import check_urdf_verdict, CORPUS, CORPUS_PACKAGES  # noqa: E402, I100
from timing import p90  # noqa: E402


def _robots() -> list[tuple[Path, list[Path]]]:
    found = [(path, registry_robots.search_paths()) for path in registry_robots.robots()]
    if CORPUS.is_dir():
        folders = sorted({(CORPUS / folder).parent for folder in CORPUS_PACKAGES.values()})
        found += [(path, folders) for path in sorted(CORPUS.rglob('*.urdf'))]
    return [(path, folders) for path, folders in found if check_urdf_verdict(path)]


@contextlib.contextmanager
def _silent():
    """Keep the peers' prints (and MuJoCo's C warnings) out of the report."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    with open(os.devnull, 'w') as null:
        os.dup2(null.fileno(), 1)
        os.dup2(null.fileno(), 2)
        try:
            with contextlib.redirect_stdout(io.StringIO()), \
                    contextlib.redirect_stderr(io.StringIO()):
                yield
        finally:
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])


def _compiles(path: Path) -> bool:
    import mujoco
    try:
        mujoco.MjModel.from_xml_path(str(path))
    except ValueError:
        return False
    return True


COLD = False  # --cold: each of our runs starts with an empty mesh cache
FRESH_MUJOCO = False  # --fresh-mujoco: MuJoCo's mesh cache emptied before every timed run
CLOCK = time.perf_counter  # --cpu: time.process_time (this process's CPU, on a shared machine)


def ours(source: Path, folders: list[Path], out: Path, verify: bool) -> bool:
    from urdfgenpy_ros.formats import load
    if COLD:
        _empty_cache(out)
    from urdfgenpy_ros.formats.mjcf import write_mjcf
    try:
        write_mjcf(load(source, {}, folders), out / 'robot.xml', search_paths=folders)
    except Exception:  # noqa: B902 - a refusal (a tensor MuJoCo refuses) counts as not loaded
        return False
    return _compiles(out / 'robot.xml') if verify else True


def _empty_cache(out: Path) -> None:
    """Point the mesh cache at an empty folder, this process's memory of it forgotten."""
    os.environ['URDFGENPY_CACHE_DIR'] = str(out / 'mesh-cache')
    try:
        from urdfgenpy_ros import mesh_cache
    except ImportError:  # a tree without the cache (6684634)
        return
    mesh_cache._memory.clear()


def mujoco_import(source: Path, folders: list[Path], out: Path, verify: bool) -> bool:
    import mujoco
    try:
        mujoco.MjModel.from_xml_path(str(source))
        mujoco.mj_saveLastXML(str(out / 'robot.xml'), mujoco.MjModel.from_xml_path(
            str(source)))
    except ValueError:
        return False
    return True


def mujoco_absolute(source: Path, folders: list[Path], out: Path, verify: bool) -> bool:
    copy = out / source.name
    copy.write_text(registry_robots.absolute_meshes(_expanded(source, folders), source.parent))
    return mujoco_import(copy, folders, out, verify)


def _expanded(source: Path, folders: list[Path]) -> str:
    from urdfgenpy_ros.formats import load
    robot = load(source, {}, folders)  # a Xacro .urdf (TurtleBot3's) expanded as ROS does
    if any(warning.code == 'X101' for warning in robot.read_warnings):
        return robot.to_urdf()
    return source.read_text()


def xacrodoc(source: Path, folders: list[Path], out: Path, verify: bool) -> bool:
    from xacrodoc import packages, XacroDoc
    packages.update_package_cache({folder.name: str(folder) for root in folders
                                   for folder in root.iterdir() if folder.is_dir()})
    XacroDoc.from_file(str(source)).to_mjcf_file(str(out / 'robot.xml'))
    return _compiles(out / 'robot.xml')


def urdf2mjcf(source: Path, folders: list[Path], out: Path, verify: bool) -> bool:
    from urdf2mjcf.convert import convert_urdf_to_mjcf
    convert_urdf_to_mjcf(source, out / 'robot.xml', copy_meshes=True)
    return _compiles(out / 'robot.xml')


def truerig(source: Path, folders: list[Path], out: Path, verify: bool) -> bool:
    import truerig as peer
    peer.convert(str(source), str(out / 'robot.xml'))
    return _compiles(out / 'robot.xml')


PEERS = (('urdfgenpy_ros convert', ours, False), ('urdfgenpy_ros convert+verify', ours, True),
         ('MuJoCo import, file as given', mujoco_import, False),
         ('MuJoCo import, meshes made absolute', mujoco_absolute, False),
         ('xacrodoc', xacrodoc, False), ('urdf2mjcf', urdf2mjcf, False),
         ('truerig', truerig, False))


def _time(function, source: Path, folders: list[Path], verify: bool,
          repeat: int) -> float | None:
    times = []
    for _ in range(repeat):
        with tempfile.TemporaryDirectory() as folder:
            if FRESH_MUJOCO:
                import mujoco
                mujoco.mj_clearCache(mujoco.mj_getCache())
            start = CLOCK()
            try:
                with _silent():
                    loaded = function(source, folders, Path(folder), verify)
            except Exception:  # noqa: B902 - a peer failing on a robot is a result
                loaded = False
            times.append(CLOCK() - start)
        if not loaded:
            return None
    return statistics.median(times)


def main() -> None:
    """Time every peer on every robot; print a Markdown table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=3)
    parser.add_argument('--cold', action='store_true',
                        help='an empty mesh cache for each of our runs')
    parser.add_argument('--fresh-mujoco', action='store_true',
                        help="MuJoCo's in-process mesh cache emptied before every timed run")
    parser.add_argument('--cpu', action='store_true',
                        help="time by this process's CPU time, not the wall clock")
    arguments = parser.parse_args()
    global COLD, FRESH_MUJOCO, CLOCK
    COLD, FRESH_MUJOCO = arguments.cold, arguments.fresh_mujoco
    CLOCK = time.process_time if arguments.cpu else time.perf_counter
    cache = tempfile.mkdtemp(prefix='mesh-cache-')
    os.environ.setdefault('URDFGENPY_CACHE_DIR', cache)
    robots = _robots()
    times: dict[str, dict[str, float]] = {name: {} for name, _, _ in PEERS}
    for source, folders in robots:
        for name, function, verify in PEERS:
            seconds = _time(function, source, folders, verify, arguments.repeat)
            if seconds is not None:
                times[name][str(source)] = seconds
        print(f'{source.name}: ' + ', '.join(
            f'{name} {times[name].get(str(source), float("nan")) * 1000:.0f} ms'
            for name, _, _ in PEERS), file=sys.stderr)
    reference = times['MuJoCo import, meshes made absolute']
    print(f'{len(robots)} robots check_urdf accepts, median of {arguments.repeat} runs each\n')
    print('| converter | robots loaded | median ms | p90 ms | vs MuJoCo import (median) '
          '| vs MuJoCo import (p90) |')
    print('|---|---:|---:|---:|---:|---:|')
    for name, _, _ in PEERS:
        mine = times[name]
        if not mine:
            print(f'| {name} | 0 of {len(robots)} | | | | |')
            continue
        ratios = [mine[robot] / reference[robot] for robot in mine if robot in reference]
        values = list(mine.values())
        ratio = (f'{statistics.median(ratios):.2f}x | {p90(ratios):.2f}x' if ratios
                 else ' | ')
        print(f'| {name} | {len(mine)} of {len(robots)} | {statistics.median(values) * 1000:.0f}'
              f' | {p90(values) * 1000:.0f} | {ratio} |')


if __name__ == '__main__':
    main()
