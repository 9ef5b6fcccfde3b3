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
``<gazebo>`` blocks in SDF, placed where libsdformat's URDF conversion places them.

One table names each URDF element the conversion understands, where the SDF holds it and
how its text becomes SDF text (libsdformat's parser_urdf.cc: ParseSDFExtension and the
InsertSDFExtension* functions). Any other element of a block is copied as it is: into the
link or joint its ``reference`` names, into the model without one. Link settings of a
block whose link was merged into its parent (a fixed joint) go to that parent; its
collision and visual settings go nowhere, as in libsdformat. :func:`gazebo_losses` names
every element the SDF does not carry, and why.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
import copy
from typing import Any, NamedTuple, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.model.errors import ModelError, SourceLocation
from urdfgenpy_ros.model.floats import fmt

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.model.extensions import Extension
    from urdfgenpy_ros.model.link import Link

_TRUE = ('true', 'yes', '1')
MATERIAL_SCRIPTS = 'file://media/materials/scripts/gazebo.material'


def _number(text: str) -> tuple[str, ...]:
    return (fmt(float(text)),)


def _flag(text: str) -> tuple[str, ...]:
    return ('true' if text.lower() in _TRUE else 'false',)


class Setting(NamedTuple):
    """Where an element of a ``<gazebo>`` block goes: on what, at which paths, as what."""

    on: str  # 'link', 'collision', 'visual', 'joint' or 'model'
    places: tuple[str, ...]
    value: Callable[[str], tuple[str, ...]]


SETTINGS: dict[str, Setting] = {
    'mu1': Setting('collision', ('surface/friction/ode/mu',), _number),
    'mu2': Setting('collision', ('surface/friction/ode/mu2',), _number),
    'fdir1': Setting('collision', ('surface/friction/ode/fdir1',), lambda text: (text,)),
    'kp': Setting('collision', ('surface/contact/ode/kp',), _number),
    'kd': Setting('collision', ('surface/contact/ode/kd',), _number),
    'maxVel': Setting('collision', ('surface/contact/ode/max_vel',), _number),
    'minDepth': Setting('collision', ('surface/contact/ode/min_depth',), _number),
    'laserRetro': Setting('collision', ('laser_retro',), _number),
    'maxContacts': Setting('collision', ('max_contacts',), lambda text: (str(int(text)),)),
    'material': Setting('visual', ('material/script/name', 'material/script/uri'),
                        lambda text: (text, MATERIAL_SCRIPTS)),
    'turnGravityOff': Setting('link', ('gravity',), lambda text: (
        'true' if text.lower() in ('false', 'no', '0') else 'false',)),
    'dampingFactor': Setting('link', ('velocity_decay/linear', 'velocity_decay/angular'),
                             lambda text: _number(text) * 2),
    'selfCollide': Setting('link', ('self_collide',), lambda text: (
        '1' if text.lower() in _TRUE else '0',)),
    'stopCfm': Setting('joint', ('physics/ode/limit/cfm',), _number),
    'stopErp': Setting('joint', ('physics/ode/limit/erp',), _number),
    'springReference': Setting('joint', ('axis/dynamics/spring_reference',), _number),
    'springStiffness': Setting('joint', ('axis/dynamics/spring_stiffness',), _number),
    'fudgeFactor': Setting('joint', ('physics/ode/fudge_factor',), _number),
    'provideFeedback': Setting('joint', ('physics/provide_feedback',
                                         'physics/ode/provide_feedback'), lambda text: _flag(
        text) * 2),
    'implicitSpringDamper': Setting('joint', ('physics/ode/implicit_spring_damper',
                                              'physics/ode/cfm_damping'),
                                    lambda text: _flag(text) * 2),
    'static': Setting('model', ('static',), _flag),
}
"""Each element libsdformat's URDF conversion reads from a ``<gazebo>`` block."""
SETTINGS['cfmDamping'] = SETTINGS['implicitSpringDamper']  # its older name
SHAPE_BLOCKS = {'collision': 'collision', 'visual': 'visual'}  # children copied into each
CONTROLS = ('preserveFixedJoint', 'disableFixedJointLumping', 'canonicalBody')
"""Elements that steer the conversion (lumping) and are written nowhere."""


