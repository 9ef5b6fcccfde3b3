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
Pictures of a 60-link robot with meshes: ``render`` and the viewer's first paint.

The robot is made here: a torso with five chains of revolute joints; each link has an STL
visual (a 2,000-triangle capsule-like mesh, written to a temporary folder) with a colour,
and a box collision. Timed, each ``--repeat`` times, reported as median and 90th percentile:

- ``render``: ``urdfgenpy_ros.viewer.render.render`` to an 800x600 image in a warm process
  (VTK off screen through OSMesa); ``render (cold CLI)``: the whole ``urdfgenpy render``
  command in a new process. Peer, when ``--pyrender PYTHON`` names a Python that has
  pyrender: the same meshes and poses drawn by pyrender on OSMesa.
- ``view first paint``: from creating the viewer (server start and scene) to the robot's
  pixels on the canvas of a headless Chromium that is already running. Peer: viser's own
  ``ViserUrdf`` (yourdfpy) on the same URDF, in the same browser.
- ``reload``: from writing the file to the page showing the change (polled in the page).

    python bench/bench_view.py [--repeat 5] [--pyrender /path/to/python] [--view-only]
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path
import statistics
import subprocess
import sys
import tempfile
import time

from urdfgenpy_ros import Box, Collision, Joint, JointLimit, Link, Material, Mesh, Origin, Robot
from urdfgenpy_ros import Visual

HERE = Path(__file__).resolve().parent


