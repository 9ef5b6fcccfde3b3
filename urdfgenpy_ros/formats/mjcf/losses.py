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
What an MJCF model cannot carry of the URDF, each a located finding (M801-M808).

The whole file is walked, element by element and attribute by attribute, against one
table of what the MJCF writer carries (``CARRIED``); what is not in it is a finding in
``check``'s format. Blocks whose meaning depends on their content (``<gazebo>``,
``<transmission>``, ``<ros2_control>``) are judged by what the writer made of them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.errors import SourceLocation, ValidationError
from urdfgenpy_ros.model.findings import Findings

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

# tag -> (attributes carried, children carried); '*' children: judged by a handler
CARRIED: dict[str, tuple[frozenset[str], frozenset[str]]] = {
    name: (frozenset(attributes.split()), frozenset(children.split()))
    for name, attributes, children in (
        ('robot', 'name version', 'link joint material gazebo transmission ros2_control '
                                  'mujoco'),
        ('link', 'name', 'inertial visual collision'),
        ('inertial', '', 'origin mass inertia'),
        ('origin', 'xyz rpy quat_xyzw', ''),
        ('mass', 'value', ''),
        ('inertia', 'ixx ixy ixz iyy iyz izz', ''),
        ('visual', 'name', 'origin geometry material'),
        ('collision', 'name', 'origin geometry'),
        ('geometry', '', 'box cylinder sphere mesh capsule'),
        ('box', 'size', ''), ('cylinder', 'radius length', ''), ('sphere', 'radius', ''),
        ('capsule', 'radius length', ''), ('mesh', 'filename scale', ''),
        ('material', 'name', 'color'), ('color', 'rgba', ''),
        ('joint', 'name type', 'origin parent child axis limit dynamics mimic'),
        ('parent', 'link', ''), ('child', 'link', ''), ('axis', 'xyz', ''),
        ('limit', 'lower upper effort', ''), ('dynamics', 'damping friction', ''),
        ('mimic', 'joint multiplier offset', ''),
    )}

HINTS = {
    'M801': 'MJCF has no joint velocity limit: limit it in the controller (a velocity '
            "actuator's ctrlrange), or accept it",
    'M802': 'MJCF has no soft limits: tune the joint range or solref/solimp by hand',
    'M803': 'MJCF has no calibration references: set the home keyframe by hand if needed',
    'M804': 'the stand-in moves as the URDF joint does; check its names in your code',
    'M805': 'MuJoCo drives joints through <actuator>: add one in an overlay if needed',
    'M806': 'Gazebo-only: give MuJoCo its counterpart in an overlay (--overlay)',
    'M807': 'MJCF has no place for it: carry it in an overlay if the simulation needs it',
    'M808': "MuJoCo's schema has no such attribute: fix the spelling",
    'M809': 'the model has no such geom: make the mesh available, or convert it',
}


@dataclass
class Carried:
    """What the writer made of the blocks whose meaning depends on their content."""

    friction_links: set[str] = field(default_factory=set)  # mu1 (and an equal mu2) carried
    friction_written: set[str] = field(default_factory=set)  # links given mu1 as friction
    transmissions: set[Any] = field(default_factory=set)  # the mapped ones: a number, or
    # (ros2_control block, element number) for one inside <ros2_control>
    interfaces: set[tuple[int, int]] = field(default_factory=set)  # (block, element number)
    sensors: set[str] = field(default_factory=set)  # names of the <sensor>s written
    partly: dict[str, str] = field(default_factory=dict)  # sensor -> what was left out
    stand_ins: dict[str, str] = field(default_factory=dict)
    missing: dict[str, tuple[str, str]] = field(default_factory=dict)  # mesh URI -> why
    # not written, and the fix
    followers: set[str] = field(default_factory=set)
    links: set[str] = field(default_factory=set)
    mimics: set[str] = field(default_factory=set)  # followers written as equalities
    replaced_by: str | None = None  # the actuators option that replaced the declared ones
    world_root: bool = False  # the root link is 'world': MuJoCo's world body, no inertial
    mujoco_check: Callable[[Any], list[tuple[str, str]]] | None = None


class Losses:
    """Collect the findings while walking the URDF document."""

    def __init__(self, robot: RobotModel, file: str | None, carried: Carried) -> None:
        self.file = file
        self.carried = carried
        self.findings = Findings(robot)

    def add(self, code: str, node: Any, element: str, message: str,
            hint: str | None = None) -> None:
        """Record a finding about ``node`` (an lxml element) of the document."""
        line = node.sourceline if self.file is not None else None
        self.findings.add(code, SourceLocation(self.file, line), element, _path(node),
                          message, hint or HINTS[code], str(node.tag))


