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
MuJoCo pre-flight: compile the URDF with MuJoCo and report what it changed.

MuJoCo reads URDF with ``fusestatic`` and ``discardvisual`` on: links on fixed joints are
fused into their parent body and the root into the world (M501); a link without
``<inertial>`` gets the mass of its collision geometry (M502); ``lower == upper`` means no
range (M503); a mesh collides as its convex hull (M504, decided with trimesh when it is
installed). The model MuJoCo compiles has its mesh URIs resolved to absolute paths and its
visuals left out (MuJoCo discards them); a collision mesh it cannot read is left out too and
reported (M506). MuJoCo then reads the user's file itself, as written (M505 when it refuses
what the rebuilt model hid). Without the ``mujoco`` package, M501 and M503 follow its rules.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
import copy
import dataclasses
import math
import os
from pathlib import Path
import re
import sys
import tempfile
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.codes import PREFLIGHT_HINTS
from urdfgenpy_ros.model.errors import SourceLocation, UrdfgenpyError
from urdfgenpy_ros.model.findings import Findings, joint_path, link_path
from urdfgenpy_ros.model.geometry import Mesh
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.joint import JointType
from urdfgenpy_ros.model.transforms import from_xyz_rpy, IDENTITY4, Matrix4, multiply
from urdfgenpy_ros.model.transforms import symmetric_eigenvalues
from urdfgenpy_ros.reshape.lumping import combine
from urdfgenpy_ros.resources import PackageResolver

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

MESH_FORMATS = ('.stl', '.obj', '.msh')
_RELATIVE = 1e-6  # MuJoCo computes in doubles; principal moments differ by rounding only


def mujoco_findings(robot: RobotModel, findings: Findings, search_paths: list[Any],
                    base: Path | None) -> None:
    """Add what MuJoCo's compile of ``robot`` changes or drops (M501-M509) to ``findings``."""
    _dropped_by_import(robot, findings)
    try:
        import mujoco
    except ImportError:
        _by_rules(robot, findings)
        return
    from urdfgenpy_ros.formats.urdf import write_urdf
    compiled, meshes = _compilable(robot, findings, search_paths, base)
    said: list[str] = []
    model = None
    try:
        with _quiet(said):
            model = mujoco.MjModel.from_xml_string(write_urdf(compiled))
    except (ValueError, UrdfgenpyError) as error:
        findings.add('M505', robot, f'robot {robot.name!r}', '/robot',
                     ' '.join(str(error).split()), PREFLIGHT_HINTS['M505'], 'robot')
    for line in dict.fromkeys(said):
        if 'equal lower and upper limits' in line:
            continue  # M503 says it, on the joint
        findings.add('M507', robot, f'robot {robot.name!r}', '/robot', line,
                     PREFLIGHT_HINTS['M507'], 'robot')
    if model is None:
        return
    if not any(finding.code == 'M506' for finding in findings.items):
        _as_written(robot, findings, search_paths, base, mujoco)
    bodies = {model.body(index).name: index for index in range(model.nbody)}
    into = _fused(robot, set(bodies), findings)
    _masses(robot, model, bodies, into, findings)
    _ranges(robot, model, mujoco, findings)
    _hulls(meshes, findings)


@contextmanager
def _quiet(said: list[str]) -> Iterator[None]:
    """
    Compile in a folder of its own and catch what MuJoCo prints; add its warnings to said.

    MuJoCo writes its warnings on the process's stderr and appends them to
    ``MUJOCO_LOG.TXT`` in the working directory: neither belongs in a user's terminal or
    repository, so both go to a temporary folder, and the warnings become findings.
    """
    here = os.getcwd()
    sys.stderr.flush()
    saved = os.dup(2)
    with tempfile.TemporaryDirectory() as folder, \
            open(Path(folder) / 'stderr', 'w+b') as printed:
        os.chdir(folder)
        os.dup2(printed.fileno(), 2)
        try:
            yield
        finally:
            os.dup2(saved, 2)
            os.close(saved)
            os.chdir(here)
            printed.seek(0)
            text = printed.read().decode('utf-8', 'replace')
            said += [' '.join(line.removeprefix('WARNING:').split())
                     for line in text.splitlines() if line.strip()]


