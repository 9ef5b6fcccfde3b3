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
Robots from parts: prefixed copies whose every reference follows, and parts attached.

Renaming a link or a joint must reach everything that names it: joint ends, mimic
targets, ``<gazebo reference>``, ``<transmission>`` and ``<ros2_control>`` joints, sensor
frames, and the joint and link names inside plugin parameters (``<left_joint>``,
``<joint_name>``, ``<child_frame_id>``, ...). All names change at once, from one map, so
a prefix never renames a name another rename has just produced.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.errors import ModelError
from urdfgenpy_ros.model.extensions import Extension
from urdfgenpy_ros.model.geometry import Origin
from urdfgenpy_ros.model.joint import Joint, JointMimic
from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.model.owned_names import set_name_only

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel, RobotT

_TOP_NAMES = ('transmission', 'ros2_control')  # blocks whose own name must be unique
_NAMED_INSIDE = ('actuator', 'sensor', 'gpio')  # names that must be unique robot-wide
_MODEL_TAGS = ('link', 'joint', 'material', 'gazebo', 'transmission', 'ros2_control')


@dataclass
class _Renaming:
    """Old name to new name, per kind; ``prefix`` also goes on block and sensor names."""

    links: dict[str, str] = field(default_factory=dict)
    joints: dict[str, str] = field(default_factory=dict)
    materials: dict[str, str] = field(default_factory=dict)
    prefix: str = ''

    def frame(self, name: str) -> str | None:
        """Return the new name of a link or joint (both get the same prefix), or None."""
        return self.links.get(name, self.joints.get(name))


def prefixed(robot: RobotT, prefix: str, *, materials: bool = False) -> RobotT:
    """
    Return a copy of ``robot`` with ``prefix`` before every link and joint name.

    Every reference follows (see the module's docstring). Transmission, actuator,
    ``<ros2_control>`` and sensor names get the prefix too, and so do sensors' relative
    topics, so two copies publish apart. Robot-level materials keep their names unless
    ``materials`` (an assembly shares identical ones and renames the others).
    """
    if not isinstance(prefix, str) or any(char.isspace() for char in prefix):
        raise ModelError(f'prefix {prefix!r}: a prefix is a string without spaces, e.g. '
                         "'left_'")
    renaming = _Renaming({link.name: prefix + link.name for link in robot.links},
                         {joint.name: prefix + joint.name for joint in robot.joints},
                         {m.name: prefix + m.name for m in _definitions(robot) if m.name}
                         if materials else {}, prefix)
    clone = copy.deepcopy(robot)
    if prefix:
        _rename(clone, renaming)
    return clone


def rename(robot: RobotModel, links: dict[str, str] | None = None,
           joints: dict[str, str] | None = None) -> None:
    """Rename links and joints of ``robot`` in place (old -> new); every reference follows."""
    _rename(robot, _Renaming(links or {}, joints or {}))


def _rename(robot: RobotModel, renaming: _Renaming) -> None:
    """Apply ``renaming`` to ``robot`` in place, every reference included."""
    for link in robot.links:
        set_name_only(link, renaming.links.get(link.name, link.name))
        for sensor in link.sensors:
            _rename_sensor(sensor, renaming)
    for joint in robot.joints:
        set_name_only(joint, renaming.joints.get(joint.name, joint.name))
        joint.parent = renaming.links.get(joint.parent, joint.parent)
        joint.child = renaming.links.get(joint.child, joint.child)
        mimic = joint.mimic
        if mimic is not None and mimic.joint in renaming.joints:
            joint.mimic = JointMimic(renaming.joints[mimic.joint], mimic.multiplier,
                                     mimic.offset, source=mimic.source, extras=mimic.extras)
        for sensor in joint.sensors:
            _rename_sensor(sensor, renaming)
    robot._reindex()
    if renaming.materials:
        robot._rename_materials(renaming.materials)
    for block in _blocks(robot):
        _rename_block(block.element, renaming)
    extras = robot.extras
    if extras is not None:  # urdfdom's <sensor> (<parent link="...">), vendor elements
        # a copy's source tree and its list of items hold separate copies of such nodes
        kept = {id(node): node for node in [*extras.node, *(extras.order or [])]
                if isinstance(getattr(node, 'tag', None), str) and node.tag not in _MODEL_TAGS}
        for node in kept.values():
            _rename_block(node, renaming)


def _rename_sensor(sensor: Any, renaming: _Renaming) -> None:
    if sensor.frame is not None:
        sensor.frame = renaming.frame(sensor.frame) or sensor.frame
    if renaming.prefix:
        if sensor.topic is not None and not sensor.topic.startswith('/'):
            sensor.topic = renaming.prefix + sensor.topic
        sensor.name = renaming.prefix + sensor.name


def _blocks(robot: RobotModel) -> list[Extension]:
    owners: list[Any] = [*robot.links, *robot.joints]
    return [*robot.extensions, *(block for owner in owners for block in owner.extensions)]


# Words in a plugin element's tag that say its text is no link or joint, even when it is
# spelt like one (<topicName>trunk</topicName>, <robotNamespace>, <ros><remapping>)
_NOT_FRAMES = ('topic', 'namespace', 'service', 'remap', 'filename', 'uri', 'plugin')


def _names_no_frame(tag: str) -> bool:
    lowered = tag.lower()
    return any(word in lowered for word in _NOT_FRAMES)


