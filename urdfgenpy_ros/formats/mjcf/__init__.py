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
MuJoCo MJCF writer: every link a body, the physics as the URDF gives it, losses named.

:func:`write_mjcf` returns an :class:`MjcfResult`: the MJCF text, the findings for what
the MJCF cannot carry (M801-M808, in ``check``'s format), the choices it made (the
base, the gains) as notes, and the files it wrote beside the model (meshes, scene).
It prepares (:func:`.prepare.prepare` refuses what MuJoCo refuses), runs the stages of
:data:`.stages.STAGES` in order over one :class:`.build.Build`, then writes the files;
:func:`write_prepared` does the same after a ``prepare`` made by the caller.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from os import PathLike
from pathlib import Path
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.formats.mjcf.build import Build, EXPANDED, start, WriteOptions
from urdfgenpy_ros.formats.mjcf.fusing import fused
from urdfgenpy_ros.formats.mjcf.gains import GainOption
from urdfgenpy_ros.formats.mjcf.meshes import MeshAssets
from urdfgenpy_ros.formats.mjcf.prepare import (
    BASES, Fused, MINIMUM_MASS, MjcfRefusedError, prepare, prepared, raise_refused, REFUSED,
    TENSORS)
from urdfgenpy_ros.formats.mjcf.stages import DEFAULT_KP, DEFAULT_KV, NO_ACTUATORS, STAGES
from urdfgenpy_ros.model.errors import ModelError, ValidationError

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.model.review import ReviewRecord

__all__ = ['BASES', 'DEFAULT_KP', 'DEFAULT_KV', 'EXPANDED', 'MINIMUM_MASS',
           'MjcfRefusedError', 'MjcfResult', 'NO_ACTUATORS', 'prepare', 'REFUSED', 'STAGES',
           'TENSORS', 'write_mjcf', 'write_prepared']


@dataclass
class MjcfResult:
    """The MJCF text, what it cannot carry, the choices made, and the files written."""

    text: str
    findings: list[ValidationError] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    files: list[Path] = field(default_factory=list)
    advice: list[str] = field(default_factory=list)  # of the notes, what asks the user to act


def write_mjcf(robot: RobotModel, path: str | PathLike[str] | None = None, *,
               fuse_fixed: bool = False, base: str | None = None,
               actuators: str | None = None, kp: GainOption = None,
               kv: GainOption = None, scene: bool = False,
               overlay: str | PathLike[str] | None = None, meshdir: str = 'assets',
               search_paths: Any = (), overwrite: bool = True,
               strict: bool = False) -> MjcfResult:
    """
    Return the MJCF of ``robot``; with ``path``, write it, its meshes and ``scene.xml``.

    ``fuse_fixed`` merges fixed-joint children into their parents (the lumped inertia,
    each merged link a ``<site>``); ``base`` is ``fixed`` (the default) or ``floating``
    (a free joint) unless the root link is ``world``; ``actuators`` (position, velocity,
    motor) puts that actuator on every joint instead of what ``<ros2_control>``
    declares; ``kp``/``kv`` are the servo gains, a number for every joint or a mapping
    of joint names (``{'default': 2000, 'wrist_3_joint': 500}``; MuJoCo's default 1
    otherwise; ``kv`` also damps the position servos); each keyframe's ``ctrl`` holds
    the robot at its pose, and a stiff servo on a light joint gets the armature that
    keeps it stable at the timestep (the notes say the values);
    ``overlay`` is an MJCF file merged in by element name; ``meshdir`` the folder beside
    ``path`` the meshes go to; without ``overwrite``, a file there with other content is
    refused before anything is written. With ``strict``, each thing the MJCF cannot carry
    is an error, and with any, nothing is written.

    :raises MjcfRefusedError: for a mass or tensor MuJoCo refuses, before writing.
    :raises ModelError: for a bad option or a mesh that cannot be found or read.
    """
    options = WriteOptions(fuse_fixed, base, actuators, kp, kv, scene, overlay, meshdir,
                           search_paths, overwrite, strict)
    review, written = prepared(robot, vars(options))
    raise_refused(review, fuse_fixed)
    assert written is not None  # a review that refuses nothing has the robot to write
    return _run(robot, path, options, written)


def write_prepared(robot: RobotModel, review: ReviewRecord,
                   path: str | PathLike[str] | None = None, **options: Any) -> MjcfResult:
    """
    Return (and with ``path``, write) the MJCF of ``robot``, which ``prepare`` reviewed.

    ``review`` is what :func:`prepare` returned for ``robot`` and the same ``options``
    (``write_mjcf``'s keywords): its refusals are raised as ``write_mjcf`` raises them.
    """
    settings = WriteOptions(**options)
    raise_refused(review, settings.fuse_fixed)
    written = Fused(*fused(robot)) if settings.fuse_fixed else Fused(robot, {}, {})
    return _run(robot, path, settings, written)


def _run(robot: RobotModel, path: str | PathLike[str] | None, options: WriteOptions,
         written: Fused) -> MjcfResult:
    """Run the stages over one build of ``robot``'s MJCF; finish it."""
    build = start(robot, Path(path) if path is not None else None, options, written)
    for stage in STAGES:
        stage(build)
    return _finish(build)


def _finish(build: Build) -> MjcfResult:
    """Return the result of ``build``; with a path, write the files (unless ``strict`` fails)."""
    etree.indent(build.document, space='  ')
    text = etree.tostring(build.document, encoding='unicode') + '\n'
    result = MjcfResult(text, build.findings, build.notes, advice=build.advice)
    options = build.options
    if build.path is not None and not (options.strict and build.findings):
        result.files = _write(build.path, text, build.meshes, options.meshdir,
                              options.scene, build.robot.name, options.overwrite)
    return result


def _write(path: Path, text: str, meshes: MeshAssets, meshdir: str, scene: bool,
           name: str, overwrite: bool) -> list[Path]:
    """
    Write the model, its meshes and, with ``scene``, ``scene.xml``; return the files.

    Everything is made in memory first (a mesh that fails writes nothing); without
    ``overwrite``, a file that exists with other content is refused before any is written.
    """
    from urdfgenpy_ros.formats._xml import xml_bytes
    folder = path.parent / meshdir
    planned = {folder / file: data for file, data in meshes.contents().items()}
    planned[path] = xml_bytes(text)
    if scene:
        from urdfgenpy_ros.formats.mjcf.scene import scene_text
        target = path.parent / 'scene.xml'
        if target.resolve() == path.resolve():
            raise ModelError(f'{path}: the scene is written to scene.xml beside the model: '
                             'name the model otherwise')
        planned[target] = xml_bytes(scene_text(path.name, name))
    if not overwrite:
        for file, data in planned.items():
            if file.exists() and file.read_bytes() != data:
                raise ModelError(f'{file} exists: pass --force (overwrite=True) to replace '
                                 'it, or write the model to another folder')
    for file, data in planned.items():
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_bytes(data)
    return list(planned)