def _as_written(robot: RobotModel, findings: Findings, search_paths: list[Any],
                base: Path | None, mujoco: Any) -> None:
    """
    Let MuJoCo read the user's file itself; report a refusal the rebuilt model hides (M505).

    The model compiled above is rebuilt (visuals left out, absolute mesh paths), so MuJoCo
    never sees, say, a repeated ``<material>`` or a mesh path its ``<compiler meshdir>``
    does not find. Here it reads the file where it is, as written; only the URIs it cannot
    open (``package://``, ``file://``) are handed to it resolved, as assets. It still runs
    in a folder of its own (see _quiet). Skipped when the robot is not that file's (Xacro,
    or edited since it was read).
    """
    from urdfgenpy_ros.formats.urdf_edits import is_as_read
    source = robot.source.file if robot.source is not None else None
    document = robot.extras
    if not source or document is None or not Path(source).is_file() \
            or any(note.code.startswith('X') for note in robot.read_warnings) \
            or not is_as_read(robot):
        return
    path = Path(source).resolve()
    resolver = PackageResolver(search_paths)
    assets: dict[str, bytes] = {}
    whole = document.file_element()  # the file as read
    uses_meshdir = any(node.attrib.get('meshdir') is not None for node in whole.each('compiler'))
    for node in whole.each('mesh'):
        uri = node.attrib.get('filename', '')
        if '://' in uri:
            try:
                assets[uri] = resolver.resolve(uri, base).read_bytes()
            except (UrdfgenpyError, OSError):
                continue  # a visual mesh (MuJoCo drops visuals), or said as M506
    try:
        with _quiet([]):  # its warnings were said once (M507)
            mujoco.MjModel.from_xml_path(str(path), assets)
    except ValueError as error:
        said = ' '.join(str(error).split())
        line = re.search(r"Element '([\w:-]+)', line (\d+)", said)
        where: Any = robot
        tag = 'robot'
        if line:
            where, tag = SourceLocation(str(path), int(line.group(2))), line.group(1)
        hint = PREFLIGHT_HINTS['M505']
        if uses_meshdir and 'Error opening file' in said:
            hint = ('MuJoCo looks for meshes under the <compiler meshdir> of the file: write '
                    'their filenames relative to it, or drop the meshdir')
        findings.add('M505', where, f'robot {robot.name!r}', '/robot',
                     f'MuJoCo refuses {path.name} as it is written: {said}', hint, tag)


_MeshUse = tuple[str, str, Path, float]  # link, element path, file, volume factor of scale


def _compilable(robot: RobotModel, findings: Findings, search_paths: list[Any],
                base: Path | None) -> tuple[RobotModel, list[_MeshUse]]:
    """Return a copy MuJoCo can load: absolute mesh paths, no visuals, no unreadable mesh."""
    compiled = copy.deepcopy(robot)
    resolver = PackageResolver(search_paths)
    meshes: list[_MeshUse] = []
    for link in compiled.links:
        link.visuals.clear()
        kept = []
        for number, collision in enumerate(link.collisions, start=1):
            geometry = collision.geometry
            where = f'{link_path(link.name)}/collision[{number}]/geometry/mesh'
            if isinstance(geometry, Mesh):
                try:
                    # absolute: MuJoCo compiles in a folder of its own (see _quiet)
                    path = resolver.resolve(geometry.filename, base).resolve()
                except UrdfgenpyError as error:  # the message says how to find it
                    findings.add('M506', robot.get_link(link.name), f'link {link.name!r}',
                                 where, f'collision mesh not found ({error}): MuJoCo refuses '
                                 'the model; the pre-flight went on without it',
                                 'make the file findable as the message says', 'mesh')
                    continue
                if path.suffix.lower() not in MESH_FORMATS:
                    findings.add('M506', robot.get_link(link.name), f'link {link.name!r}',
                                 where, f'MuJoCo cannot read {path.suffix} meshes '
                                 f'({geometry.filename!r}): it refuses the model; the '
                                 'pre-flight went on without it', PREFLIGHT_HINTS['M506'],
                                 'mesh')
                    continue
                collision.geometry = dataclasses.replace(geometry, filename=str(path))
                scale = math.prod(abs(value) for value in geometry.scale or (1.0, 1.0, 1.0))
                meshes.append((link.name, where, path, scale))
            kept.append(collision)
        link.collisions[:] = kept
    return compiled, meshes


