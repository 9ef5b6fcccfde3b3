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
The MJCF writer's stages, in the order :data:`STAGES` runs them over one :class:`Build`.

Each stage writes one part of the model (bodies, assets, the URDF's ``<mujoco>`` block,
equalities, actuators, keyframe, sensors, overlay, integrator and placement, armatures,
contact excludes) or finds the losses, and records what it did in the build's notes and
:class:`~urdfgenpy_ros.formats.mjcf.losses.Carried`. No stage checks the robot:
:mod:`.prepare` refused what MuJoCo refuses before the first one runs.
"""

from __future__ import annotations

import importlib.util
from typing import Any, Callable

from lxml import etree

from urdfgenpy_ros.formats.mjcf.actuators import declared_actuators, gears
from urdfgenpy_ros.formats.mjcf.actuators import initial_values, write_actuators
from urdfgenpy_ros.formats.mjcf.armature import stabilise, write_rotor_armatures
from urdfgenpy_ros.formats.mjcf.blocks import (
    apply_block, check_attributes, merge_overlay, read_overlay)
from urdfgenpy_ros.formats.mjcf.bodies import BodyWriter
from urdfgenpy_ros.formats.mjcf.build import Build
from urdfgenpy_ros.formats.mjcf.contacts import write_excludes
from urdfgenpy_ros.formats.mjcf.friction import declared_friction
from urdfgenpy_ros.formats.mjcf.gains import Gains
from urdfgenpy_ros.formats.mjcf.keyframe import hold_keyframes, home_positions
from urdfgenpy_ros.formats.mjcf.keyframe import write_keyframe
from urdfgenpy_ros.formats.mjcf.losses import Carried, find_losses
from urdfgenpy_ros.formats.mjcf.mimic import write_equalities
from urdfgenpy_ros.formats.mjcf.sensors import write_sensors
from urdfgenpy_ros.formats.mjcf.source import mujoco_block, urdf_root
from urdfgenpy_ros.model.errors import Severity, ValidationError
from urdfgenpy_ros.model.floats import fmt, fmt_vec

DEFAULT_KP = 1.0  # MuJoCo's own default for a position actuator
DEFAULT_KV = 1.0  # and for a velocity actuator
NO_ACTUATORS = ('no actuator written: the <ros2_control> of the robot declares no joint '
                'command interface, so nothing drives the joints (the robot falls limp under '
                "gravity): actuators='position' / --actuators position puts a servo on every "
                'joint, with kp= / --kp for its gain')


def write_bodies(build: Build) -> None:
    """Write every link a body (meshes converted first); record what they carry."""
    robot, written = build.robot, build.written
    declared = declared_friction(robot)
    build.meshes.prepare(written)  # converts what needs it, in parallel when there is much
    writer = BodyWriter(written, build.meshes, build.taken, build.fused.sites)
    writer.friction = ({link: value.text for link, value in declared.items()},
                       build.fused.owners)
    tree = build.tree = writer.write(build.worldbody)
    build.carried = Carried(stand_ins=dict(tree.stand_ins), missing=dict(tree.missing),
                            followers={j.name for j in robot.joints if j.mimic is not None},
                            links={link.name for link in robot.links},
                            mujoco_check=check_attributes, world_root=build.at_world,
                            friction_links={link for link, value in declared.items()
                                            if value.isotropic},
                            friction_written=set(declared))


def write_assets(build: Build) -> None:
    """Write the meshes and materials the bodies use into ``<asset>`` (none: no section)."""
    build.notes.extend(build.meshes.said())
    asset = build.asset
    for element, attributes in build.meshes.elements():
        etree.SubElement(asset, element, attributes)
    for name, rgba in build.tree.materials.items():
        etree.SubElement(asset, 'material', name=name, rgba=fmt_vec(rgba))
    if not len(asset):
        build.document.remove(asset)


def copy_block(build: Build) -> None:
    """Copy the compiler, option and size of the URDF's ``<mujoco>`` block."""
    block = mujoco_block(build.robot)
    apply_block(block, build.document)
    if block is not None and importlib.util.find_spec('mujoco') is None:
        build.notes.append("the URDF's <mujoco> block was copied unchecked: MuJoCo checks it "
                           "when installed (pip install 'urdfgenpy_ros[engines]')")


