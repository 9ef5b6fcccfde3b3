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
"""

from __future__ import annotations

from dataclasses import dataclass, field
import importlib.util
from os import PathLike
from pathlib import Path
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.errors import ModelError, Severity, UrdfgenpyError, ValidationError
from urdfgenpy_ros.floats import fmt, fmt_vec
from urdfgenpy_ros.formats.mjcf.actuators import ACTUATOR_TYPES, declared_actuators, gears
from urdfgenpy_ros.formats.mjcf.actuators import initial_values
from urdfgenpy_ros.formats.mjcf.actuators import write_actuators
from urdfgenpy_ros.formats.mjcf.armature import stabilise, write_rotor_armatures
from urdfgenpy_ros.formats.mjcf.blocks import (
    apply_block, check_attributes, merge_overlay, read_overlay)
from urdfgenpy_ros.formats.mjcf.bodies import BodyWriter, WORLD
from urdfgenpy_ros.formats.mjcf.contacts import write_excludes
from urdfgenpy_ros.formats.mjcf.friction import declared_friction
from urdfgenpy_ros.formats.mjcf.fusing import fused
from urdfgenpy_ros.formats.mjcf.gains import GainOption, Gains
from urdfgenpy_ros.formats.mjcf.keyframe import hold_keyframes, home_positions
from urdfgenpy_ros.formats.mjcf.keyframe import write_keyframe
from urdfgenpy_ros.formats.mjcf.losses import Carried, find_losses
from urdfgenpy_ros.formats.mjcf.meshes import MeshAssets
from urdfgenpy_ros.formats.mjcf.mimic import write_equalities
from urdfgenpy_ros.formats.mjcf.sensors import write_sensors
from urdfgenpy_ros.resources import PackageResolver

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

BASES = ('fixed', 'floating')
DEFAULT_KP = 1.0  # MuJoCo's own default for a position actuator
DEFAULT_KV = 1.0  # and for a velocity actuator
EXPANDED = ' (expanded)'
REFUSED = ('I201', 'I202', 'I203', 'I207')  # what MuJoCo refuses to compile
TENSORS = ('I202', 'I203')  # of these, what convert --fix repairs
MINIMUM_MASS = 1e-15  # MuJoCo's mjMINVAL: a moving body needs this much
NO_ACTUATORS = ('no actuator written: the <ros2_control> of the robot declares no joint '
                'command interface, so nothing drives the joints (the robot falls limp under '
                "gravity): actuators='position' / --actuators position puts a servo on every "
                'joint, with kp= / --kp for its gain')


class MjcfRefusedError(UrdfgenpyError):
    """The robot has what MuJoCo refuses (an inertia, a mass): nothing was written."""

    def __init__(self, message: str, findings: list[ValidationError]) -> None:
        super().__init__(message)
        self.findings = findings


@dataclass
class MjcfResult:
    """The MJCF text, what it cannot carry, the choices made, and the files written."""

    text: str
    findings: list[ValidationError] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    files: list[Path] = field(default_factory=list)
    advice: list[str] = field(default_factory=list)  # of the notes, what asks the user to act


def _source_folder(robot: RobotModel) -> Path | None:
    file = robot.source.file if robot.source is not None else None
    if not file:
        return None
    path = Path(file.removesuffix(EXPANDED))
    return path.parent if path.is_file() else None


def _refuse(robot: RobotModel, written: RobotModel, fuse_fixed: bool, floating: bool) -> None:
    """Raise MjcfRefusedError when MuJoCo refuses a mass or tensor of ``written``."""
    from urdfgenpy_ros.validation import validate
    refused = [finding for finding in validate(written, check_meshes=False)
               if finding.code in REFUSED]
    root = written.root
    if floating and root.name != WORLD and _welded_mass(written, root.name) < MINIMUM_MASS:
        from urdfgenpy_ros.errors import SourceLocation
        refused.append(ValidationError(
            'I201', Severity.ERROR, f'link {root.name!r}',
            root.source or SourceLocation(path=f"/robot/link[@name='{root.name}']"),
            'the root link moves (a floating base) but has no mass, nor anything welded '
            'to it', 'give it a mass and inertia (Inertial.from_geometry), or keep the base '
            'fixed: MuJoCo refuses a massless moving body'))
    if refused:
        raise MjcfRefusedError(
            f'robot {robot.name!r}: MuJoCo refuses the mass or inertia of '
            f'{len(refused)} link(s): {_advice(refused, fuse_fixed)}; nothing written',
            refused)


def _advice(refused: list[ValidationError], fuse_fixed: bool) -> str:
    """Return what repairs the refused links: convert --fix for a tensor, else the URDF."""
    tensors = sorted({finding.element for finding in refused if finding.code in TENSORS})
    massless = sorted({finding.element for finding in refused
                       if finding.code not in TENSORS})
    said = []
    if tensors:
        said.append(f"urdfgenpy convert --fix repairs the tensor of {', '.join(tensors)}")
    if massless:
        said.append(f"give {', '.join(massless)} an <inertial> with a positive mass (urdfgenpy "
                    'inertia MESH --mass KG prints one; Inertial.from_geometry in Python)'
                    + ('' if fuse_fixed else ', or pass --fuse-fixed / fuse_fixed if they '
                       'are fixed links'))
    return '; '.join(said)


def _welded_mass(robot: RobotModel, name: str) -> float:
    """Return the mass of link ``name`` and of every link welded to it below."""
    link = robot.get_link(name)
    mass = link.inertial.mass if link.inertial is not None else 0.0
    return mass + sum(_welded_mass(robot, joint.child) for joint in robot.child_joints(name)
                      if joint.type.value == 'fixed')


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
    if base not in (None, *BASES):
        raise ModelError(f'base {base!r}: use fixed or floating')
    if actuators not in (None, *ACTUATOR_TYPES):
        raise ModelError(f"actuators {actuators!r}: use {', '.join(ACTUATOR_TYPES)}")
    gains = (Gains.of('kp', kp, True), Gains.of('kv', kv, False))
    if len(robot.roots) != 1:
        raise ModelError(f'robot {robot.name!r} has {len(robot.roots)} root links: MJCF '
                         'needs one tree (urdfgenpy check says why)')
    for joint in robot.joints:
        for role in ('parent', 'child'):
            if not robot.has_link(getattr(joint, role)):
                raise ModelError(f'joint {joint.name!r}: {role} link {getattr(joint, role)!r}'
                                 ' does not exist: define the link or fix the name')
    written, sites, owners = fused(robot) if fuse_fixed else (robot, {}, {})
    _refuse(robot, written, fuse_fixed, base == 'floating')
    at_world = robot.root.name == WORLD
    taken = 'fixed' if base is None else base
    notes = [_base_note(at_world, base)]
    meshes = MeshAssets(PackageResolver(search_paths), _source_folder(robot),
                        meshdir if path is not None else None)
    document = _skeleton(robot.name, notes[0], fuse_fixed,
                         meshdir if path is not None else None)
    asset = etree.SubElement(document, 'asset')
    worldbody = etree.SubElement(document, 'worldbody')
    declared = declared_friction(robot)
    meshes.prepare(written)  # converts what needs it, in parallel when there is much
    writer = BodyWriter(written, meshes, taken, sites)
    writer.friction = ({link: value.text for link, value in declared.items()}, owners)
    tree = writer.write(worldbody)
    notes.extend(meshes.said())
    for element, attributes in meshes.elements():
        etree.SubElement(asset, element, attributes)
    for name, rgba in tree.materials.items():
        etree.SubElement(asset, 'material', name=name, rgba=fmt_vec(rgba))
    if not len(asset):
        document.remove(asset)
    carried = Carried(stand_ins=dict(tree.stand_ins), missing=dict(tree.missing),
                      followers={j.name for j in robot.joints if j.mimic is not None},
                      links={link.name for link in robot.links},
                      mujoco_check=check_attributes, world_root=at_world,
                      friction_links={link for link, value in declared.items()
                                      if value.isotropic},
                      friction_written=set(declared))
    from urdfgenpy_ros.formats.urdf import write_urdf
    urdf = etree.fromstring(write_urdf(robot).encode('utf-8'),
                            etree.XMLParser(huge_tree=True, resolve_entities=False,
                                            no_network=True))
    apply_block(urdf.find('mujoco'), document)
    if urdf.find('mujoco') is not None and importlib.util.find_spec('mujoco') is None:
        notes.append("the URDF's <mujoco> block was copied unchecked: MuJoCo checks it "
                     "when installed (pip install 'urdfgenpy_ros[engines]')")
    carried.mimics = write_equalities(document, written)
    chosen = declared_actuators(written, actuators)
    advice = _check_gains(written, chosen, gains)
    write_actuators(document, chosen, *gains, defaults=(DEFAULT_KP, DEFAULT_KV))
    armatures = _armatures(worldbody)  # the URDF's <mujoco> block set them: the user's
    notes.extend(write_rotor_armatures(worldbody, written))
    advice += [NO_ACTUATORS] if not chosen and actuators is None else []
    reductions = gears(written)
    made = {(actuator.joint.name, actuator.kind) for actuator in chosen}
    declared_ones = chosen if actuators is None else declared_actuators(written, None)
    carried.replaced_by = actuators
    for actuator in declared_ones:  # with --actuators, an interface of that kind is carried
        if actuator.origin is not None and (actuator.joint.name, actuator.kind) in made:
            carried.interfaces.add(actuator.origin)
    for actuator in chosen:
        if actuator.joint.name in reductions:
            carried.transmissions.add(reductions[actuator.joint.name][1])
    home = home_positions(tree, written, initial_values(written))
    write_keyframe(document, tree, home)
    carried.sensors = write_sensors(document, worldbody, written, carried.partly)
    if overlay is not None:
        extra = read_overlay(overlay)
        armatures |= _armatures(extra)
        merge_overlay(document, extra)
    _note_gains(notes, document, gains)
    _simulate(document, notes, {actuator.kind for actuator in chosen}, gains[1].given,
              (scene and path is not None and taken == 'floating' and not at_world)
              and (robot.root.name, meshes, meshdir))
    added, unstable = stabilise(document, written, home, armatures)
    notes.extend(added)
    advice.extend(unstable + hold_keyframes(document, tree))
    notes.extend(advice)
    notes.append(write_excludes(document, meshes.contents(),
                                meshdir if path is not None else None))
    file = robot.source.file if robot.source is not None else None
    findings = find_losses(robot, urdf, file, carried)
    from urdfgenpy_ros.validation.xacro_source import in_source
    findings = in_source(findings, robot)
    etree.indent(document, space='  ')
    text = etree.tostring(document, encoding='unicode') + '\n'
    if strict:
        findings = [ValidationError(finding.code, Severity.ERROR, finding.element,
                                    finding.location, finding.message, finding.hint)
                    for finding in findings]
    result = MjcfResult(text, findings, notes, advice=advice)
    if path is not None and not (strict and findings):
        result.files = _write(Path(path), text, meshes, meshdir, scene, robot.name,
                              overwrite)
    return result


def _simulate(document: Any, notes: list[str], kinds: set[str], servo_damping: bool,
              placed: Any) -> None:
    """Choose the integrator, place a floating base on the floor; say both in the header."""
    from urdfgenpy_ros.formats.mjcf.placement import choose_integrator, rest_on_floor
    said = [choose_integrator(document, kinds, servo_damping)]
    if placed:
        root, meshes, meshdir = placed
        said.append(rest_on_floor(document, root, meshes.contents(), meshdir))
    for note in filter(None, said):
        notes.append(note)
        comment = document[0]
        comment.text = f"{comment.text}{note.replace('--', '- -')}. "


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


def _check_gains(robot: RobotModel, chosen: list[Any], gains: tuple[Gains, Gains]
                 ) -> list[str]:
    """Refuse a gain for a joint the robot lacks; return notes for gains left unused."""
    takes = {'kp': ('position',), 'kv': ('position', 'velocity')}
    notes = []
    for gain in gains:
        actuated = {actuator.joint.name for actuator in chosen
                    if actuator.kind in takes[gain.option]}
        notes.extend(gain.check_joints((joint.name for joint in robot.joints), actuated))
    return notes


def _note_gains(notes: list[str], document: Any, gains: tuple[Gains, Gains]) -> None:
    """Say each servo kind's gain, as the model has it (an overlay may have set it)."""
    section = document.find('actuator')
    for kind, gain, fallback in (('position', gains[0], DEFAULT_KP),
                                 ('velocity', gains[1], DEFAULT_KV)):
        found = {(element.get('joint'), element.get(gain.option))
                 for element in (section.iter(kind) if section is not None else ())}
        if not found:
            continue
        expected = {(joint, fmt(value if (value := gain.of_joint(joint or '')) is not None
                                else fallback)) for joint, _ in found}
        if found != expected:
            values = ', '.join(sorted({text or "MuJoCo's default" for _, text in found}))
            notes.append(f'{kind} actuators: {gain.option}={values} (the overlay sets them)')
            continue
        notes.append(f'{kind} actuators: {gain.option}={gain.describe(fallback)}')


def _armatures(element: Any) -> set[str]:
    """Return the names of the joints under ``element`` that have an armature."""
    return {node.get('name') for node in element.iter('joint')
            if node.get('armature') is not None and node.get('name')}


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