def _fused(robot: RobotModel, bodies: set[str], findings: Findings,
           note: str = '') -> dict[str, str]:
    """Report links that are not bodies (M501); return link -> the body it is fused into."""
    into: dict[str, str] = {}
    for joint, link in robot.walk():
        if link.name in bodies:
            into[link.name] = link.name
            continue
        if joint is None:
            into[link.name] = 'world'
            message = ('the root link is fused into the world body: MuJoCo fixes the robot '
                       'to the world')
        else:
            into[link.name] = into.get(joint.parent, 'world')
            message = (f'fused into body {into[link.name]!r} (fixed joint {joint.name!r}): '
                       f'there is no body {link.name!r}')
        findings.add('M501', link, f'link {link.name!r}', link_path(link.name),
                     message + note, PREFLIGHT_HINTS['M501'], 'link')
    return into


def _masses(robot: RobotModel, model: Any, bodies: dict[str, int], into: dict[str, str],
            findings: Findings) -> None:
    """Compare each body's mass and principal moments with the URDF's (M502)."""
    frames: dict[str, Matrix4] = {}
    for joint, link in robot.walk():
        if joint is None or into[link.name] == link.name:
            frames[link.name] = IDENTITY4
        else:
            frames[link.name] = multiply(frames[joint.parent],
                                         from_xyz_rpy(joint.origin.xyz, joint.origin.rpy))
    for name, index in bodies.items():
        if index == 0 or not robot.has_link(name):
            continue
        group = [robot.get_link(link) for link, body in into.items() if body == name]
        parts = [(link.inertial, frames[link.name]) for link in group
                 if link.inertial is not None]
        expected = combine(parts) if parts else None
        mass = float(model.body_mass[index])
        moments = sorted(float(value) for value in model.body_inertia[index])
        link = robot.get_link(name)
        if expected is None:
            if mass > 0.0:
                findings.add('M502', link, f'link {name!r}', link_path(name),
                             f'has no mass in the URDF; MuJoCo computes {mass:.6g} kg from '
                             'its collision geometry (density 1000 kg/m^3)',
                             PREFLIGHT_HINTS['M502'], 'link')
            continue
        if _differ(mass, expected.mass) or _moments_differ(moments, expected):
            listed = ', '.join(f'{value:.6g}' for value in moments)
            findings.add('M502', link, f'link {name!r}', link_path(name),
                         f'MuJoCo uses mass {mass:.6g} and principal moments {listed} '
                         f'(the URDF gives {expected.mass:.6g} kg)',
                         PREFLIGHT_HINTS['M502'], 'link')


def _differ(value: float, expected: float) -> bool:
    return abs(value - expected) > _RELATIVE * max(abs(expected), 1e-12)


def _moments_differ(moments: list[float], expected: Inertial) -> bool:
    wanted = sorted(symmetric_eigenvalues(expected.tensor))
    scale = max(abs(value) for value in wanted) or 1e-12
    return any(abs(a - b) > _RELATIVE * scale for a, b in zip(moments, wanted))


def _ranges(robot: RobotModel, model: Any, mujoco: Any, findings: Findings) -> None:
    """Report joints whose range MuJoCo does not take as the URDF gives it (M503)."""
    for joint in robot.joints:
        if joint.type not in (JointType.REVOLUTE, JointType.PRISMATIC) or joint.limit is None:
            continue
        index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, joint.name)
        if index < 0:
            continue
        limit = joint.limit
        low, high = (float(value) for value in model.jnt_range[index])
        if not model.jnt_limited[index]:
            message = (f'range [{limit.lower:g}, {limit.upper:g}] is empty: MuJoCo gives the '
                       'joint no range, it turns freely')
        elif (low, high) != (limit.lower, limit.upper):
            message = f'MuJoCo uses the range [{low:g}, {high:g}]'
        else:
            continue
        findings.add('M503', joint, f'joint {joint.name!r}', joint_path(joint.name) + '/limit',
                     message, PREFLIGHT_HINTS['M503'], 'limit')


