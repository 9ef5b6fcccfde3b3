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
Every chosen link's collision meshes made light, planned in full, then applied at once.

Only ``<collision>`` elements change: each simplified mesh collision is replaced by its
parts, in place (the lossless writer then rewrites those elements only). New meshes are
binary STL files named after the link and the method, beside the source mesh or in
``mesh_folder``; nothing is written unless every link succeeds, and a file already there
is kept only when it holds the same bytes.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
import hashlib
import json
import math
import os
from pathlib import Path
import re
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.collision.findings import CollisionReport, LinkResult
from urdfgenpy_ros.collision.measure import OpenMeshError
from urdfgenpy_ros.collision.methods import METHODS, Options
from urdfgenpy_ros.collision.parts import Part
from urdfgenpy_ros.collision.primitives import split_capsule
from urdfgenpy_ros.collision.simplify import Simplified, simplify
from urdfgenpy_ros.model.errors import ModelError, SourceLocation
from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, Geometry, Mesh, Origin, Sphere
from urdfgenpy_ros.model.link import Collision
from urdfgenpy_ros.model.transforms import to_xyz_rpy
from urdfgenpy_ros.model.urdf_versions import parse_version

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.model.inertial import Inertial


@dataclass
class Plan:
    """What a run will do: each collision's replacement and each file's bytes."""

    report: CollisionReport
    replacements: dict[tuple[str, int], list[Collision]] = field(default_factory=dict)
    files: dict[Path, bytes] = field(default_factory=dict)


def plan_collisions(robot: RobotModel, method: str = 'hull', links: Any = None, *,
                    mesh_folder: str | os.PathLike[str] | None = None,
                    search_paths: tuple = (), min_iou: float | None = None,
                    capsules: bool | None = None, relative_to: Path | None = None,
                    absolute: bool = False, options: Options = Options()) -> Plan:
    """
    Return the plan for ``robot`` (nothing changed, nothing written).

    A mesh written into ``mesh_folder`` is named by a ``package://`` URI inside a ROS
    package, else by its path relative to ``relative_to`` (the robot's file's folder by
    default), or its absolute path with ``absolute``.
    """
    from urdfgenpy_ros.resources import PackageResolver
    if method not in METHODS:
        raise ModelError(f"collision method {method!r}: use one of {', '.join(METHODS)}")
    chosen = _chosen_links(robot, links)
    if capsules is None:
        version = parse_version(robot.urdf_version)
        capsules = isinstance(version, tuple) and version >= (1, 1)
    source = getattr(robot, 'source', None)
    file = getattr(source, 'file', None) if source is not None else None
    base = Path(file).parent if file else None
    run = _Run(method, options, min_iou, capsules, PackageResolver(search_paths), base,
               Path(mesh_folder) if mesh_folder is not None else None,
               None if absolute else relative_to or base, Plan(CollisionReport(method, min_iou)))
    for link in chosen:
        meshes = [index for index, item in enumerate(link.collisions)
                  if isinstance(item.geometry, Mesh)]
        for index in meshes:
            only = link.inertial if len(meshes) == 1 and len(link.collisions) == 1 else None
            _plan_one(run, link.name, index, link.collisions[index],
                      index if len(meshes) > 1 else None, only)
    return run.plan


@dataclass
class _Run:
    """What every collision of one run shares."""

    method: str
    options: Options
    min_iou: float | None
    capsules: bool
    resolver: Any
    base: Path | None  # the robot file's folder: relative URIs are read against it
    folder: Path | None  # mesh_folder
    relative_to: Path | None  # what a URI into mesh_folder is relative to (None: absolute)
    plan: Plan


def _plan_one(run: _Run, link: str, index: int, item: Collision, numbered: int | None,
              inertial: Inertial | None) -> None:
    """Plan the replacement of one mesh collision (or name it, when it is open)."""
    where = item.source or SourceLocation(
        path=f"/robot/link[@name='{link}']/collision[{index + 1}]")
    geometry = item.geometry
    assert isinstance(geometry, Mesh)
    path = run.resolver.resolve(geometry.filename, run.base)
    try:
        done = simplify(path, geometry.scale or (1.0, 1.0, 1.0), run.method, run.options,
                        inertial, run.min_iou)
    except OpenMeshError as error:
        run.plan.report.unclosed.append((link, where, str(error)))
        return
    stem = _stem(link, numbered, done.method, run.options)
    parts = _written(done.parts, run.capsules)
    several = sum(part.kind == 'mesh' for part in parts) > 1
    uri = _uri_maker(geometry.filename, run.folder, run.relative_to)
    run.plan.replacements[(link, index)] = [
        _collision(part, item, number, stem, several, run.folder or path.parent, run.plan, uri)
        for number, part in enumerate(parts)]
    budget = run.options.max_faces if done.method == 'decimate' else None
    run.plan.report.results.append(LinkResult(link, index, done.method, done.measures,
                                              done.repairs, where, geometry.filename, budget))


def _chosen_links(robot: RobotModel, links: Any) -> list[Any]:
    """Return the links named (a name or several), or every link."""
    if links is None or links == ():
        return list(robot.links)
    names = [links] if isinstance(links, str) else list(links)
    known = {link.name for link in robot.links}
    for name in names:
        if name not in known:
            raise ModelError(f'collision: no link named {name!r} (the robot has '
                             f"{', '.join(sorted(known)[:8])}{', ...' if len(known) > 8 else ''})")
    return [link for link in robot.links if link.name in names]


