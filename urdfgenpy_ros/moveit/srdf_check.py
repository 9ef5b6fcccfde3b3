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
Does an SRDF still match its robot? Findings at the SRDF's own lines.

K901 a name the robot does not have (a link renamed since, say); K902 a chain group whose
base is not above its tip; K903 a group state value outside the joint's limits; K904 a
pair disabled as "Never" in collision that is in contact in some of ``samples`` random
states (with its rate); K905 a disabled pair naming a link without collision geometry.
"""

from __future__ import annotations

import difflib
from os import PathLike
import re
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.dynamics import compiled
from urdfgenpy_ros.model.codes import severity_of
from urdfgenpy_ros.model.errors import (ParseError, SourceLocation, UrdfgenpyError,
                                        ValidationError)
from urdfgenpy_ros.moveit import sampling
from urdfgenpy_ros.moveit.collision_matrix import CHUNK, pair
from urdfgenpy_ros.moveit.contacts import Pair, ShapeSet
from urdfgenpy_ros.moveit.shapes import link_shapes

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

# (element, attribute): the kind of name it holds
_LINKS = (('disable_collisions', 'link1'), ('disable_collisions', 'link2'),
          ('chain', 'base_link'), ('chain', 'tip_link'), ('end_effector', 'parent_link'),
          ('virtual_joint', 'child_link'), ('link', 'name'))
_JOINTS = (('joint', 'name'), ('passive_joint', 'name'))
_GROUPS = (('group_state', 'group'), ('end_effector', 'group'),
           ('end_effector', 'parent_group'))


_SRDF = ('group', 'group_state', 'end_effector', 'virtual_joint', 'passive_joint',
         'disable_collisions', 'enable_collisions', 'disable_default_collisions',
         'link_sphere_approximation', 'joint_property')


def start_tags(text: str, root: Any) -> dict[Any, tuple[int, int]]:
    """
    Return each element's line and column: where its start tag ``<tagname`` begins.

    lxml gives the line where a start tag ends; the tags are found in the text instead
    (comments blanked), the k-th ``<tag`` being the k-th element of that tag.
    """
    blank = re.sub(r'<!--.*?-->|<!\[CDATA\[.*?\]\]>',
                   lambda match: re.sub(r'[^\n]', ' ', match.group()), text, flags=re.S)
    places: dict[Any, tuple[int, int]] = {}
    for tag in {element.tag for element in root.iter() if isinstance(element.tag, str)}:
        starts = [match.start() for match in re.finditer(
            f'<{re.escape(tag)}(?=[\\s/>])', blank)]
        elements = list(root.getroottree().iter(tag))
        if len(starts) != len(elements):
            continue  # an entity or a namespace prefix: lxml's line, column 1
        for element, start in zip(elements, starts):
            places[element] = (blank.count('\n', 0, start) + 1,
                               start - blank.rfind('\n', 0, start))
    return places


class _Findings(list):
    """The findings of one SRDF file."""

    def __init__(self, path: str, places: dict[Any, tuple[int, int]]) -> None:
        super().__init__()
        self.path = path
        self.places = places

    def add(self, code: str, element: Any, what: str, message: str, hint: str) -> None:
        line, column = self.places.get(element, (element.sourceline, None))
        where = SourceLocation(self.path, line, column, None)
        self.append(ValidationError(code, severity_of(code), what, where, message, hint))


def _is_srdf(root: Any) -> bool:
    """Return whether ``root`` is an SRDF's: ``<robot>`` without URDF links or Xacro."""
    if root.tag != 'robot':
        return False
    tags = {child.tag for child in root if isinstance(child.tag, str)}
    urdf = bool(tags & {'link', 'joint'}) or any(tag.startswith('{') for tag in tags)
    return not urdf or bool(tags & set(_SRDF))


def check_srdf(robot: RobotModel, path: str | PathLike[str], samples: int = 10000, seed: int = 0,
               search_paths: Any = ()) -> list[ValidationError]:
    """Return the findings of the SRDF at ``path`` against ``robot`` (see the module)."""
    root, text = read_srdf(path)
    found = _Findings(str(path), start_tags(text, root))
    _names(robot, root, found)
    _chains(robot, root, found)
    _states(robot, root, found)
    _pairs(robot, root, found, samples, seed, search_paths)
    return sorted(found, key=lambda finding: (finding.location.line or 0,
                                              finding.location.column or 0))


def read_srdf(path: str | PathLike[str]) -> tuple[Any, str]:
    """Return the SRDF's root element and text; a file not an SRDF is a UrdfgenpyError."""
    try:
        with open(path, 'rb') as stream:
            data = stream.read()
        root = etree.fromstring(data)
    except (OSError, etree.XMLSyntaxError) as error:
        raise ParseError(f'{path}: cannot read the SRDF: {error} (give an SRDF file)'
                         ) from None
    if not _is_srdf(root):
        what = 'a URDF or Xacro robot (it has <link>, <joint> or xacro elements)' \
            if root.tag == 'robot' else f'a <{root.tag}> document'
        raise UrdfgenpyError(f'{path} is not an SRDF but {what}: give --srdf the SRDF '
                             'file (e.g. config/ROBOT.srdf), or make one: urdfgenpy srdf '
                             'ROBOT -o robot.srdf')
    return root, data.decode('utf-8', 'replace')