def text_of(element: Any) -> str:
    """Return an element's value as libsdformat reads it: ``value=``, else its text."""
    value = element.get('value')
    return (value if value is not None else element.text or '').strip()


def children(block: Extension) -> Iterator[Any]:
    """Yield the elements of a block (comments aside)."""
    return (child for child in block.element if isinstance(child.tag, str))


def _put(target: Any, path: str, text: str) -> None:
    node = target
    for tag in path.split('/'):
        found = node.find(tag)
        node = found if found is not None else etree.SubElement(node, tag)
    node.text = text


def _apply(target: Any, child: Any, setting: Setting, block: Extension) -> None:
    try:
        values = setting.value(text_of(child))
    except ValueError:
        where = _location(block, child)
        raise ModelError(f'{where}: <gazebo> <{child.tag}> {text_of(child)!r} is not a '
                         'number, which libsdformat refuses: write a number') from None
    for path, value in zip(setting.places, values):
        _put(target, path, value)


def _location(block: Extension, child: Any) -> SourceLocation:
    source = block.source if isinstance(block.source, SourceLocation) else SourceLocation()
    line = child.sourceline if source.line is not None else None
    where = (f"/robot/gazebo[@reference='{block.reference}']" if block.reference is not None
             else '/robot/gazebo')
    return SourceLocation(source.file, line, None, source.path or f'{where}/{child.tag}')


def apply_blocks(target: Any, blocks: list[Extension], on: str, own: str | None) -> None:
    """
    Write ``blocks``' settings for an ``on`` element (link, joint, model) into ``target``.

    Link, joint and model elements also get the elements the table does not name. A link
    block whose ``reference`` is not ``own`` came from a link merged into this one. Each
    model block sets ``<static>``, false unless it says otherwise, as libsdformat does.
    """
    for block in blocks:
        if on == 'model':
            _put(target, 'static', 'false')
        for child in children(block):
            setting = SETTINGS.get(child.tag)
            if setting is not None:
                if setting.on == on:
                    _apply(target, child, setting, block)
            elif child.tag not in CONTROLS and child.tag not in SHAPE_BLOCKS:
                target.append(copy.deepcopy(child))


LUMP = '_fixed_joint_lump__'


def takes(link: str, shape: str | None, kind: str, reference: str | None) -> bool:
    """
    Return whether libsdformat gives a ``kind`` shape the settings of a ``reference`` block.

    It names the shape ``NAME_collision`` (NAME: the URDF name, else its link's), with
    ``LINK_fixed_joint_lump__`` before it when that does not start with the link's name;
    the link's own blocks go to the shapes without that prefix, a merged link's blocks to
    the shapes the prefix gives that merged link's name.
    """
    name = f'{shape or link}_{kind}'
    if not name.startswith(link):
        name = f'{link}{LUMP}{name}'
    if reference is None or reference == link:  # a block added to the link in Python
        return LUMP not in name
    return f'{LUMP}{reference}_{kind}' in name


def apply_shape_blocks(target: Any, blocks: list[Extension], kind: str, link: str,
                       shape: str | None) -> None:
    """Write the settings of the blocks libsdformat gives a ``kind`` shape into ``target``."""
    replaced = 'surface' if kind == 'collision' else 'material'
    for block in blocks:
        if not takes(link, shape, kind, block.reference):
            continue
        for child in children(block):
            if child.tag != kind:
                continue
            for part in child:
                if not isinstance(part.tag, str):
                    continue
                if part.tag == replaced:
                    for old in target.findall(replaced):
                        target.remove(old)
                target.append(copy.deepcopy(part))
        for child in children(block):
            setting = SETTINGS.get(child.tag)
            if setting is not None and setting.on == kind:
                _apply(target, child, setting, block)


