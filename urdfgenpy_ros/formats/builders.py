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
Robots a user's function builds: ``package.module:function`` returning a Robot or URDF text.

The node's ``model``, ``urdfgenpy init --from`` and assembly files' ``function:`` parts
name them.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
import importlib
import os
import sys
from typing import TYPE_CHECKING

from urdfgenpy_ros.model import robot_class
from urdfgenpy_ros.model.errors import UrdfgenpyError

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


def robot_from_function(target: str) -> RobotModel:
    """
    Return the robot ``package.module:function`` builds (a Robot, or URDF text).

    :raises UrdfgenpyError: when it cannot be imported or returns something else.
    """
    module_name, _, function_name = target.partition(':')
    try:
        with _here_importable():
            function = getattr(importlib.import_module(module_name), function_name)
    except (ImportError, AttributeError, ValueError) as error:
        raise UrdfgenpyError(f'cannot import {target!r}: {error} (write '
                             'package.module:function, importable from here)') from None
    result = function()
    if isinstance(result, robot_class()):
        return result
    if isinstance(result, (str, bytes)):
        from urdfgenpy_ros.formats._xml import xml_bytes
        from urdfgenpy_ros.formats.urdf_read import read_urdf_bytes
        data = xml_bytes(result, 'surrogateescape') if isinstance(result, str) else result
        return read_urdf_bytes(data, target)
    raise UrdfgenpyError(f'{target}() returned {type(result).__name__}, not a Robot or '
                         'URDF text')


@contextmanager
def _here_importable() -> Iterator[None]:
    """Let modules in the current folder be imported, as ``python -c`` would."""
    here = os.getcwd()
    added = '' not in sys.path and here not in sys.path
    if added:
        sys.path.insert(0, here)
    try:
        yield
    finally:
        if added and here in sys.path:
            sys.path.remove(here)