def _stale(found: _Findings, element: Any, kind: str, name: str, known: list[str]) -> None:
    close = difflib.get_close_matches(name, known, n=1)
    hint = f'did you mean {close[0]!r}?' if close else f"name one of the robot's {kind}s"
    found.add('K901', element, f'<{element.tag}>', f'names {kind} {name!r}, which the '
              'robot does not have', f'{hint} Or regenerate: urdfgenpy srdf --update')


def _names(robot: RobotModel, root: Any, found: _Findings) -> None:
    links = [link.name for link in robot.links]
    joints = [joint.name for joint in robot.joints] + [  # the SRDF's own joints too
        str(element.get('name')) for element in root.iter('virtual_joint')]
    groups = [group.get('name') for group in root.iter('group') if group.get('name')]
    for kind, table, known in (('link', _LINKS, links), ('joint', _JOINTS, joints),
                               ('group', _GROUPS, groups)):
        for tag, attribute in table:
            for element in root.iter(tag):
                name = element.get(attribute)
                if tag == 'joint' and element.getparent().tag == 'robot':
                    continue
                if name is not None and name not in known:
                    _stale(found, element, kind, name, known)
    for group in root.iter('group'):  # a group of groups: <group name="arm"/> inside
        for inner in group.findall('group'):
            if inner.get('name') not in groups:
                _stale(found, inner, 'group', str(inner.get('name')), groups)


def _chains(robot: RobotModel, root: Any, found: _Findings) -> None:
    links = {link.name for link in robot.links}
    for chain in root.iter('chain'):
        base, tip = chain.get('base_link'), chain.get('tip_link')
        if base not in links or tip not in links:
            continue  # K901 said so
        above, current = set(), tip
        while current is not None:
            above.add(current)
            joint = robot.parent_joint(current)
            current = joint.parent if joint is not None else None
        if base not in above:
            found.add('K902', chain, '<chain>', f'base {base!r} is not above tip {tip!r} in '
                      'the tree', 'give a base_link that the tip hangs from')


def _states(robot: RobotModel, root: Any, found: _Findings) -> None:
    joints = {joint.name: joint for joint in robot.joints}
    for state in root.iter('group_state'):
        for element in state.findall('joint'):
            joint = joints.get(element.get('name'))
            if joint is None or not joint.type.needs_limit or joint.limit is None:
                continue
            try:
                value = float(element.get('value', ''))
            except ValueError:
                continue
            low, high = joint.limit.lower, joint.limit.upper
            if not low - 1e-9 <= value <= high + 1e-9:
                found.add('K903', element, f"state {state.get('name')!r}",
                          f'joint {joint.name!r} = {value:g} is outside its limits '
                          f'[{low:g}, {high:g}]', 'give a value within the limits')


def _pairs(robot: RobotModel, root: Any, found: _Findings, samples: int, seed: int,
           search_paths: Any) -> None:
    known = {link.name for link in robot.links}
    solid = {link.name for link in robot.links if link.collisions}
    never: dict[Pair, Any] = {}
    for element in root.iter('disable_collisions'):
        one, two = element.get('link1'), element.get('link2')
        if one not in known or two not in known:
            continue
        bare = [name for name in (one, two) if name not in solid]
        if bare:
            found.add('K905', element, '<disable_collisions>', f'link {bare[0]!r} has no '
                      'collision geometry: the pair is never tested anyway',
                      'remove the line, or give the link a <collision>')
        elif element.get('reason') == 'Never' and one != two:
            never[pair(one, two)] = element
    if not never or not samples:
        return
    for key, count in _counts(robot, list(never), samples, seed, search_paths).items():
        if count:
            found.add('K904', never[key], '<disable_collisions>', f'{key[0]!r} and {key[1]!r}'
                      f' are disabled as never colliding, but collide in {count} of '
                      f'{samples} random states ({count / samples:.2%})',
                      'remove the line, or regenerate: urdfgenpy srdf --update')


def _counts(robot: RobotModel, pairs: list[Pair], samples: int, seed: int, search_paths: Any
            ) -> dict[Pair, int]:
    shapes = ShapeSet(compiled(robot), link_shapes(robot, search_paths))
    generator, ranges = sampling.generator(seed), sampling.bounds(robot)
    counts = dict.fromkeys(pairs, 0)
    for start in range(0, samples, CHUNK):
        states = shapes.poses(sampling.random_states(ranges, min(CHUNK, samples - start),
                                                     generator))
        for key, count in states.counts(pairs).items():
            counts[key] += count
    return counts