def _path(node: Any) -> str:
    """Return the element path (``/robot/joint[@name='elbow']/limit``), as check's."""
    parts = []
    while node is not None:
        name = node.get('name') or node.get('reference')
        root = node.getparent() is None
        parts.append(f"{node.tag}[@name='{name}']" if name and not root else str(node.tag))
        node = node.getparent()
    return '/' + '/'.join(reversed(parts))


def _owner(node: Any) -> str:
    """Return the finding's element: the nearest named link, joint or block."""
    while node is not None:
        if node.tag in ('link', 'joint') and node.getparent() is not None \
                and node.getparent().tag == 'robot':
            return f"{node.tag} {node.get('name')!r}"
        if node.tag in ('gazebo', 'transmission', 'ros2_control', 'material', 'mujoco') \
                and node.getparent() is not None and node.getparent().tag == 'robot':
            name = node.get('name') or node.get('reference')
            return f'<{node.tag}>' + (f' {name!r}' if name else '')
        node = node.getparent()
    return 'robot'


def find_losses(robot: RobotModel, root: Any, file: str | None, carried: Carried
                ) -> list[ValidationError]:
    """Return one finding per element or attribute of ``robot``'s URDF ``root`` not carried."""
    losses = Losses(robot, file, carried)
    _walk(root, losses)
    return losses.findings.items


def _walk(node: Any, losses: Losses) -> None:
    tag = node.tag
    if not isinstance(tag, str):
        return  # comments and processing instructions say nothing to a simulator
    parent = node.getparent()
    special = {'gazebo': _gazebo, 'transmission': _transmission,
               'ros2_control': _ros2_control, 'mujoco': _mujoco}
    if parent is not None and parent.tag == 'robot' and tag in special:
        special[tag](node, losses)
        return
    owner = _owner(node)
    if tag == 'joint' and parent is not None and parent.tag == 'robot':
        _joint(node, losses, owner)
    attributes, children = CARRIED.get(tag, (frozenset(), frozenset()))
    for name, value in node.attrib.items():
        if name.startswith('{'):
            continue  # namespaced attributes belong to other tools (xacro's, say)
        if name not in attributes and not (tag == 'limit' and name == 'velocity'):
            losses.add('M807', node, owner, f'<{tag} {name}="{value}"> has no MJCF '
                       'counterpart')
    if tag == 'limit':
        _limit(node, losses, owner)
    if tag == 'mimic' and parent is not None and parent.get('name') not in \
            losses.carried.mimics:
        losses.add('M807', node, owner, f"<mimic joint=\"{node.get('joint')}\"> is not "
                   'carried: MuJoCo couples two joints that each move along one axis')
    if tag == 'inertial' and losses.carried.world_root and owner == "link 'world'":
        losses.add('M807', node, owner, "<inertial> of the root link 'world' is not carried: "
                   "MuJoCo's world body has no mass")
        return
    if tag in SIZES and not _positive(node.get(SIZES[tag], '')):
        losses.add('M809', node, owner, f'<{tag} {SIZES[tag]}="{node.get(SIZES[tag])}"> has '
                   'a size of zero: MuJoCo refuses such a geom, so it is not written')
    if tag == 'mesh' and node.get('filename') in losses.carried.missing:
        why, fix = losses.carried.missing[node.get('filename')]
        losses.add('M809', node, owner, f"mesh {node.get('filename')!r} not written, nor its "
                   f'geom: {why}', fix)
    for child in node:
        if not isinstance(child.tag, str):
            continue
        if child.tag in children:
            _walk(child, losses)
        elif child.tag in ('safety_controller', 'calibration') and tag == 'joint':
            code = 'M802' if child.tag == 'safety_controller' else 'M803'
            losses.add(code, child, owner, f'<{child.tag}> is not carried')
        elif child.tag == 'texture' and tag == 'material':
            losses.add('M807', child, owner, f"<texture filename=\"{child.get('filename')}\">"
                       ' is not carried (colours are)')
        else:
            losses.add('M807', child, owner, f'<{child.tag}> has no MJCF counterpart')


SIZES = {'box': 'size', 'sphere': 'radius', 'cylinder': 'radius', 'capsule': 'radius'}


def _positive(text: str) -> bool:
    try:
        return all(float(value) > 0.0 for value in text.split())
    except ValueError:
        return True  # the reader said what is wrong with it


def _joint(node: Any, losses: Losses, owner: str) -> None:
    name = node.get('name', '')
    if name in losses.carried.stand_ins:
        losses.add('M804', node, owner, f"{node.get('type')} joint written as "
                   f'{losses.carried.stand_ins[name]}')


