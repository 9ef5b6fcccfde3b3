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
The one context the MJCF writer's stages build on: the robot, the options, the document.

:class:`Build` starts as the ``<mujoco>`` skeleton (header comment, compiler, defaults,
an empty ``<asset>`` and ``<worldbody>``) with the base note; each stage of
:data:`urdfgenpy_ros.formats.mjcf.stages.STAGES` adds to it in turn.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from os import PathLike
from pathlib import Path
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.formats.mjcf.bodies import BodyTree, WORLD
from urdfgenpy_ros.formats.mjcf.gains import GainOption, Gains
from urdfgenpy_ros.formats.mjcf.losses import Carried
from urdfgenpy_ros.formats.mjcf.meshes import MeshAssets
from urdfgenpy_ros.model.errors import ValidationError
from urdfgenpy_ros.resources import PackageResolver

if TYPE_CHECKING:
    from urdfgenpy_ros.formats.mjcf.prepare import Fused
    from urdfgenpy_ros.model import RobotModel

EXPANDED = ' (expanded)'


@dataclass(frozen=True)
class WriteOptions:
    """The keywords of ``write_mjcf`` (see there)."""

    fuse_fixed: bool = False
    base: str | None = None
    actuators: str | None = None
    kp: GainOption = None
    kv: GainOption = None
    scene: bool = False
    overlay: str | PathLike[str] | None = None
    meshdir: str = 'assets'
    search_paths: Any = ()
    overwrite: bool = True
    strict: bool = False


@dataclass
class Build:
    """What the stages share: the robot (as read and as written) and the MJCF so far."""

    robot: RobotModel
    path: Path | None
    options: WriteOptions
    fused: Fused
    gains: tuple[Gains, Gains]
    meshes: MeshAssets
    document: Any
    asset: Any
    worldbody: Any
    notes: list[str]
    advice: list[str] = field(default_factory=list)  # of the notes, what asks to act
    tree: BodyTree = field(default_factory=BodyTree)
    carried: Carried = field(default_factory=Carried)
    chosen: list[Any] = field(default_factory=list)  # the actuators written
    armatures: set[str] = field(default_factory=set)  # joints the user gave an armature
    home: Any = None  # the home keyframe's joint positions
    findings: list[ValidationError] = field(default_factory=list)

    @property
    def written(self) -> RobotModel:
        """Return the robot the bodies are written from (fixed links fused, or not)."""
        return self.fused.robot

    @property
    def at_world(self) -> bool:
        """Return whether the root link is ``world`` (MuJoCo's world body)."""
        return self.robot.root.name == WORLD

    @property
    def taken(self) -> str:
        """Return the base the model has: ``fixed`` unless the options say floating."""
        return 'fixed' if self.options.base is None else self.options.base

    @property
    def meshdir(self) -> str | None:
        """Return the mesh folder the model names (None when nothing is written)."""
        return self.options.meshdir if self.path is not None else None


def start(robot: RobotModel, path: Path | None, options: WriteOptions, fused: Fused) -> Build:
    """Return the build of ``robot``'s MJCF: the skeleton and the note on its base."""
    meshdir = options.meshdir if path is not None else None
    note = _base_note(robot.root.name == WORLD, options.base)
    meshes = MeshAssets(PackageResolver(options.search_paths), _source_folder(robot),
                        meshdir)
    document = _skeleton(robot.name, note, options.fuse_fixed, meshdir)
    asset = etree.SubElement(document, 'asset')
    worldbody = etree.SubElement(document, 'worldbody')
    gains = (Gains.of('kp', options.kp, True), Gains.of('kv', options.kv, False))
    return Build(robot, path, options, fused, gains, meshes, document, asset, worldbody,
                 [note])


def _source_folder(robot: RobotModel) -> Path | None:
    file = robot.source.file if robot.source is not None else None
    if not file:
        return None
    path = Path(file.removesuffix(EXPANDED))
    return path.parent if path.is_file() else None


def _base_note(at_world: bool, base: str | None) -> str:
    """Return the note saying which base the model has, and why."""
    if at_world:
        return ("base: the root link is 'world': its joints attach the robot to the world"
                + (f' (base={base!r} ignored)' if base else ''))
    if base is None:
        return ("base: fixed (the default; base='floating' / --base floating gives the root "
                'a free joint)')
    return f'base: {base}'


def _skeleton(name: str, base: str, fuse_fixed: bool, meshdir: str | None) -> Any:
    """Return the ``<mujoco>`` root with its header comment, compiler and defaults."""
    document = etree.Element('mujoco', model=name)
    document.append(etree.Comment(
        f' Written by urdfgenpy_ros from robot {name!r}. '
        f"{base.replace(' / --base floating', '')}. Fixed links "
        f'{"fused into their parents (each a site)" if fuse_fixed else "kept as bodies"}. '
        .replace('--', '- -')))
    compiler = etree.SubElement(document, 'compiler', angle='radian', autolimits='true',
                                inertiafromgeom='false')
    if meshdir:
        compiler.set('meshdir', meshdir)
    defaults = etree.SubElement(document, 'default')
    visual = etree.SubElement(defaults, 'default', {'class': 'visual'})
    etree.SubElement(visual, 'geom', contype='0', conaffinity='0', group='2')
    collision = etree.SubElement(defaults, 'default', {'class': 'collision'})
    etree.SubElement(collision, 'geom', group='3')
    # inertia comes from the URDF: a mesh's own volume (open surfaces have none) is unused
    etree.SubElement(defaults, 'mesh', inertia='shell')
    return document
