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
What the MJCF writer reads of the robot's URDF source: the one place that knows the record.

:func:`mujoco_block` is the robot's first ``<mujoco>`` element, as the reader kept it
(``SourceDocument.elements``). :func:`urdf_root` is the ``<robot>`` element the
losses walk: the one read from the file when the robot is as the file says (the URDF
writer would copy the file's text), else the robot written as URDF and parsed back.
"""

from __future__ import annotations

import re
from typing import Any, TYPE_CHECKING

from lxml import etree

from urdfgenpy_ros.formats.urdf import as_read_text
from urdfgenpy_ros.model.preserved import SourceDocument

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

# read warnings after which the tree read is not the tree of the text the writer copies
_REREAD = frozenset(('P101', 'P102', 'P103', 'P104', 'P105'))
_ENCODING = re.compile(r'\s*<\?xml[^>]*\bencoding\s*=\s*["\']([\w.-]+)["\']')


def mujoco_block(robot: RobotModel) -> Any | None:
    """Return the robot's first ``<mujoco>`` element (lxml), or None."""
    document = robot.extras
    if not isinstance(document, SourceDocument):
        return None  # built in Python: the model has no place for one
    if None in document.node.nsmap and as_read_text(robot) is not None:
        return None  # the written file keeps its default namespace: no <mujoco> tag in it
    return next(iter(document.elements('mujoco')), None)


def urdf_root(robot: RobotModel) -> Any:
    """Return the ``<robot>`` element of ``robot``'s URDF, with its source lines."""
    document = robot.extras
    if isinstance(document, SourceDocument) and as_read_text(robot) is not None \
            and None not in document.node.nsmap and _utf8(document.text) \
            and not any(warning.code in _REREAD for warning in robot.read_warnings):
        return document.node
    from urdfgenpy_ros.formats.urdf import write_urdf
    kept = any(warning.code == 'P105' for warning in robot.read_warnings)
    # undeclared prefixes (P105) are written as read: read them again as the reader did
    return etree.fromstring(write_urdf(robot).encode('utf-8'),
                            etree.XMLParser(huge_tree=True, resolve_entities=False,
                                            no_network=True, recover=kept))


def _utf8(text: str) -> bool:
    """Return whether ``text`` reads the same encoded as UTF-8 (what its declaration says)."""
    declared = _ENCODING.match(text)
    return text.isascii() or declared is None or declared.group(1).lower() in (
        'utf-8', 'utf8')