def _stem(link: str, index: int | None, method: str, options: Options) -> str:
    """
    Return the file stem of a link's new collision mesh: link, collision, method, options.

    A method whose result depends on options (decimate, decompose) gets a short hash of
    them, so that a run with other options writes other files.
    """
    safe = re.sub(r'[^A-Za-z0-9_.-]', '_', link)
    stem = f'{safe}_{index}_{method}' if index is not None else f'{safe}_{method}'
    key = replace(options, hulls=False).key(method)
    if key:
        stem += '_' + hashlib.sha256(json.dumps(list(key)).encode()).hexdigest()[:6]
    return stem


def _written(parts: list[Part], capsules: bool) -> list[Part]:
    """Return the parts as they are written: capsules split where the URDF has none."""
    if capsules:
        return parts
    return [piece for part in parts
            for piece in (split_capsule(part) if part.kind == 'capsule' else [part])]


def _uri_maker(original: str, folder: Path | None, relative_to: Path | None) -> Any:
    """Return how a new file's URI is made: beside the original's, or in ``folder``."""
    def uri(target: Path) -> str:
        if folder is None:
            head, _, _ = original.rpartition('/')
            return f'{head}/{target.name}' if head else target.name
        package = _package_uri(target)
        if package is not None:
            return package
        if relative_to is not None:
            return Path(os.path.relpath(target.absolute(), relative_to.absolute())).as_posix()
        return str(target.absolute())
    return uri


def _package_uri(target: Path) -> str | None:
    """Return ``package://NAME/...`` for a file inside a ROS package, else None."""
    from lxml import etree
    for folder in target.absolute().parents:
        manifest = folder / 'package.xml'
        if manifest.is_file():
            try:
                name = (etree.parse(str(manifest)).findtext('name') or '').strip()
            except (OSError, etree.XMLSyntaxError):
                return None
            relative = target.absolute().relative_to(folder).as_posix()
            return f'package://{name}/{relative}' if name else None
    return None


def _collision(part: Part, item: Collision, number: int, stem: str, several: bool,
               folder: Path, plan: Plan, uri: Any) -> Collision:
    """Return the collision element of one part; plan its mesh file when it is one."""
    name = item.name if number == 0 or item.name is None else f'{item.name}_{number}'
    if part.kind == 'mesh':
        target = folder / (f'{stem}_{number}.stl' if several else f'{stem}.stl')
        plan.files[target] = _stl(part)
        return Collision(Mesh(uri(target)), origin=item.origin, name=name)
    import numpy
    matrix = numpy.asarray(item.origin.matrix(), float) @ numpy.asarray(part.pose, float)
    xyz, rpy = to_xyz_rpy(matrix.tolist())
    size = [math.ceil(x * 1e7) / 1e7 for x in part.size]  # up: nothing is lost
    geometry: Geometry
    if part.kind == 'box':
        geometry = Box(*size)
    elif part.kind == 'cylinder':
        geometry = Cylinder(*size)
    elif part.kind == 'capsule':
        geometry = Capsule(*size)
    else:
        geometry = Sphere(size[0])
    origin = Origin([round(x, 7) + 0.0 for x in xyz], [round(x, 9) + 0.0 for x in rpy])
    return Collision(geometry, origin=origin, name=name)


def _stl(part: Part) -> bytes:
    """Return a mesh part as binary STL."""
    data = part.solid().export(file_type='stl')
    return data if isinstance(data, bytes) else data.encode()


def apply_plan(robot: RobotModel, plan: Plan, folder_option: str = 'mesh_folder=') -> list[Path]:
    """
    Write the planned files (none, on failure), then replace the collisions.

    ``folder_option`` is how a failure names the mesh folder option (``--mesh-folder`` on
    the command line).
    """
    written: list[Path] = []
    try:
        for target, data in plan.files.items():
            if target.exists():
                if target.read_bytes() == data:
                    continue
                raise ModelError(f'collision: {target} exists with other content: move it '
                                 f'away, or pass {folder_option} (nothing was written)')
            target.parent.mkdir(parents=True, exist_ok=True)
            with open(target, 'xb') as stream:
                written.append(target)
                stream.write(data)
    except (OSError, ModelError) as error:
        for path in written:
            path.unlink(missing_ok=True)
        if isinstance(error, ModelError):
            raise
        raise ModelError(f'collision: cannot write {error.filename}: {error.strerror} '
                         f'(nothing was written; pass {folder_option} a folder you can '
                         'write)') from None
    later_first = sorted(plan.replacements.items(), key=lambda entry: -entry[0][1])
    for (name, index), collisions in later_first:  # earlier indices stay right
        link = robot.get_link(name)
        link.collisions[index:index + 1] = collisions
    plan.report.files = written
    return written


def simplify_collisions(robot: RobotModel, method: str = 'hull', links: Any = None,
                        **options: Any) -> CollisionReport:
    """
    Make the collision meshes of ``links`` (default: all) light; return what each lost.

    See :meth:`urdfgenpy_ros.robot.Robot.simplify_collisions` for the options.
    """
    min_iou = options.pop('min_iou', None)
    keywords = {name: options.pop(name) for name in
                ('mesh_folder', 'search_paths', 'capsules', 'relative_to') if name in options}
    known = set(Options.__dataclass_fields__)
    unknown = set(options) - known
    if unknown:
        raise ModelError('simplify_collisions: unknown option(s) '
                         f"{', '.join(sorted(unknown))} (known: max_faces, max_hulls, "
                         'threshold, seed, split, min_iou, mesh_folder, search_paths, '
                         'capsules)')
    plan = plan_collisions(robot, method, links, min_iou=min_iou,
                           options=Options(**options), **keywords)
    plan.report.refuse_below()
    apply_plan(robot, plan)
    return plan.report


__all__ = ['apply_plan', 'plan_collisions', 'Plan', 'Simplified', 'simplify_collisions']
