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

"""Render a description package in memory, then write it without overwriting anything."""

from __future__ import annotations

from collections.abc import Mapping
import copy
import datetime
import os
from pathlib import Path
import posixpath
import shutil
from typing import Any

from urdfgenpy_ros.formats._xml import fragment, INDENT
from urdfgenpy_ros.formats.urdf import UrdfWriter
from urdfgenpy_ros.formats.xacro import (defined_once, macro_name, macro_xacro, PREFIX_MARK,
                                         top_level_xacro, with_prefix, XACRO_NS)
from urdfgenpy_ros.model.errors import MissingDependencyError, UrdfgenpyError
from urdfgenpy_ros.model.geometry import Mesh
from urdfgenpy_ros.model.link import Shape
from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.reshape.assembly import prefixed
from urdfgenpy_ros.resources import PackageResolver, ResourceError, uri_warning
from urdfgenpy_ros.robot import Robot
from urdfgenpy_ros.scaffold.assets import copy_referenced_files, with_find
from urdfgenpy_ros.scaffold.described import (baked_arguments, hardware_warnings,
                                              referenced_packages)
from urdfgenpy_ros.scaffold.mesh_files import companions, mesh_names, numbered
from urdfgenpy_ros.scaffold.sensors_read import sensors_of
from urdfgenpy_ros.scaffold.spec import PackageSpec
from urdfgenpy_ros.scaffold.templates import template_root

# What the launch files run; package.xml must name each of them.
LAUNCH_DEPENDS = ('joint_state_publisher', 'joint_state_publisher_gui', 'launch',
                  'launch_ros', 'robot_state_publisher', 'ros_gz_bridge', 'ros_gz_sim',
                  'rviz2', 'xacro')
_BRIDGE_TYPES = {'camera': ('sensor_msgs/msg/Image', 'gz.msgs.Image'),
                 'gpu_lidar': ('sensor_msgs/msg/LaserScan', 'gz.msgs.LaserScan'),
                 'imu': ('sensor_msgs/msg/Imu', 'gz.msgs.IMU'),
                 'force_torque': ('geometry_msgs/msg/Wrench', 'gz.msgs.Wrench')}

# RViz displays for what the sensors publish through the bridge (off until Gazebo runs).
_DISPLAYS = {'camera': 'Image', 'gpu_lidar': 'LaserScan'}


def _fragment_file(lines: list[str]) -> str:
    body = '\n'.join(lines)
    return f'<?xml version="1.0"?>\n<robot xmlns:xacro="{XACRO_NS}">\n{body}\n</robot>\n'


def _meshes(spec: PackageSpec, robot: Robot, search_paths: list[str],
            warnings: list[str]) -> dict[str, bytes]:
    """Copy every resolvable mesh into meshes/ and point the robot's URIs at it."""
    resolver = PackageResolver(search_paths)
    base = None
    origin = robot.included_files[0] if robot.included_files else (
        robot.source.file if robot.source is not None else None)  # Xacro: the main file
    if origin and Path(origin).is_file():
        base = Path(origin).parent
    files: dict[str, bytes] = {}
    renamed: dict[str, str] = {}
    for link in robot.links:
        items: tuple[Shape, ...] = (*link.visuals, *link.collisions)
        for item in items:
            mesh = item.geometry
            if not isinstance(mesh, Mesh):
                continue
            if mesh.filename not in renamed:
                note = uri_warning(mesh.filename)
                if note is not None:
                    warnings.append(note)
                try:
                    found = resolver.resolve(mesh.filename, base)
                    data = found.read_bytes()
                    beside = {name: path.read_bytes()
                              for name, path in companions(found, data).items()}
                except (ResourceError, OSError) as error:
                    warnings.append(f'mesh {mesh.filename!r} not copied: {error}')
                    renamed[mesh.filename] = mesh.filename
                    continue
                name = _free_name(files, mesh.filename, data)
                files[name] = data
                folder = posixpath.dirname(name)
                for relative, content in beside.items():  # textures, materials: along
                    relative = posixpath.join(folder, relative)
                    if files.setdefault(relative, content) != content:
                        warnings.append(f'{relative} of mesh {mesh.filename!r} not copied: '
                                        'another mesh has a different file of that name')
                renamed[mesh.filename] = f'package://{spec.name}/meshes/{name}'
            item.geometry = Mesh(renamed[mesh.filename], mesh.scale)
    return {f'meshes/{name}': data for name, data in files.items()}


