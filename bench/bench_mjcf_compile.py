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
What MuJoCo's compile of our written MJCF costs, robot by robot, against its own import.

Each robot's MJCF is written once, then, MuJoCo's in-process mesh cache emptied before
every compile (as a new process starts): the compile of the file written (what
bench_mjcf.py's "verify" times), MuJoCo's own timers for it (load, BVH, ..., from its
compile-time log, in a process of its own), the same file without visual geoms and the
meshes only they use, a prototype with every mesh rewritten as MuJoCo's binary MSH (the
compiled models compared field by field), MuJoCo's URDF import (one compile, meshes made
absolute as bench_mjcf.py does) and the same import told to keep
visuals (``<compiler discardvisual="false"/>``). CPU milliseconds, medians of --repeat.

    URDFGENPY_CORPUS=<corpus> python bench/bench_mjcf_compile.py --repeat 5 [--robot cookie.urdf]
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path
import re
import shutil
import statistics
import struct
import subprocess
import sys
import tempfile
import time

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE), str(HERE.parent), str(HERE.parent / 'test')]

import bench_mjcf  # noqa: E402
import registry_robots  # noqa: E402, I100

ROBOTS = ('cookie.urdf', 'upkie.urdf', 'upkie_camera.urdf', 'icub_simple_collisions.urdf',
          '/fr3.urdf', 'gym_ignition_models/panda/panda.urdf', 'ur5_gripper.urdf',
          'racecar.urdf', 'iCubGazeboV2_5/icub.urdf')
TIMERS = ('load', 'hull', 'polygon', 'inertia', 'bvh', 'other')
LOG = r"""
import mujoco, sys
config = mujoco.MjLogConfig.get()
config.topics, config.logto_file = 6, False
config.set()
for _ in range(int(sys.argv[2])):
    mujoco.mj_clearCache(mujoco.mj_getCache())
    mujoco.MjModel.from_xml_path(sys.argv[1])
"""


def cold_cpu(path: Path, repeat: int) -> float:
    """Return the median CPU ms of MuJoCo compiling ``path``, its mesh cache emptied."""
    import mujoco
    times = []
    for _ in range(repeat):
        mujoco.mj_clearCache(mujoco.mj_getCache())
        start = time.process_time()
        mujoco.MjModel.from_xml_path(str(path))
        times.append(time.process_time() - start)
    return statistics.median(times) * 1000


def timers(path: Path, repeat: int) -> dict[str, float]:
    """Return MuJoCo's own compile timers for ``path`` (ms, medians), from its log."""
    run = subprocess.run([sys.executable, '-c', LOG, str(path), str(repeat)],
                         capture_output=True, text=True, check=True)
    found: dict[str, list[float]] = {}
    for name, value in re.findall(r'^\s+(\w+):\s+([\d.]+)', run.stdout + run.stderr, re.M):
        found.setdefault(name, []).append(float(value))
    return {name: statistics.median(values) for name, values in found.items()}


def without_visuals(path: Path) -> Path:
    """Write ``path`` without its visual geoms and the meshes only they use; return it."""
    from lxml import etree
    document = etree.parse(str(path))
    for geom in document.xpath('//geom[@class="visual"]'):
        geom.getparent().remove(geom)
    used = {geom.get('mesh') for geom in document.iter('geom')}
    for mesh in document.xpath('/mujoco/asset/mesh'):
        if mesh.get('name') not in used:
            mesh.getparent().remove(mesh)
    target = path.with_name('without_visuals.xml')
    document.write(str(target))
    return target


def _stl_arrays(data: bytes) -> tuple:
    """Return a binary STL's corners merged as MuJoCo's reader merges them, and its faces."""
    import numpy
    count = int.from_bytes(data[80:84], 'little')
    record = numpy.dtype([('normal', '<f4', 3), ('corners', '<f4', (3, 3)), ('extra', '<u2')])
    corners = numpy.frombuffer(data, record, count, 84)['corners'].reshape(-1, 3)
    _, first, inverse = numpy.unique(corners.view([('', corners.dtype)] * 3).ravel(),
                                     return_index=True, return_inverse=True)
    order = numpy.argsort(first)  # numbered in the order they first appear
    rank = numpy.empty_like(order)
    rank[order] = numpy.arange(len(order))
    return corners[first[order]], rank[inverse].reshape(-1, 3)


def _obj_arrays(data: bytes) -> tuple | None:
    """Return an OBJ's vertices and faces; None unless it is bare triangles (ours)."""
    import numpy
    vertices, faces = [], []
    for line in data.decode('ascii', 'replace').splitlines():
        kind, *values = line.split() or ['#']
        if kind == 'v' and len(values) == 3:
            vertices.append([float(value) for value in values])
        elif kind == 'f' and len(values) == 3 and '/' not in line:
            faces.append([int(value) - 1 for value in values])
        elif kind != '#':
            return None
    return numpy.asarray(vertices, numpy.float32), numpy.asarray(faces)


