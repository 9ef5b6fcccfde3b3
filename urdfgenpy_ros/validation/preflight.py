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
Engine pre-flight: what a consumer silently changes or drops when it loads the URDF.

``gazebo`` applies the rules of SDFormat's URDF conversion (libsdformat's parser_urdf),
which Gazebo runs on every URDF it spawns: links on fixed joints are lumped into their
parent (unless a ``<gazebo reference="JOINT">`` block sets ``preserveFixedJoint`` or
``disableFixedJointLumping``), a link whose mass, after lumping, is below 1e-6 kg (or
that has no ``<inertial>``) is left out with everything below it, and each ``<gazebo>``
setting no link, collision, visual or joint takes is dropped (G603; a Gazebo-classic
material script Gazebo Sim does not render is G604). The tests compare these rules with
libsdformat's own conversion (the rules: :mod:`~urdfgenpy_ros.formats.sdf_conversion`).
``mujoco`` compiles the URDF with MuJoCo (see :mod:`.mujoco_preflight`).
"""

from __future__ import annotations

from collections.abc import Iterable
from os import PathLike
from pathlib import Path
from typing import TYPE_CHECKING

from urdfgenpy_ros.formats.sdf_conversion import sdformat_conversion
from urdfgenpy_ros.formats.sdf_frames import merge_for_sdf
from urdfgenpy_ros.formats.sdf_gazebo import gazebo_losses, script_notes
from urdfgenpy_ros.model.codes import PREFLIGHT_HINTS
from urdfgenpy_ros.model.errors import ValidationError
from urdfgenpy_ros.model.findings import Findings, link_path
from urdfgenpy_ros.model.review import ENGINES

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def sdformat_findings(robot: RobotModel, findings: Findings) -> None:
    """Add G601 for every lumped link and G602 for every link the conversion leaves out."""
    conversion = sdformat_conversion(robot)
    for name, (into, joint) in conversion.lumped.items():
        link = robot.get_link(name)
        parts = [kind for kind, items in (('collisions', link.collisions),
                                          ('visuals', link.visuals)) if items]
        renamed = (f'; its {" and ".join(parts)} are renamed {into}_fixed_joint_lump__...'
                   if parts else '')
        findings.add('G601', link, f'link {name!r}', link_path(name),
                     f'lumped into {into!r} (fixed joint {joint.name!r}): there is no frame '
                     f'{name!r} in Gazebo, its mass and sensors move to {into!r}{renamed}',
                     PREFLIGHT_HINTS['G601'].replace('JOINT', joint.name), 'link')
    for name, below in conversion.cut.items():
        if name in conversion.lumped and not below:
            continue  # a massless frame lumped into its parent: nothing is lost
        link = robot.get_link(name)
        mass = link.inertial.mass if link.inertial is not None else None
        why = ('has no <inertial>' if mass is None and name not in conversion.lumped_into
               else 'has no mass' if not mass else
               f'has mass {mass:g} kg, which SDFormat takes for none (under 1e-06)')
        if name in conversion.lumped:
            what = f'its collisions and visuals still go to {conversion.lumped[name][0]!r}'
        elif robot.parent_joint(name) is None:
            what = 'it is the root: no link is left, Gazebo cannot load the robot'
        else:
            what = 'the conversion leaves it out with its joint'
        listed = ', '.join(map(repr, below))
        lost = f'; the {len(below)} link(s) below it are left out too: {listed}' if below else ''
        findings.add('G602', link, f'link {name!r}', link_path(name), f'{why}: {what}{lost}',
                     PREFLIGHT_HINTS['G602'], 'link')


def gazebo_block_findings(robot: RobotModel, findings: Findings) -> None:
    """Add G603 for each ``<gazebo>`` element the conversion drops, G604 for scripts."""
    merged, frames = merge_for_sdf(robot, lump_fixed=True)  # as the conversion lumps
    for code, losses in (('G603', gazebo_losses(merged, [frame.joint for frame in frames])),
                         ('G604', script_notes(merged))):
        for loss in losses:
            block = (f'<gazebo reference={loss.reference!r}>' if loss.reference is not None
                     else '<gazebo>')
            path = (f"/robot/gazebo[@reference='{loss.reference}']/{loss.tag}"
                    if loss.reference is not None else f'/robot/gazebo/{loss.tag}')
            findings.add(code, loss.location, f'{block} <{loss.tag}>', path, loss.why,
                         PREFLIGHT_HINTS[code], loss.tag)


def preflight(robot: RobotModel, engines: Iterable[str],
              search_paths: Iterable[str | PathLike[str]] = ()) -> list[ValidationError]:
    """
    Return what each engine in ``engines`` (``mujoco``, ``gazebo``) would change or drop.

    MuJoCo runs when the ``mujoco`` package is importable; otherwise a finding says it
    could not. Mesh URIs resolve through ``search_paths`` as in :func:`validate`.
    """
    findings = Findings(robot)
    if len(robot.roots) != 1:
        return []  # validate() reports it (S001, S002); no engine loads such a robot
    for engine in engines:
        if engine == 'gazebo':
            sdformat_findings(robot, findings)
            gazebo_block_findings(robot, findings)
        elif engine == 'mujoco':
            from urdfgenpy_ros.validation.mujoco_preflight import mujoco_findings
            source = robot.source.file if robot.source is not None else None
            base = Path(source).parent if source and Path(source).is_file() else None
            mujoco_findings(robot, findings, list(search_paths), base)
        else:
            raise ValueError(f'unknown engine {engine!r} (use {", ".join(ENGINES)})')
    return findings.items