def mesh_robot(folder: Path, links: int = 60) -> Robot:
    """Return a 60-link tree whose links are STL meshes in ``folder``."""
    import trimesh
    part = trimesh.creation.capsule(height=0.08, radius=0.025, count=[40, 25])
    stl = folder / 'segment.stl'
    part.export(stl)
    robot = Robot('mesh_humanoid')
    colours = [(0.8, 0.3, 0.2, 1.0), (0.2, 0.5, 0.8, 1.0), (0.3, 0.7, 0.3, 1.0)]

    def link(name: str, index: int) -> Link:
        material = Material(f'c{index % 3}', rgba=colours[index % 3])
        return Link(name).add_visual(Visual(Mesh(str(stl)), origin=Origin((0, 0, 0.05)),
                                            material=material)).add_collision(
            Collision(Box(0.05, 0.05, 0.1), origin=Origin((0, 0, 0.05))))

    robot.add_link(link('base_link', 0))
    count = 1
    for chain in range(5):
        parent = 'base_link'
        for step in range((links - 1) // 5 + (1 if chain < (links - 1) % 5 else 0)):
            name = f'c{chain}_l{step}'
            robot.add_link(link(name, count))
            x = 0.12 if parent == 'base_link' else 0.0
            robot.add_joint(Joint(f'{name}_joint', 'revolute', parent, name,
                                  origin=Origin((x * (chain - 2), 0.0, 0.1),
                                                (0.0, 0.0, 0.3 * (chain - 2))),
                                  axis=(0, 1, 0), limit=JointLimit(-1, 1, effort=1,
                                                                   velocity=1)))
            parent, count = name, count + 1
    assert len(robot.links) == links, len(robot.links)
    return robot


def stats(times: list[float]) -> str:
    """Return 'median / p90' in milliseconds."""
    ordered = sorted(times)
    p90 = ordered[min(len(ordered) - 1, round(0.9 * (len(ordered) - 1)))]
    return f'{statistics.median(ordered) * 1000:.0f} | {p90 * 1000:.0f}'


_PYRENDER = """
import json, os, sys, time
os.environ['PYOPENGL_PLATFORM'] = 'osmesa'
import numpy, pyrender, trimesh
parts = json.load(open(sys.argv[1]))
times = []
for _ in range(int(sys.argv[2])):
    start = time.perf_counter()
    scene = pyrender.Scene(bg_color=[1, 1, 1, 1], ambient_light=[.3, .3, .3])
    for path, matrix, rgba in parts:
        mesh = trimesh.load(path, force='mesh')
        material = pyrender.MetallicRoughnessMaterial(baseColorFactor=rgba)
        scene.add(pyrender.Mesh.from_trimesh(mesh, material=material), pose=numpy.array(matrix))
    camera = pyrender.OrthographicCamera(xmag=0.6, ymag=0.45)
    pose = numpy.eye(4); pose[:3, 3] = [0, -2, 0.5]
    pose[:3, :3] = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]
    scene.add(camera, pose=pose)
    scene.add(pyrender.DirectionalLight(intensity=3.0), pose=pose)
    renderer = pyrender.OffscreenRenderer(800, 600)
    colour, _ = renderer.render(scene)
    renderer.delete()
    times.append(time.perf_counter() - start)
    assert colour.min() < 250
print(json.dumps(times))
"""


def bench_render(robot: Robot, urdf: Path, repeat: int, pyrender: str | None) -> list[str]:
    """Time our renderer warm and cold, and pyrender when given."""
    from urdfgenpy_ros.viewer.render import render
    from urdfgenpy_ros.viewer.scene import link_matrices, robot_parts
    render(robot, {}, 'iso')  # load VTK once
    warm = []
    for _ in range(repeat):
        start = time.perf_counter()
        render(robot, {'c0_l3_joint': 0.5}, 'iso')
        warm.append(time.perf_counter() - start)
    cold = []
    output = urdf.with_suffix('.png')
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run([str(Path(sys.executable).with_name('urdfgenpy')), 'render', str(urdf),
                        '-o', str(output)], check=True, capture_output=True)
        cold.append(time.perf_counter() - start)
    rows = [f'| render, warm process | urdfgenpy_ros (VTK + OSMesa) | {stats(warm)} |',
            f'| render, cold `urdfgenpy render` | urdfgenpy_ros (VTK + OSMesa) | {stats(cold)} |']
    if pyrender:
        matrices = link_matrices(robot, {})
        parts = [(robot.get_link(p.link).visuals[0].geometry.filename,
                  (matrices[p.link] @ _origin(p)).tolist(), list(p.rgba))
                 for p in robot_parts(robot)]
        spec = urdf.with_suffix('.json')
        spec.write_text(json.dumps(parts))
        script = urdf.with_name('pyrender_bench.py')
        script.write_text(_PYRENDER)
        result = subprocess.run([pyrender, str(script), str(spec), str(repeat)],
                                capture_output=True, text=True, timeout=600)
        if result.returncode == 0:
            rows.append(f'| render, warm process | pyrender (OSMesa) | '
                        f'{stats(json.loads(result.stdout.splitlines()[-1]))} |')
        else:
            rows.append(f'| render | pyrender (OSMesa) | failed: '
                        f'{result.stderr.strip().splitlines()[-1]} |')
    return rows


def _origin(part):
    from urdfgenpy_ros.viewer.scene import origin_matrix
    return origin_matrix(Origin((0, 0, 0.05)))


def _browser():
    sys.path.insert(0, str(HERE.parent / 'test'))
    from browser import Browser
    return Browser()


def _painted(browser, timeout: float = 120.0) -> None:
    """Wait until the canvas shows saturated (robot) pixels."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        pixels = browser.canvas()
        saturation = pixels.max(axis=2) - pixels.min(axis=2)
        if (saturation > 80).sum() > 2000:
            return
        time.sleep(0.05)
    raise RuntimeError('the robot never appeared')


def bench_view(robot: Robot, urdf: Path, repeat: int) -> list[str]:
    """Time the first paint of our page and of viser's ViserUrdf, in one browser."""
    browser = _browser()
    browser.driver.set_script_timeout(180)
    from browser import free_port  # noqa: I100 - the test folder, put on the path above
    import viser
    from viser.extras import ViserUrdf
    import yourdfpy
    from urdfgenpy_ros.formats import load
    from urdfgenpy_ros.viewer.web import RobotViewer
    ours, theirs, reloads = [], [], []
    try:
        for _ in range(repeat):
            browser.driver.get('about:blank')
            start = time.perf_counter()
            viewer = RobotViewer(lambda: load(urdf), port=free_port(),
                                 watched=lambda robot: [str(urdf)])
            browser.driver.get(viewer.url)
            _painted(browser)
            ours.append(time.perf_counter() - start)
            viewer.watch(0.2)
            robot.get_joint('c0_l0_joint').limit = JointLimit(-1, 0.5, effort=1, velocity=1)
            robot.to_urdf(urdf)
            written = time.time()
            shown = browser.driver.execute_async_script("""
                const done = arguments[arguments.length - 1];
                const poll = () => {
                  const thumbs = [...document.querySelectorAll('[role=slider]')];
                  if (thumbs.some(t => t.getAttribute('aria-valuemax') === '0.5')) {
                    done(Date.now());
                  } else { setTimeout(poll, 10); }
                };
                poll();""")
            reloads.append(shown / 1000.0 - written)
            robot.get_joint('c0_l0_joint').limit = JointLimit(-1, 1, effort=1, velocity=1)
            robot.to_urdf(urdf)
            viewer.close()
            browser.driver.get('about:blank')
            start = time.perf_counter()
            server = viser.ViserServer(port=free_port(), verbose=False)
            ViserUrdf(server, yourdfpy.URDF.load(str(urdf)))
            browser.driver.get(f'http://127.0.0.1:{server.get_port()}')
            _painted(browser)
            theirs.append(time.perf_counter() - start)
            server.stop()
    finally:
        browser.close()
    return [f'| view, first paint | urdfgenpy_ros viewer (viser) | {stats(ours)} |',
            f'| view, first paint | viser ViserUrdf (yourdfpy) | {stats(theirs)} |',
            f'| view, file written to page updated | urdfgenpy_ros viewer | {stats(reloads)} |']


def main() -> None:
    """Run the benchmark and print a Markdown table."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument('--repeat', type=int, default=5)
    parser.add_argument('--view-only', action='store_true', help='skip the render rows')
    parser.add_argument('--pyrender', help='a Python that has pyrender (for the peer)')
    options = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        robot = mesh_robot(Path(folder))
        urdf = Path(folder) / 'mesh_humanoid.urdf'
        robot.to_urdf(urdf)
        rows = [] if options.view_only else bench_render(robot, urdf, options.repeat,
                                                         options.pyrender)
        rows += bench_view(robot, urdf, options.repeat)
    print('| what | tool | median (ms) | p90 (ms) |\n|---|---|---:|---:|')
    print('\n'.join(rows))


if __name__ == '__main__':
    main()