def as_msh(path: Path) -> Path:
    """Copy ``path``'s folder with every mesh it can rewritten as MSH; return the copy."""
    import numpy
    from lxml import etree
    target = path.parent.with_name(path.parent.name + '-msh')
    shutil.copytree(path.parent, target)
    document = etree.parse(str(target / path.name))
    folder = target / (document.find('compiler').get('meshdir') or '')
    for mesh in document.xpath('/mujoco/asset/mesh[@file]'):
        file = folder / mesh.get('file')
        data = file.read_bytes()
        arrays = _stl_arrays(data) if file.suffix.lower() == '.stl' else _obj_arrays(data)
        if arrays is None:
            continue
        vertices, faces = arrays
        file.unlink()
        file.with_suffix('.msh').write_bytes(
            struct.pack('<4i', len(vertices), 0, 0, len(faces)) +
            numpy.asarray(vertices, '<f4').tobytes() + numpy.asarray(faces, '<i4').tobytes())
        mesh.set('file', file.with_suffix('.msh').name)
    document.write(str(target / path.name))
    return target / path.name


FIELDS = ('nbody', 'ngeom', 'nmesh', 'nmeshvert', 'nmeshface')
ARRAYS = ('mesh_vert', 'mesh_face', 'mesh_normal', 'mesh_pos', 'mesh_quat', 'body_mass',
          'body_inertia', 'body_ipos', 'body_iquat', 'geom_size', 'geom_pos', 'geom_quat',
          'geom_aabb', 'geom_rbound')


def differences(first: Path, second: Path) -> list[str]:
    """Return the fields in which MuJoCo's models of the two files differ (bit for bit)."""
    import mujoco
    import numpy
    one, two = (mujoco.MjModel.from_xml_path(str(path)) for path in (first, second))
    return [name for name in FIELDS if getattr(one, name) != getattr(two, name)] + [
        name for name in ARRAYS if not numpy.array_equal(getattr(one, name), getattr(two, name))]


def mujoco_imports(source: Path, folders: list[Path], work: Path, repeat: int
                   ) -> tuple[float | None, float | None]:
    """Return MuJoCo's URDF import (one compile), and keeping visuals; None: it refuses."""
    text = registry_robots.absolute_meshes(bench_mjcf._expanded(source, folders),
                                           source.parent)
    kept = re.sub(r'(<robot[^>]*>)', r'\1<mujoco><compiler discardvisual="false"/></mujoco>',
                  text, count=1)
    found: list[float | None] = []
    for name, content in (('import.urdf', text), ('import_visual.urdf', kept)):
        (work / name).write_text(content)
        try:
            found.append(cold_cpu(work / name, repeat))
        except ValueError:
            found.append(None)
    return found[0], found[1]


def measure(source: Path, folders: list[Path], repeat: int) -> str:
    """Return the Markdown row of one robot."""
    import mujoco
    work = Path(tempfile.mkdtemp(prefix='compile-'))
    try:
        written = work / 'ours' / 'robot.xml'
        bench_mjcf.ours(source, folders, written.parent, False)
        model = mujoco.MjModel.from_xml_path(str(written))
        clock = timers(written, repeat)
        msh = as_msh(written)
        same = differences(written, msh)
        plain, visual = mujoco_imports(source, folders, work, repeat)
        cells = [f'{model.nmesh} / {model.nmeshface:,}', f'{cold_cpu(written, repeat):.0f}',
                 *(f'{clock.get(name, 0.0):.0f}' for name in TIMERS),
                 f'{cold_cpu(without_visuals(written), repeat):.1f}',
                 f'{cold_cpu(msh, repeat):.0f}' + ('' if not same else ' (' + ', '.join(same)
                                                   + ' differ)'),
                 f'{plain:.1f}' if plain is not None else 'refused',
                 f'{visual:.0f}' if visual is not None else 'refused']
        return f'| {source.name} | ' + ' | '.join(cells) + ' |'
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main() -> None:
    """Print one Markdown row per robot."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=5)
    parser.add_argument('--robot', action='append', help='the end of a robot file path')
    arguments = parser.parse_args()
    os.environ.setdefault('URDFGENPY_CACHE_DIR', tempfile.mkdtemp(prefix='mesh-cache-'))
    robots = bench_mjcf._robots()
    print('| robot | meshes / faces | compile | ' + ' | '.join(TIMERS) + ' | without visual '
          'meshes | as MSH | MuJoCo import | MuJoCo import keeping visuals |')
    print('|---|---|' + '---:|' * (len(TIMERS) + 5))
    for ending in arguments.robot or ROBOTS:
        for source, folders in robots:
            if str(source).endswith(ending):
                print(measure(source, folders, arguments.repeat), flush=True)
                break


if __name__ == '__main__':
    main()