def _rename_block(root: Any, renaming: _Renaming) -> None:
    """Rename the links and joints a ``<gazebo>``/``<transmission>``/... block names."""
    prefix = renaming.prefix
    if prefix and root.tag in _TOP_NAMES and root.get('name'):
        root.set('name', prefix + root.get('name'))
    for element in root.iter():
        if not isinstance(element.tag, str):
            continue
        reference = element.get('reference')
        if reference is not None and renaming.frame(reference) is not None:
            element.set('reference', renaming.frame(reference))
        name = element.get('name')
        # <joint name> anywhere; in transmissions, any element naming a joint (PR2's
        # <rollJoint name>, <gap_joint name>, <passive_joint name>)
        if name in renaming.joints and (element.tag == 'joint' or root.tag == 'transmission'):
            element.set('name', renaming.joints[name])
        elif prefix and name and (element.tag in _NAMED_INSIDE or (
                root.tag == 'transmission' and element.tag.endswith('Actuator'))):
            element.set('name', prefix + name)  # PR2's <rightActuator>, <leftActuator> too
        link = element.get('link')
        if element.tag in ('parent', 'child') and link in renaming.links:
            element.set('link', renaming.links[link])
        if len(element) == 0 and element.text is not None and not _names_no_frame(element.tag):
            text = element.text.strip()
            renamed = renaming.frame(text)
            if renamed is not None:
                element.text = element.text.replace(text, renamed)
            elif prefix and element.tag == 'topic' and text and not text.startswith('/') \
                    and element.getparent() is not None \
                    and element.getparent().tag == 'sensor':
                element.text = element.text.replace(text, prefix + text)


def _definitions(robot: RobotModel) -> list[Material]:
    """Return the materials ``robot`` defines: robot-level, then those visuals define."""
    found = {material.name: material for material in robot.materials}
    for link in robot.links:
        for visual in link.visuals:
            material = visual.material
            if material is not None and not material.is_reference:
                found.setdefault(material.name, material)
    return list(found.values())


def attach(base: RobotT, part: RobotModel, at: str, origin: Origin | None = None,
           prefix: str = '', joint_name: str | None = None, joint_type: str = 'fixed',
           **joint_options: Any) -> RobotT:
    """
    Join a prefixed copy of ``part`` to ``base``'s link ``at``; return ``base``.

    See :meth:`urdfgenpy_ros.robot.Robot.attach`. Nothing changes when it is refused.
    """
    where = f'cannot attach {part.name!r} to {base.name!r}'
    if not base.has_link(at):
        from urdfgenpy_ros.model import _suggest
        raise ModelError(f'{where}: link {at!r} is not in {base.name!r}'
                         f'{_suggest(at, [link.name for link in base.links])} '
                         '(name a link of the base, with its prefix if it has one)')
    piece = prefixed(part, prefix)
    root = piece.root.name
    name = joint_name or f'{at}_to_{root}'
    taken = _clashes(base, piece, name)
    if taken:
        shown = ', '.join(taken[:8]) + (f' and {len(taken) - 8} more' if len(taken) > 8 else '')
        if len(taken) == 1 and taken[0].endswith('(the joint that attaches the part)'):
            fix = 'choose another joint_name'
        else:
            hint = f"prefix='{part.name}_'" if not prefix else 'another prefix'
            fix = f'give the part {hint}, or pass joint_name= for the joint that attaches it'
        count = '1 name' if len(taken) == 1 else f'{len(taken)} names'
        raise ModelError(f'{where}: {count} taken: {shown} ({fix})')
    mount = Joint(name, joint_type, at, root, origin=origin or Origin(), **joint_options)
    _merge_materials(base, piece, prefix or f'{part.name}_')
    for link in piece.links:
        base.add_link(link)
    base.add_joint(mount)
    for joint in piece.joints:
        base.add_joint(joint)
    base.extensions.extend(piece.extensions)
    base.extensions.extend(_unknown_elements(piece))
    base.included_files = list(dict.fromkeys([*base.included_files, *piece.included_files]))
    base.read_warnings.extend(piece.read_warnings)
    return base


def _unknown_elements(piece: RobotModel) -> list[Extension]:
    """Return the part's top-level elements the model does not hold, to keep them."""
    if piece.extras is None:
        return []
    return [Extension(copy.deepcopy(node)) for node in piece.extras.unknown_elements()]


def _clashes(base: RobotModel, piece: RobotModel, joint_name: str) -> list[str]:
    taken = [f'link {link.name!r}' for link in piece.links if base.has_link(link.name)]
    joints = [joint.name for joint in piece.joints]
    taken += [f'joint {name!r}' for name in joints if base.has_joint(name)]
    if base.has_joint(joint_name) or joint_name in joints:
        taken.append(f'joint {joint_name!r} (the joint that attaches the part)')
    named = {(block.tag, block.name) for block in base.extensions if block.tag in _TOP_NAMES}
    taken += [f'{block.tag} {block.name!r}' for block in piece.extensions
              if (block.tag, block.name) in named]
    return taken


def _merge_materials(base: RobotModel, piece: RobotModel, prefix: str) -> None:
    """Share the part's materials that equal the base's; rename those that differ."""
    ours = {material.name: material for material in _definitions(base)}
    theirs = _definitions(piece)
    names = {material.name for material in [*ours.values(), *theirs]}
    renames: dict[str, str] = {}
    for material in theirs:
        if not material.name:
            continue  # an unnamed inline colour: nothing refers to it
        known = ours.get(material.name)
        if known is not None and (known.rgba, known.texture) != (
                material.rgba, material.texture):
            new, number = prefix + material.name, 2
            while new in names:
                new, number = f'{prefix}{material.name}_{number}', number + 1
            names.add(new)
            renames[material.name] = new
    if renames:
        piece._rename_materials(renames)
    for material in piece.materials:
        if base.has_material(material.name):
            shared = base.get_material(material.name)
            for link in piece.links:
                for visual in link.visuals:
                    if visual.material is material:
                        visual.material = shared
        else:
            base.add_material(material)