def _free_name(files: dict[str, bytes], uri: str, data: bytes) -> str:
    """Return the readable name under meshes/ for ``uri``'s ``data`` (mesh_names)."""
    names = mesh_names(uri) or ['mesh']
    for name in names:
        if files.get(name, data) == data:
            return name
    number = 2
    while files.get(numbered(names[-1], number), data) != data:
        number += 1
    return numbered(names[-1], number)


def _macro_file(name: str, lines: list[str]) -> str:
    """Return a file holding ``<xacro:macro name=... params="prefix">`` around ``lines``."""
    body = with_prefix('\n'.join(lines))
    return _fragment_file([f'{INDENT}<xacro:macro name="{name}" params="prefix">', body,
                           f'{INDENT}</xacro:macro>'])


def _urdf_files(spec: PackageSpec, robot: Robot) -> tuple[dict[str, bytes], list[str], str]:
    """
    Return the Xacro files and the names of those the main one uses.

    ``<robot>.urdf.xacro`` includes ``<robot>.macro.xacro`` and calls the robot's macro
    with the ``prefix`` argument (default ''); the macro file includes ``materials.xacro``
    (each material defined unless an earlier file did) and ``<robot>.gazebo.xacro`` and
    ``<robot>.ros2_control.xacro``, macros of their own taking the same prefix, when the
    robot has such blocks. Another package can include the macro file alone and call the
    macro with a prefix and a parent link.
    """
    stem, macro = robot.name, macro_name(robot)
    writer = UrdfWriter(robot)
    materials = [line for material in robot.materials
                 for line in defined_once(writer, material, INDENT)]
    blocks: dict[str, list[str]] = {'gazebo': [], 'ros2_control': []}
    for block in prefixed(robot, PREFIX_MARK).extensions:
        if block.tag in blocks:
            blocks[block.tag].append(fragment(block.element, INDENT * 2))
    for link in robot.links:  # the definitions move to materials.xacro: refer to them
        for visual in link.visuals:
            if visual.material is not None and robot.has_material(visual.material.name):
                visual.material = Material(visual.material.name)
    find = f'$(find {spec.name})/urdf'
    files: dict[str, bytes] = {}
    used, calls, inside = [], [], []
    if materials:  # the macro file includes them: another package may include it alone
        files['urdf/materials.xacro'] = _fragment_file(materials).encode()
        used.append('materials.xacro')
        inside.append(f'{find}/materials.xacro')
    for tag, lines in blocks.items():
        if lines:
            name = f'{stem}.{tag}.xacro'
            files[f'urdf/{name}'] = _macro_file(f'{macro}_{tag}', lines).encode()
            inside.append(f'{find}/{name}')
            calls.append(f'<xacro:{macro}_{tag} prefix="${{prefix}}"/>')
            used.append(name)
    files[f'urdf/{stem}.macro.xacro'] = macro_xacro(
        robot, includes=inside, materials=False, skip=tuple(blocks), calls=calls).encode()
    used.append(f'{stem}.macro.xacro')
    top = [f'{find}/{stem}.macro.xacro']
    files[f'urdf/{stem}.urdf.xacro'] = top_level_xacro(robot, top).encode()
    return files, used, f'{stem}.urdf.xacro'


