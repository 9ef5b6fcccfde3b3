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

"""What a generated package is: its name (checked against ROS's rules) and its metadata."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
import re

from urdfgenpy_ros.model.errors import UrdfgenpyError

BUILD_TYPES = ('ament_cmake', 'ament_python')
_NAME = re.compile(r'^[a-z][a-z0-9_]*$')


def check_package_name(name: str) -> None:
    """
    Raise UrdfgenpyError with a one-line reason unless ``name`` is a valid ROS package name.

    The rules (REP 144): lower-case letters, digits and underscores, starting with a letter,
    with no two underscores in a row and no underscore at the end.
    """
    if not _NAME.match(name):
        reason = ('must start with a lower-case letter' if not name[:1].islower()
                  or not name[:1].isalpha() else
                  'may hold only lower-case letters, digits and underscores')
    elif '__' in name:
        reason = 'must not hold two underscores in a row'
    elif name.endswith('_'):
        reason = 'must not end with an underscore'
    else:
        return
    raise UrdfgenpyError(f'invalid package name {name!r}: it {reason} (e.g. my_robot_description)')


@dataclass(slots=True)
class PackageSpec:
    """The package to generate; ``name`` is conventionally ``<robot>_description``."""

    name: str
    build_type: str = 'ament_cmake'
    destination: Path = field(default_factory=Path)
    maintainer_name: str = 'maintainer'
    maintainer_email: str = 'maintainer@example.com'
    license: str = 'Apache-2.0'  # noqa: A003 - ros2 pkg create's option name
    description: str = ''  # empty: 'Robot description of <robot name>'
    dependencies: list[str] = field(default_factory=list)

    def __post_init__(self) -> None:
        """Check the name and build type."""
        check_package_name(self.name)
        if self.build_type not in BUILD_TYPES:
            raise UrdfgenpyError(f'build type {self.build_type!r}: use ament_cmake or '
                                 'ament_python')
        self.destination = Path(self.destination)

    @property
    def root(self) -> Path:
        """Return the package folder to create."""
        return self.destination / self.name