def _limit(node: Any, losses: Losses, owner: str) -> None:
    velocity = node.get('velocity')
    if velocity is not None:
        losses.add('M801', node, owner, f'velocity limit {velocity} is not carried')
    joint = node.getparent()
    kind = joint.get('type') if joint is not None else None
    effort = node.get('effort')
    try:
        if effort is not None and not float(effort) > 0.0:
            losses.add('M807', node, owner, f'effort limit {effort} is not written (MuJoCo '
                       'needs a positive actuatorfrcrange; the joint has no force limit)')
        if kind in ('revolute', 'prismatic') and float(node.get('lower', '0')) >= \
                float(node.get('upper', '0')):
            losses.add('M807', node, owner, f"range [{node.get('lower', '0')}, "
                       f"{node.get('upper', '0')}] is empty: MuJoCo has no such range, the "
                       'joint is written without one')
    except ValueError:
        pass


def _gazebo(node: Any, losses: Losses) -> None:
    reference = node.get('reference')
    owner = _owner(node)
    for child in node:
        if not isinstance(child.tag, str):
            continue
        if child.tag in ('mu1', 'mu2') and reference in losses.carried.friction_links:
            continue
        if child.tag == 'mu1' and reference in losses.carried.friction_written:
            continue
        if child.tag == 'mu2' and reference in losses.carried.friction_written:
            losses.add('M806', child, owner, f'<mu2> {(child.text or "").strip()} is not '
                       "carried: MuJoCo's sliding friction is one number for both "
                       f"directions, and <mu1> {(node.findtext('mu1') or '').strip()} is it")
            continue
        if child.tag in ('preserveFixedJoint', 'disableFixedJointLumping'):
            continue  # honoured when fixed links are fused
        if child.tag == 'sensor' and child.get('name') in losses.carried.sensors:
            left = losses.carried.partly.get(child.get('name'))
            if left:
                losses.add('M806', child, owner, f"<sensor name=\"{child.get('name')}\">: "
                           + left)
            continue
        what = (f"<plugin filename=\"{child.get('filename')}\">" if child.tag == 'plugin'
                else f"<sensor type=\"{child.get('type')}\">" if child.tag == 'sensor'
                else f'<{child.tag}>')
        losses.add('M806', child, owner, f'{what} is not carried')


def _number(node: Any) -> int:
    """Return the number of ``node`` among the robot's blocks of its tag."""
    return [child for child in node.getparent() if child.tag == node.tag].index(node)


def _transmission(node: Any, losses: Losses) -> None:
    if _number(node) not in losses.carried.transmissions:
        joints = ', '.join(repr(joint.get('name')) for joint in node.findall('joint'))
        losses.add('M805', node, _owner(node), f'maps to no actuator (joint {joints or "none"}'
                   ' has no actuator in the MJCF)')


def _ros2_control(node: Any, losses: Losses) -> None:
    owner = _owner(node)
    number, elements = _number(node), list(node.iter())
    for child in node:
        if not isinstance(child.tag, str):
            continue
        if child.tag == 'transmission':
            if (number, elements.index(child)) not in losses.carried.transmissions:
                joints = ', '.join(repr(joint.get('name')) for joint in child.findall('joint'))
                losses.add('M805', child, owner, f'<transmission> maps to no actuator (joint '
                           f'{joints or "none"} has no actuator in the MJCF)',
                           "its mechanical_reduction becomes the gear of the joint's "
                           'actuator: declare a command interface for the joint, or pass '
                           '--actuators')
            continue
        if child.tag != 'joint':
            losses.add('M805', child, owner, f'<{child.tag}> has no MJCF counterpart '
                       '(MuJoCo simulates the joints itself)')
            continue
        follower = child.get('name') in losses.carried.followers
        for interface in child:
            if not isinstance(interface.tag, str) or interface.tag != 'command_interface':
                continue  # state interfaces: MuJoCo's joint state; params: read with them
            if (number, elements.index(interface)) in losses.carried.interfaces or follower:
                continue
            replaced = losses.carried.replaced_by
            losses.add('M805', interface, owner, 'command interface '
                       f"{interface.get('name')!r} of joint {child.get('name')!r} became no "
                       'actuator' + (f' (--actuators / actuators={replaced!r} put a '
                                     f'{replaced} actuator on every joint instead)'
                                     if replaced else ''))


def _mujoco(node: Any, losses: Losses) -> None:
    owner = _owner(node)
    check = losses.carried.mujoco_check
    for child in node:
        if not isinstance(child.tag, str):
            continue
        if child.tag not in ('compiler', 'option', 'size'):
            losses.add('M807', child, owner, f'<{child.tag}> in <mujoco> is not carried '
                       '(compiler, option and size are)')
            continue
        for _, message in (check(child) if check is not None else []):
            losses.add('M808', child, owner, message)