def render_package(spec: PackageSpec, robot: Robot, source: str = 'the built-in example',
                   search_paths: list[str] | None = None,
                   templates: Path | None = None,
                   xacro_args: Mapping[str, str] | None = None
                   ) -> tuple[dict[str, bytes], list[str]]:
    """
    Return every file of the package (path relative to it: bytes) and any warnings.

    ``xacro_args`` are those the source was expanded with: the package holds the robot
    with their values (and the declared defaults of the others), which it says.
    """
    try:
        import jinja2  # noqa: F401 (refused before any work, not at the templates)
    except ImportError:
        raise MissingDependencyError('jinja2', 'scaffold', 'urdfgenpy init') from None
    from urdfgenpy_ros.viewer.pictures import package_pictures
    pictures, warnings = package_pictures(robot, search_paths or ())  # before URIs change
    baked = baked_arguments(robot, xacro_args or {})
    warnings += _baked_note(baked) + hardware_warnings(robot, baked)
    depends = referenced_packages(robot, PackageResolver(search_paths or ()))
    robot = copy.deepcopy(robot)
    root = templates or template_root()
    files = _meshes(spec, robot, list(search_paths or ()), warnings)
    borrowed: dict[str, tuple[str, str]] = {}
    files.update(copy_referenced_files(spec.name, robot, list(search_paths or ()),
                                       _template_outputs(root, spec.build_type), borrowed))
    files.update(pictures)
    urdf_files, includes, xacro_file = _urdf_files(spec, robot)
    files.update({path: with_find(data.decode(), spec.name).encode()
                  for path, data in urdf_files.items()})
    warnings += _borrowed_notes(files, borrowed)
    depends += [package for package, _ in borrowed.values()]
    context = _context(spec, robot, source, files, xacro_file, includes, baked,
                       sorted(pictures), sorted({*LAUNCH_DEPENDS, *spec.dependencies, *depends}))
    files.update(_rendered(root, spec, context))
    files.setdefault('meshes/.gitkeep', b'')
    return files, warnings


def _context(spec: PackageSpec, robot: Robot, source: str, files: dict[str, bytes],
             xacro_file: str, includes: Any, baked: list[tuple[str, str, bool]],
             pictures: list[str], depends: list[str]) -> dict[str, Any]:
    """Return what the templates are rendered with."""
    sensors = sensors_of(robot)  # built, or read back from <gazebo> blocks
    return {
        'name': spec.name, 'robot_name': robot.name, 'root_link': robot.root.name,
        'macro_name': macro_name(robot),
        'build_type': spec.build_type, 'maintainer_name': spec.maintainer_name,
        'maintainer_email': spec.maintainer_email, 'license': spec.license,
        'description': spec.description or f'Robot description of {robot.name}',
        'source': _shown(source), 'xacro_file': xacro_file,
        'pictures': pictures,
        'includes': includes, 'mesh_count': sum(p.startswith('meshes/') for p in files),
        'year': datetime.date.today().year,
        'exec_depends': depends,
        'baked_arguments': baked,
        'sensor_displays': [{'plugin': _DISPLAYS[sensor.kind], 'name': sensor.name,
                             'topic': sensor.topic if sensor.topic.startswith('/')
                             else f'/{sensor.topic}'}
                            for sensor in sensors if sensor.kind in _DISPLAYS],
        'bridge_topics': [{'name': sensor.topic or sensor.name,
                           'ros_type': _BRIDGE_TYPES[sensor.kind][0],
                           'gz_type': _BRIDGE_TYPES[sensor.kind][1]}
                          for sensor in sensors if sensor.kind in _BRIDGE_TYPES],
    }


