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
Whether a read robot, or one of its elements, was edited since it was read: one answer.

A model element is edited when its fields differ from the snapshot taken when it was
read; a ``<gazebo>``-style block when lxml's text of its element differs from that text
when read; the robot when its name, version or items (which, and in which order) changed
or any of them was edited. The writers, ``check --fix`` and the MuJoCo pre-flight ask here.
"""

from __future__ import annotations

from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.formats.urdf_schema import values
from urdfgenpy_ros.model.extensions import Extension
from urdfgenpy_ros.model.joint import Joint
from urdfgenpy_ros.model.link import Link
from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.model.preserved import SourceDocument

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

_ITEMS = (Material, Link, Joint, Extension)  # what a robot holds of its file's top level


def is_edited(item: Any) -> bool:
    """Return whether a model element differs from what was read (or was not read at all)."""
    extras = item.extras
    return extras is None or extras.snapshot is None or values(item) != extras.snapshot


def block_edited(document: SourceDocument, block: Extension) -> bool:
    """Return whether a block differs from what was read (or is no block of the file)."""
    element = block.element
    was = document.blocks.get(element)
    return was is None or element.getparent() is not document.node or \
        was != etree.tostring(element, with_tail=False)


def owners_of_blocks(robot: RobotModel) -> dict[int, Link | Joint]:
    """Return the link or joint holding each block, by the block's id."""
    holders: list[Link | Joint] = [*robot.links, *robot.joints]
    return {id(block): owner for owner in holders for block in owner.extensions_if_any or ()}


def is_as_read(robot: RobotModel) -> bool:
    """Return whether ``robot`` holds exactly what its file said: nothing edited."""
    document = robot.extras
    if not isinstance(document, SourceDocument):
        return False
    node = document.node
    if node.get('name') != robot.name or node.get('version') != robot.urdf_version:
        return False
    holders: list[Link | Joint] = [*robot.links, *robot.joints]
    owners: dict[int, Link | Joint] = {}
    blocks = [*robot.extensions]
    for holder in holders:
        held = holder.extensions_if_any  # no empty list made (lazy_lists)
        if held:
            blocks += held
            for block in held:
                owners[id(block)] = holder
    read = [item for item in document.order if isinstance(item, _ITEMS)]
    materials = robot.materials
    if len(materials) + len(holders) + len(blocks) != len(read) or {
            *map(id, materials), *map(id, holders), *map(id, blocks)} != {*map(id, read)}:
        return False
    for item in read:
        if isinstance(item, Extension):
            owner = owners.get(id(item))
            if block_edited(document, item) or (
                    owner is not None and item.tag == 'gazebo' and item.reference != owner.name):
                return False
        elif (extras := item.extras) is None or extras.snapshot is None or \
                values(item) != extras.snapshot:  # is_edited, inline: once per element
            return False
    return not any(holder.sensors_if_any for holder in holders)