def _hulls(meshes: list[_MeshUse], findings: Findings) -> None:
    """Report collision meshes that are not convex (M504); needs trimesh."""
    try:
        import trimesh
    except ImportError:
        return
    robot = findings.robot
    for name, where, path, scale in meshes:
        try:
            mesh: Any = trimesh.load(str(path), force='mesh')
        except Exception:  # noqa: B902 - a mesh trimesh cannot read was read by MuJoCo
            continue
        if mesh.is_watertight and mesh.volume < 0.0:
            _inside_out(findings, name, where, path, mesh, scale)
            mesh = mesh.copy()
            mesh.invert()  # is it convex, the right way out?
        if mesh.is_convex:
            continue
        hull = mesh.convex_hull.volume * scale  # the URDF's scale applied: m^3
        size = (f': its hull holds {hull:.4g} m^3, the mesh {abs(mesh.volume) * scale:.4g} '
                'm^3' if mesh.is_watertight and math.isfinite(hull) else '')
        findings.add('M504', robot.get_link(name), f'link {name!r}', where,
                     f'{path.name} is not convex; MuJoCo collides with its convex hull{size}',
                     PREFLIGHT_HINTS['M504'], 'mesh')


def _inside_out(findings: Findings, name: str, where: str, path: Path, mesh: Any,
                scale: float) -> None:
    """Report a closed mesh whose triangles face inwards (M510): its volume is negative."""
    findings.add('M510', findings.robot.get_link(name), f'link {name!r}', where,
                 f'{path.name} is wound inside out: its triangles face inwards (signed volume '
                 f'{mesh.volume * scale:.4g} m^3); MuJoCo collides with its convex hull, '
                 'which does not mind, but refuses it where it takes inertia from the mesh '
                 '(<mesh inertia="exact">: "mesh volume is negative"), and viewers that cull '
                 'back faces show its inside', PREFLIGHT_HINTS['M510'], 'mesh')


def _dropped_by_import(robot: RobotModel, findings: Findings) -> None:
    """
    Report what MuJoCo's URDF import drops that the MJCF export carries (M508, M509).

    The export's own readings decide: the actuators it makes of ``<ros2_control>``, and
    the friction it gives links from their ``<gazebo reference>`` blocks.
    """
    from urdfgenpy_ros.formats.mjcf.actuators import declared_actuators
    from urdfgenpy_ros.formats.mjcf.friction import declared_friction
    file = robot.source.file if robot.source is not None else None
    for actuator in declared_actuators(robot, None):
        joint = actuator.joint
        where = SourceLocation(file, actuator.line) if actuator.line and file else joint
        findings.add('M508', where, f'joint {joint.name!r}',
                     '/robot/ros2_control/joint/command_interface',
                     f'its {_INTERFACES[actuator.kind]} command interface becomes no '
                     "actuator in MuJoCo's URDF import: the model cannot be driven",
                     PREFLIGHT_HINTS['M508'], 'command_interface')
    for link, friction in declared_friction(robot).items():
        line = friction.element.sourceline
        findings.add('M509', SourceLocation(file, line) if line and file else None,
                     f'link {link!r}',
                     f"/robot/gazebo[@reference='{link}']",
                     f"MuJoCo's URDF import ignores its friction ({friction.text.split()[0]}): "
                     "its geoms get MuJoCo's default 1", PREFLIGHT_HINTS['M509'], 'gazebo')


_INTERFACES = {'position': 'position', 'velocity': 'velocity', 'motor': 'effort'}


def _by_rules(robot: RobotModel, findings: Findings) -> None:
    """Without MuJoCo: fused bodies and empty ranges, by its rules."""
    fused = {link.name for joint, link in robot.walk()
             if joint is None or joint.type is JointType.FIXED}
    bodies = {link.name for link in robot.links} - fused | {'world'}  # MuJoCo's own body
    _fused(robot, bodies, findings, ' (by its rules: the mujoco package is not installed)')
    for joint in robot.joints:
        limit = joint.limit
        if joint.type in (JointType.REVOLUTE, JointType.PRISMATIC) and limit is not None \
                and limit.lower == limit.upper:
            findings.add('M503', joint, f'joint {joint.name!r}',
                         joint_path(joint.name) + '/limit',
                         f'range [{limit.lower:g}, {limit.upper:g}] is empty: MuJoCo gives '
                         'the joint no range, it turns freely (by its rules: the mujoco '
                         'package is not installed)', PREFLIGHT_HINTS['M503'], 'limit')