def _rendered(root: Path, spec: PackageSpec, context: dict[str, Any]) -> dict[str, bytes]:
    """Return the files the templates of the package's build type make."""
    import jinja2
    environment = jinja2.Environment(loader=jinja2.FileSystemLoader(str(root)),
                                     undefined=jinja2.StrictUndefined,
                                     keep_trailing_newline=True, autoescape=False)
    files = {}
    for folder in ('common', spec.build_type):
        for path in sorted((root / folder).rglob('*.jinja')):
            relative = path.relative_to(root / folder).as_posix()[:-len('.jinja')]
            relative = relative.replace('__name__', spec.name)
            template = environment.get_template(path.relative_to(root).as_posix())
            files[relative] = template.render(context).encode()
    return files


def _baked_note(baked: list[tuple[str, str, bool]]) -> list[str]:
    """Return the line that says which Xacro argument values the package holds."""
    if not baked:
        return []
    given = [f'{name}:={value}' for name, value, said in baked if said]
    default = [f'{name}:={value or repr(value)}' for name, value, said in baked if not said]
    parts = ([f'{" ".join(given)} (given)'] if given else []) + (
        [f'{" ".join(default)} (the defaults)'] if default else [])
    return [f'the package holds the robot as xacro expanded it with {" and ".join(parts)}: '
            'its files do not take these arguments (run urdfgenpy init again with '
            'NAME:=VALUE for other values; its README lists them)']


def _borrowed_notes(files: Mapping[str, bytes],
                    borrowed: Mapping[str, tuple[str, str]]) -> list[str]:
    """Return a line per path of this machine written back through the package it is in."""
    lines = []
    for path, (package, rest) in borrowed.items():
        forms = (f'$(find {package})/{rest}', f'package://{package}/{rest}')
        where = [name for name, data in files.items() if name.endswith('.xacro')
                 and any(form.encode() in data for form in forms)]
        written = next((form for form in forms for name in where
                        if form.encode() in files[name]), forms[0])
        lines.append(f'{", ".join(where) or "the package"}: {path} is in package {package!r} '
                     f'and no file here: written as {written} and package.xml depends on '
                     f'{package} (install it where the package runs)')
    return lines


def _template_outputs(root: Path, build_type: str) -> set[str]:
    """Return the package paths the templates write (copied files must not take them)."""
    return {path.relative_to(root / folder).as_posix()[:-len('.jinja')]
            for folder in ('common', build_type) for path in (root / folder).rglob('*.jinja')}


def _shown(source: str) -> str:
    """Return how the README names the source: a file by its name, not this machine's path."""
    return Path(source).name if Path(source).is_absolute() or os.sep in source else source


def create_package(spec: PackageSpec, robot: Robot, *, force: bool = False,
                   source: str = 'the built-in example', search_paths: list[str] | None = None,
                   templates: Path | None = None, xacro_args: Mapping[str, str] | None = None
                   ) -> tuple[list[Path], list[str]]:
    """
    Write the package; return the files written and any warnings.

    Nothing is written when the package folder exists and is not empty, or when any file
    would be overwritten, unless ``force``; if writing fails half way, what was written
    is removed again.

    :raises UrdfgenpyError: with one line saying what is wrong and how to go on.
    """
    files, warnings = render_package(spec, robot, source, search_paths, templates, xacro_args)
    root = spec.root
    if root.exists() and not root.is_dir():
        raise UrdfgenpyError(f'{root} exists and is not a folder: choose another name or '
                             '--destination-directory')
    if not force and root.is_dir() and any(root.iterdir()):
        raise UrdfgenpyError(f'{root} exists and is not empty: choose another '
                             '--destination-directory, or pass --force to overwrite')
    created_root = not root.exists()
    written: list[Path] = []
    try:
        for relative, data in sorted(files.items()):
            target = root / relative
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(data)
            written.append(target)
    except OSError as error:
        for path in written:
            path.unlink(missing_ok=True)
        if created_root and root.exists():
            shutil.rmtree(root, ignore_errors=True)
        where = error.filename or root
        raise UrdfgenpyError(f'cannot write {where}: {error.strerror or error} (choose a '
                             'writable --destination-directory)') from None
    return written, warnings