class Loss(NamedTuple):
    """An element of a ``<gazebo>`` block the SDF does not carry, and why."""

    location: SourceLocation
    reference: str | None
    tag: str
    why: str
    lost: bool = True  # else kept, but for nothing (a material script)

    def __str__(self) -> str:
        """Return the one line that says it."""
        block = (f'<gazebo reference={self.reference!r}>' if self.reference is not None
                 else '<gazebo>')
        lost = (': it is not in the SDF' if self.lost else
                ' (give the visual a <material> colour, which Gazebo Sim renders)')
        return f'{self.location}: warning: {block} <{self.tag}>: {self.why}{lost}'


def _link_losses(robot: RobotModel, losses: list[Loss]) -> None:
    for link in robot.links:
        for block in link.extensions:
            if block.tag != 'gazebo':
                continue
            for child in children(block):
                why = _why_lost(link, block, child)
                if why is not None:
                    losses.append(Loss(_location(block, child), block.reference, child.tag,
                                       why))


def _why_lost(link: Link, block: Extension, child: Any) -> str | None:
    setting = SETTINGS.get(child.tag)
    on = setting.on if setting is not None else SHAPE_BLOCKS.get(child.tag)
    if on in ('joint', 'model'):
        return f'a {on} setting, which a link block does not set'
    if on not in ('collision', 'visual'):
        return None
    shapes = link.collisions if on == 'collision' else link.visuals
    if any(takes(link.name, shape.name, on, block.reference) for shape in shapes):
        return None
    if block.reference not in (None, link.name):
        return (f'its link is merged into {link.name!r} (fixed joint) and none of its '
                f'{on}s keeps a name libsdformat gives it to (name them after the link, or '
                'keep the joint with <preserveFixedJoint>)')
    if not shapes:
        return f'link {link.name!r} has no <{on}> to take it'
    return (f'libsdformat gives it to no {on} of {link.name!r}: their names do not start '
            "with the link's (rename them)")


def _other_losses(robot: RobotModel, gone: list[str], losses: list[Loss]) -> None:
    for joint in robot.joints:
        for block in joint.extensions:
            for child in children(block):
                setting = SETTINGS.get(child.tag)
                on = setting.on if setting is not None else SHAPE_BLOCKS.get(child.tag)
                if on is not None and on != 'joint':
                    losses.append(Loss(_location(block, child), block.reference, child.tag,
                                       f'a {on} setting, which a joint block does not set'))
    for block in robot.extensions:
        if block.tag != 'gazebo':
            continue
        for child in children(block):
            setting = SETTINGS.get(child.tag)
            on = setting.on if setting is not None else SHAPE_BLOCKS.get(child.tag)
            if block.reference is not None and block.reference in gone:
                why = f'{block.reference!r} is a fixed joint merged away'
            elif block.reference is not None:
                why = f'there is no link or joint {block.reference!r}'
            elif on is not None and on != 'model':
                why = f'a {on} setting in a block without reference, which sets none'
            else:
                continue
            if child.tag not in CONTROLS:
                losses.append(Loss(_location(block, child), block.reference, child.tag, why))


def gazebo_losses(merged: RobotModel, gone: list[str]) -> list[Loss]:
    """
    Return each ``<gazebo>`` element the SDF of ``merged`` does not carry.

    ``merged`` is the robot as written (links on fixed joints merged, their blocks moved
    to the parent); ``gone`` names the fixed joints merged away, whose blocks went to
    the robot.
    """
    losses: list[Loss] = []
    _link_losses(merged, losses)
    _other_losses(merged, gone, losses)
    return losses


def script_notes(merged: RobotModel) -> list[Loss]:
    """Return one line per Gazebo-classic material script the SDF keeps for no renderer."""
    notes = []
    for link in merged.links:
        for block in link.extensions:
            if block.reference not in (None, link.name) or not link.visuals:
                continue
            for child in children(block):
                if child.tag == 'material':
                    notes.append(Loss(_location(block, child), block.reference, child.tag, (
                        f'the material script {text_of(child)!r} stays in the SDF, as '
                        'libsdformat keeps it, but Gazebo Sim renders no Gazebo-classic '
                        'script'), False))
    return notes