def write_mimics(build: Build) -> None:
    """Write each mimic joint an equality; record the followers written."""
    build.carried.mimics = write_equalities(build.document, build.written)


def write_actuator_section(build: Build) -> None:
    """Write the actuators (declared, or the option's), and the rotors' armatures."""
    written, actuators = build.written, build.options.actuators
    build.chosen = chosen = declared_actuators(written, actuators)
    build.advice.extend(_check_gains(written, chosen, build.gains))
    write_actuators(build.document, chosen, *build.gains, defaults=(DEFAULT_KP, DEFAULT_KV))
    build.armatures = _armatures(build.worldbody)  # the <mujoco> block set them: the user's
    build.notes.extend(write_rotor_armatures(build.worldbody, written))
    build.advice += [NO_ACTUATORS] if not chosen and actuators is None else []


def carry_actuators(build: Build) -> None:
    """Record the command interfaces and transmissions the actuators carry."""
    written, actuators, carried = build.written, build.options.actuators, build.carried
    reductions = gears(written)
    made = {(actuator.joint.name, actuator.kind) for actuator in build.chosen}
    declared = build.chosen if actuators is None else declared_actuators(written, None)
    carried.replaced_by = actuators
    for actuator in declared:  # with --actuators, an interface of that kind is carried
        if actuator.origin is not None and (actuator.joint.name, actuator.kind) in made:
            carried.interfaces.add(actuator.origin)
    for actuator in build.chosen:
        if actuator.joint.name in reductions:
            carried.transmissions.add(reductions[actuator.joint.name][1])


def write_keyframe_section(build: Build) -> None:
    """Write the home keyframe, the robot at its initial joint values."""
    build.home = home_positions(build.tree, build.written, initial_values(build.written))
    write_keyframe(build.document, build.tree, build.home)


def write_sensor_section(build: Build) -> None:
    """Write the sensors MuJoCo has a counterpart for; record them."""
    build.carried.sensors = write_sensors(build.document, build.worldbody, build.written,
                                          build.carried.partly)


def merge_user_overlay(build: Build) -> None:
    """Merge the overlay file in by element name (its armatures are the user's)."""
    if build.options.overlay is None:
        return
    extra = read_overlay(build.options.overlay)
    build.armatures |= _armatures(extra)
    merge_overlay(build.document, extra)


def simulate(build: Build) -> None:
    """Say the gains; choose the integrator, place a floating base on the floor."""
    _note_gains(build.notes, build.document, build.gains)
    options = build.options
    placed = (options.scene and build.path is not None and build.taken == 'floating'
              and not build.at_world) and (build.robot.root.name, build.meshes,
                                           options.meshdir)
    _simulate(build.document, build.notes, {actuator.kind for actuator in build.chosen},
              build.gains[1].given, placed)


def stabilise_joints(build: Build) -> None:
    """Give stiff servos on light joints the armature that keeps them stable; advise."""
    added, unstable = stabilise(build.document, build.written, build.home, build.armatures)
    build.notes.extend(added)
    build.advice.extend(unstable + hold_keyframes(build.document, build.tree))
    build.notes.extend(build.advice)


def exclude_contacts(build: Build) -> None:
    """Exclude the contacts of touching bodies; say how many."""
    build.notes.append(write_excludes(build.document, build.meshes.contents(),
                                      build.meshdir))


def find_build_losses(build: Build) -> None:
    """Find what the MJCF cannot carry, at its source lines (errors with ``strict``)."""
    from urdfgenpy_ros.formats.xacro_source import in_source
    robot = build.robot
    file = robot.source.file if robot.source is not None else None
    findings = in_source(find_losses(robot, urdf_root(robot), file, build.carried), robot)
    if build.options.strict:
        findings = [ValidationError(finding.code, Severity.ERROR, finding.element,
                                    finding.location, finding.message, finding.hint)
                    for finding in findings]
    build.findings = findings


STAGES: tuple[Callable[[Build], None], ...] = (
    write_bodies, write_assets, copy_block, write_mimics, write_actuator_section,
    carry_actuators, write_keyframe_section, write_sensor_section, merge_user_overlay,
    simulate, stabilise_joints, exclude_contacts, find_build_losses)
"""The stages of the MJCF writer, in the order they run."""


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


def _check_gains(robot: Any, chosen: list[Any], gains: tuple[Gains, Gains]) -> list[str]:
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
