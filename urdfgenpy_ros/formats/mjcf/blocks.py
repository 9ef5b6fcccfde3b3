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
The URDF's own ``<mujoco>`` block, checked against MuJoCo, and the user's overlay.

``<mujoco>`` holds ``<compiler>``, ``<option>`` and ``<size>`` for MuJoCo's URDF import;
their attributes are written into the MJCF, and each is checked by letting MuJoCo compile
a one-body model with it: an attribute it does not know (a misspelling) is a finding.
An overlay is an MJCF file whose elements are merged into the output by tag and name,
so hand-tuned gains, contact parameters, sites and keyframes survive a new conversion.
"""

from __future__ import annotations

import copy
from os import PathLike
from pathlib import Path
from typing import Any

from lxml import etree

from urdfgenpy_ros.model.errors import ModelError, ParseError, SourceLocation

SINGLETONS = frozenset(('compiler', 'option', 'size', 'visual', 'statistic', 'flag',
                        'global', 'quality', 'headlight', 'map', 'scale', 'rgba'))
OURS = frozenset(('meshdir', 'angle', 'autolimits', 'inertiafromgeom'))  # the writer's


def check_attributes(element: Any) -> list[tuple[str, str]]:
    """Return ``(attribute, message)`` for each attribute of ``element`` MuJoCo refuses."""
    try:
        import mujoco
    except ImportError:
        return []
    found = []
    for name, value in element.attrib.items():
        probe = etree.Element(element.tag, {name: value})
        text = ('<mujoco>' + etree.tostring(probe, encoding='unicode')
                + '<worldbody><body><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>'
                '<joint/></body></worldbody></mujoco>')
        try:
            mujoco.MjModel.from_xml_string(text)
        except ValueError as error:
            said = ' '.join(str(error).split('Element')[0].split())
            found.append((name, f'<{element.tag} {name}="{value}">: MuJoCo says: {said}'))
    return found


def apply_block(block: Any | None, document: Any) -> None:
    """Copy the attributes of the URDF's ``<mujoco>`` compiler, option and size."""
    if block is None:
        return
    for child in block:
        if not isinstance(child.tag, str) or child.tag not in ('compiler', 'option', 'size'):
            continue
        target = document.find(child.tag)
        if target is None:
            target = etree.Element(child.tag)
            insert_section(document, target)
        refused = {name for name, _ in check_attributes(child)}
        for name, value in child.attrib.items():
            if name not in OURS and name not in refused:
                target.set(name, value)


def insert_section(document: Any, section: Any) -> None:
    order = ('compiler', 'option', 'size', 'visual', 'default', 'asset', 'worldbody')
    rank = order.index(section.tag) if section.tag in order else len(order)
    for index, existing in enumerate(document):
        if isinstance(existing.tag, str) and existing.tag in order \
                and order.index(existing.tag) > rank:
            document.insert(index, section)
            return
    document.append(section)


def read_overlay(path: str | PathLike[str]) -> Any:
    """Return the ``<mujoco>`` root of an overlay file; one line naming the problem if not."""
    try:
        root = etree.parse(str(path), etree.XMLParser(no_network=True,
                                                      resolve_entities=False)).getroot()
    except OSError as error:
        raise ModelError(f'{path}: cannot read the overlay ({error.strerror or error})'
                         ) from None
    except etree.XMLSyntaxError as error:
        line, column = error.position
        raise ParseError(f'XML syntax: {error.msg}', SourceLocation(str(path), line, column)
                         ) from None
    if root.tag != 'mujoco':
        raise ParseError(f'an overlay is an MJCF file with a <mujoco> root, not <{root.tag}>',
                         SourceLocation(str(path), root.sourceline, 1))
    return root


def merge_overlay(document: Any, overlay: Any) -> None:
    """Merge ``overlay``'s sections into ``document`` by tag and ``name``."""
    for section in overlay:
        if not isinstance(section.tag, str):
            continue
        target = document.find(section.tag)
        if target is None:
            insert_section(document, copy.deepcopy(section))
            continue
        _merge(target, section)


def _merge(target: Any, source: Any) -> None:
    for name, value in source.attrib.items():
        target.set(name, value)
    for child in source:
        if not isinstance(child.tag, str):
            continue
        name = child.get('name')
        match = None
        if name is not None:
            match = next((node for node in target.iter(child.tag)
                          if node.get('name') == name), None)
        elif child.tag in SINGLETONS:
            match = target.find(child.tag)
        if match is None:
            target.append(copy.deepcopy(child))
        else:
            _merge(match, child)


def overlay_path(path: str | PathLike[str] | None) -> Path | None:
    """Return the overlay path as a Path (None stays None)."""
    return Path(path) if path is not None else None
