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
Build, read, check and publish robot descriptions for ROS 2.

>>> from urdfgenpy_ros import Box, Inertial, Link, Robot, Visual
>>> robot = Robot('demo').add_link(Link('base_link'))
"""

from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.errors import (
    ModelError, ParseError, Severity, SourceLocation, UrdfgenpyError, ValidationError)
from urdfgenpy_ros.model.extensions import Extension
from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, Geometry, Mesh, Origin, Sphere
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.joint import (
    Joint, JointCalibration, JointDynamics, JointLimit, JointMimic, JointType,
    SafetyController)
from urdfgenpy_ros.model.link import Collision, Link, Visual
from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.robot import Robot

if TYPE_CHECKING:  # imported on first use (see __getattr__): the checks are not needed to start
    from urdfgenpy_ros.validation.checklist import Review, review, ReviewOptions

__version__ = '0.1.0'

__all__ = [
    'Box', 'Capsule', 'Collision', 'Cylinder', 'Extension', 'Geometry', 'Inertial', 'Joint',
    'JointCalibration', 'JointDynamics', 'JointLimit', 'JointMimic', 'JointType', 'Link',
    'Material', 'Mesh', 'ModelError', 'Origin', 'ParseError', 'Review', 'review',
    'ReviewOptions', 'Robot', 'SafetyController', 'Severity', 'SourceLocation', 'Sphere',
    'UrdfgenpyError', 'ValidationError', 'Visual', '__version__',
]
_REVIEW = ('Review', 'review', 'ReviewOptions')


def __getattr__(name: str) -> Any:
    """Return the library review's names (``review``, ``ReviewOptions``, ``Review``)."""
    if name in _REVIEW:
        from urdfgenpy_ros.validation import checklist
        return getattr(checklist, name)
    raise AttributeError(f'module {__name__!r} has no attribute {name!r}')
