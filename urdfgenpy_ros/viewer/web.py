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
The robot in the browser: a ``viser`` page with joint sliders, display toggles and findings.

``RobotViewer`` serves one page on ``http://HOST:PORT``. The scene is built from the
package's own model and kinematics (not from a URDF re-parsed by another library): each
link is a frame posed by forward kinematics, holding its visuals, collisions (hidden until
asked), the centre of mass and the inertia box Gazebo would show. The findings of the
library review (``review_options``: the same as ``check``'s or the node's, suppression
comments included) are buttons that select the link or joint they name; the silenced ones
are counted. ``watch()`` reloads when a file changes.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
import contextlib
import io
import math
from os import PathLike
import re
import threading
import time
from typing import Any

from urdfgenpy_ros.model.errors import Severity, UrdfgenpyError, ValidationError
from urdfgenpy_ros.model.joint import JointType
from urdfgenpy_ros.report import KNOWN_ERRORS, one_line
from urdfgenpy_ros.robot import Robot
from urdfgenpy_ros.validation.checklist import review, ReviewOptions, Suppressed
from urdfgenpy_ros.viewer.scene import (
    inertia_box, joint_positions, link_matrices, MeshCache, Part, require, robot_parts)

_ELEMENT = re.compile(r"^(link|joint) '(.*)'$")
_SELECTED_RGB = (255, 214, 0)


def _node_name(link: str) -> str:
    """Return the scene-tree name of a link's frame (viser splits names at '/')."""
    return '/robot/' + link.replace('/', '\u2215')


def _rgb(rgba: Iterable[float]) -> tuple[int, int, int]:
    red, green, blue = list(rgba)[:3]
    return (round(red * 255), round(green * 255), round(blue * 255))


def _wxyz(matrix: Any) -> tuple[float, float, float, float]:
    from trimesh import transformations
    w, x, y, z = transformations.quaternion_from_matrix(matrix)
    return (float(w), float(x), float(y), float(z))


def _step(lower: float, upper: float) -> float:
    span = upper - lower
    return 10.0 ** math.floor(math.log10(span / 500.0)) if span > 0.0 else 0.001


def slider_range(robot: Robot, name: str) -> tuple[float, float]:
    """Return a free joint's slider range: its limits, or -pi..pi when continuous."""
    joint = robot.get_joint(name)
    if joint.type is JointType.CONTINUOUS or joint.limit is None:
        return -math.pi, math.pi
    return joint.limit.lower, joint.limit.upper


def free_joints(robot: Robot) -> list[str]:
    """Return the movable joints that get a slider: those that mimic none."""
    return [joint.name for joint in robot.joints if joint.is_movable and joint.mimic is None]


class RobotViewer:
    """
    Serve a robot on a local web page; sliders move its joints.

    ``load`` returns the robot (called again by ``reload``); ``watched`` the files whose
    change triggers a reload; ``on_positions`` hears every slider move (the node's GUI
    mode publishes them). ``positions`` holds the current value of every movable joint.
    ``review_options`` say what the findings are (default: every check, meshes through
    ``search_paths``); ``findings`` and ``suppressed`` are the last review's. ``words``
    says the library's fixes in the front end's words (``FrontEnd.worded``).
    """

    def __init__(self, load: Callable[[], Robot], *, host: str = '127.0.0.1',
                 port: int = 8080, search_paths: Iterable[str | PathLike[str]] = (),
                 watched: Callable[[Robot], list[str]] | None = None,
                 on_positions: Callable[[dict[str, float]], None] | None = None,
                 initial: Mapping[str, float] | None = None, validate: bool = True,
                 review_options: ReviewOptions | None = None,
                 words: Callable[[str], str] = str) -> None:
        self.viser = require('viser', 'view', 'The robot viewer')
        self._words = words
        require('trimesh', 'view', 'The robot viewer')
        self._load = load
        self._search_paths = list(search_paths)
        self._watched = watched
        self._on_positions = on_positions
        self._validate = validate
        self._review_options = review_options or ReviewOptions(
            search_paths=tuple(self._search_paths))
        self._lock = threading.RLock()
        self._stop = threading.Event()
        self._gui: list[Any] = []
        self._sliders: dict[str, Any] = {}
        self._frames: dict[str, Any] = {}
        self._layers: dict[str, list[Any]] = {'visual': [], 'collision': [], 'inertia': [],
                                              'grid': []}
        self._highlight: list[Any] = []
        self.robot = load()
        self.findings: list[ValidationError] = []
        self.suppressed: list[Suppressed] = []
        self.selected: str | None = None
        self.status = ''
        self.version = 0  # counts scene rebuilds (loads and reloads)
        self.positions: dict[str, float] = {}
        with contextlib.redirect_stdout(io.StringIO()):  # viser prints a banner anyway
            self.server = self.viser.ViserServer(host=host, port=port, verbose=False)
        # No share button: it would open a tunnel to viser's public relay; the page is local.
        self.server.gui.configure_theme(control_width='large', show_logo=False,
                                        show_share_button=False)
        self.server.scene.set_up_direction('+z')
        self._build(self.robot, dict(initial or {}))

    @property
    def url(self) -> str:
        """Return the page's address."""
        host = self.server.get_host()
        shown = '127.0.0.1' if host in ('0.0.0.0', '') else host
        return f'http://{shown}:{self.server.get_port()}'

    # ---- building the page -----------------------------------------------------------

    def _build(self, robot: Robot, keep: Mapping[str, float]) -> None:
        with self._lock, self.server.atomic():
            self.server.scene.reset()
            for handle in self._gui:
                handle.remove()
            self._gui, self._sliders, self._frames = [], {}, {}
            self._layers = {'visual': [], 'collision': [], 'inertia': [], 'grid': []}
            self._highlight = []
            self.robot, self.selected = robot, None
            if self._validate:
                found = review(robot, self._review_options)
                self.findings, self.suppressed = found.findings, found.suppressed
            self._cache = MeshCache(robot, self._search_paths)
            visuals = robot_parts(robot, 'visual', self._cache)
            shown = visuals or robot_parts(robot, 'collision', self._cache)
            self._size = self._extent(shown)
            for link in robot.links:
                self._frames[link.name] = self.server.scene.add_frame(
                    _node_name(link.name), show_axes=False, axes_length=0.15 * self._size,
                    axes_radius=0.006 * self._size)
            for part in visuals:  # collisions and inertia are sent when first shown
                self._add_part(part, True)
            self._built = {'visual'}
            self._add_controls(robot, keep)
            self.version += 1
        self._apply(self._positions_from_sliders())
        self._frame_camera(shown)

    def _frame_camera(self, parts: list[Part]) -> None:
        """Point the initial camera at the posed robot; note where a grid would lie."""
        import numpy
        matrices = link_matrices(self.robot, self.positions)
        corners = [numpy.asarray(part.mesh.bounds) @ matrices[part.link][:3, :3].T
                   + matrices[part.link][:3, 3] for part in parts if part.link in matrices]
        points = numpy.concatenate(corners) if corners else numpy.zeros((1, 3))
        low, high = points.min(axis=0), points.max(axis=0)
        centre, size = (low + high) / 2.0, max(float(numpy.max(high - low)), 0.05)
        camera = self.server.initial_camera
        camera.look_at = tuple(float(v) for v in centre)
        camera.position = tuple(float(v) for v in centre + size * numpy.array(
            [1.0, -0.9, 0.6]))
        self._ground = (float(centre[0]), float(centre[1]), float(low[2]),
                        10.0 ** math.floor(math.log10(size)))

    def _add_grid(self) -> None:
        """Lay a grid under the robot, on request (bench/RESULTS.md: it slows first paint)."""
        # A software-rendered browser spends most of each frame on the grid's shader.
        x, y, z, cell = self._ground
        self._layers['grid'].append(self.server.scene.add_grid(
            '/grid', width=20 * cell, height=20 * cell, cell_size=cell / 10.0,
            section_size=cell, position=(x, y, z)))

    @staticmethod
    def _extent(parts: list[Part]) -> float:
        import numpy
        if not parts:
            return 1.0
        bounds = numpy.array([part.mesh.bounds for part in parts])
        return float(max(numpy.ptp(bounds.reshape(-1, 3), axis=0).max(), 0.05))

    def _add_part(self, part: Part, visible: bool) -> None:
        name = f'{_node_name(part.link)}/{part.kind}_{part.index}'
        if part.textured:
            handle = self.server.scene.add_mesh_trimesh(name, part.mesh, visible=visible,
                                                        cast_shadow=False, receive_shadow=False)
        else:
            handle = self.server.scene.add_mesh_simple(
                name, part.mesh.vertices, part.mesh.faces, color=_rgb(part.rgba),
                opacity=part.rgba[3] if part.rgba[3] < 1.0 else None, visible=visible,
                flat_shading=len(part.mesh.faces) < 64, cast_shadow=False,
                receive_shadow=False)  # shadows cost seconds in a software-rendered browser
        self._layers[part.kind].append(handle)

    def _add_inertia(self, robot: Robot) -> None:
        radius = 0.015 * self._size
        for link in robot.links:
            if link.inertial is None:
                continue
            pose, sides, valid = inertia_box(link.inertial)
            base = _node_name(link.name)
            self._layers['inertia'].append(self.server.scene.add_icosphere(
                f'{base}/centre_of_mass', radius=radius, color=(20, 20, 20),
                position=tuple(pose[:3, 3])))
            self._layers['inertia'].append(self.server.scene.add_box(
                f'{base}/inertia', color=(60, 140, 255) if valid else (230, 30, 30),
                dimensions=sides, opacity=0.35, wxyz=_wxyz(pose),
                position=tuple(pose[:3, 3])))

    def _add_controls(self, robot: Robot, keep: Mapping[str, float]) -> None:
        gui = self.server.gui
        self._gui.append(gui.add_markdown(f'**{robot.name}**: {len(robot.links)} links, '
                                          f'{len(robot.joints)} joints'))
        self._status = gui.add_markdown(self.status or 'loaded')
        self._gui.append(self._status)
        joints = gui.add_folder('Joints')
        self._gui.append(joints)
        with joints:
            for name in free_joints(robot):
                lower, upper = slider_range(robot, name)
                step = _step(lower, upper)
                movable = upper > lower  # else a fixed value (or limits the findings name)
                value = min(max(float(keep.get(name, 0.0)), lower), upper) if movable \
                    else lower
                slider = gui.add_slider(name, min=lower, max=upper if movable
                                        else lower + step, step=step, initial_value=value,
                                        disabled=not movable)
                slider.on_update(self._slider_moved)
                self._sliders[name] = slider
            if not self._sliders:
                gui.add_markdown('no movable joints')
            reset = gui.add_button('Zero all joints')
            reset.on_click(lambda _: self.set_positions(dict.fromkeys(self._sliders, 0.0),
                                                        notify=True))
        show = gui.add_folder('Show')
        self._gui.append(show)
        with show:
            for label, layer, initial in (('Visual', 'visual', True),
                                          ('Collision', 'collision', False),
                                          ('Frames', 'frames', False),
                                          ('Inertia (CoM, box)', 'inertia', False),
                                          ('Ground grid', 'grid', False)):
                box = gui.add_checkbox(label, initial_value=initial)
                box.on_update(lambda event, layer=layer: self._show(layer,
                                                                    event.target.value))
        self._add_findings()

    def _add_findings(self) -> None:
        gui = self.server.gui
        errors = sum(1 for f in self.findings if f.severity is Severity.ERROR)
        silenced = f', {len(self.suppressed)} suppressed' if self.suppressed else ''
        folder = gui.add_folder(f'Findings ({errors} errors, '
                                f'{len(self.findings) - errors} warnings{silenced})')
        self._gui.append(folder)
        with folder:
            if not self.findings:
                gui.add_markdown('no findings: the model validates cleanly')
            self._selection = gui.add_markdown('')
            for finding in self.findings:
                mark = 'E' if finding.severity is Severity.ERROR else 'W'
                button = gui.add_button(f'{mark} {finding.code} {finding.element}',
                                        color='red' if mark == 'E' else 'yellow',
                                        hint=self._words(f'{finding.message} ({finding.hint})'))
                button.on_click(lambda _, finding=finding: self.select(finding))

    # ---- state -----------------------------------------------------------------------

    def _show(self, layer: str, visible: bool) -> None:
        with self._lock:
            if layer == 'frames':
                for frame in self._frames.values():
                    frame.show_axes = visible
                return
            if visible and layer not in self._built:  # sent on first use: a faster load
                self._built.add(layer)
                if layer == 'inertia':
                    self._add_inertia(self.robot)
                elif layer == 'grid':
                    self._add_grid()
                else:
                    for part in robot_parts(self.robot, layer, self._cache):
                        self._add_part(part, True)
            for handle in self._layers[layer]:
                handle.visible = visible

    def select(self, finding: ValidationError) -> None:
        """Select what ``finding`` names: outline its link (a joint's child) and say why."""
        with self._lock:
            for handle in self._highlight:
                handle.remove()
            self._highlight = []
            self.selected = finding.element
            self._selection.content = (f'**{finding.code}** {finding.element}: '
                                       f'{finding.message}  \n*fix:* '
                                       f'{self._words(finding.hint)}  \n'
                                       f'`{finding.location}`' + ''.join(
                                           f'  \n*via* {place.path} `{place}`'
                                           for place in finding.location.via))
            match = _ELEMENT.match(finding.element)
            if match is None:
                return
            kind, name = match.groups()
            link = name
            if kind == 'joint':
                if not self.robot.has_joint(name):
                    return
                link = self.robot.get_joint(name).child
            if link not in self._frames:
                return
            frame = self._frames[link]
            frame.show_axes = True
            parts = [p for p in robot_parts(self.robot, 'visual', MeshCache(
                self.robot, self._search_paths)) if p.link == link]
            if parts:
                import numpy
                bounds = numpy.array([p.mesh.bounds for p in parts]).reshape(-1, 3)
                low, high = bounds.min(axis=0), bounds.max(axis=0)
                sides = tuple(float(v) for v in numpy.maximum(high - low, 1e-3) * 1.08)
                self._highlight.append(self.server.scene.add_box(
                    f'{_node_name(link)}/selected', color=_SELECTED_RGB, dimensions=sides,
                    wireframe=True, position=tuple(float(v) for v in (low + high) / 2)))

    def _positions_from_sliders(self) -> dict[str, float]:
        return {name: float(slider.value) for name, slider in self._sliders.items()}

    def _slider_moved(self, event: Any) -> None:
        if event.client is None:  # set from Python: set_positions applies it itself
            return
        values = self._positions_from_sliders()
        self._apply(values)
        if self._on_positions is not None:
            self._on_positions(dict(values))

    def _apply(self, values: Mapping[str, float]) -> None:
        with self._lock:
            try:
                positions = joint_positions(self.robot, {
                    name: value for name, value in values.items() if name in self._sliders})
            except UrdfgenpyError:
                return
            matrices = link_matrices(self.robot, positions)
            with self.server.atomic():
                for link, frame in self._frames.items():
                    matrix = matrices.get(link)
                    if matrix is not None:
                        frame.position = tuple(float(v) for v in matrix[:3, 3])
                        frame.wxyz = _wxyz(matrix)
            self.positions = positions

    def set_positions(self, values: Mapping[str, float], notify: bool = False) -> None:
        """Move joints from Python (sliders follow); ``notify`` tells ``on_positions``."""
        with self._lock:
            for name, value in values.items():
                slider = self._sliders.get(name)
                if slider is not None:
                    slider.value = min(max(float(value), slider.min), slider.max)
            current = self._positions_from_sliders()
        self._apply(current)
        if notify and self._on_positions is not None:
            self._on_positions(dict(current))

    def show(self, robot: Robot) -> None:
        """Show another robot (a reloaded model), keeping the joint values it shares."""
        self._build(robot, self._positions_from_sliders())

    # ---- reloading -------------------------------------------------------------------

    def reload(self) -> bool:
        """
        Load the robot again; on a user's mistake keep the last one and show it in one line.

        A bug (any other exception) is raised, with its traceback.
        """
        try:
            robot = self._load()
        except KNOWN_ERRORS as error:
            self._set_status(f'**reload failed** (showing the last good model): '
                             f'{self._words(one_line(error))}')
            return False
        self.status = f'reloaded at {time.strftime("%H:%M:%S")}'
        self.show(robot)
        return True

    def _set_status(self, text: str) -> None:
        self.status = text
        with self._lock:
            self._status.content = text

    def watch(self, interval: float = 0.5) -> threading.Thread:
        """Reload whenever a watched file changes (checked every ``interval`` seconds)."""
        import os

        def stamps() -> dict[str, int]:
            result = {}
            for path in self._watched(self.robot) if self._watched else []:
                try:
                    result[path] = os.stat(path).st_mtime_ns
                except OSError:
                    result[path] = -1
            return result

        first = stamps()  # taken now: an edit made while the thread starts is not missed

        def loop() -> None:
            last = first
            while not self._stop.wait(interval):
                now = stamps()
                if now != last:
                    self.reload()
                    last = stamps()

        thread = threading.Thread(target=loop, name='urdfgenpy-view-watch', daemon=True)
        thread.start()
        return thread

    def close(self) -> None:
        """Stop watching and serving."""
        self._stop.set()
        with contextlib.redirect_stdout(io.StringIO()):
            self.server.stop()
