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

"""Generate ROS 2 description packages: ``urdfgenpy init`` and ``ros2 pkg scaffold``."""

from urdfgenpy_ros.scaffold.render import create_package
from urdfgenpy_ros.scaffold.spec import check_package_name, PackageSpec

__all__ = ['check_package_name', 'create_package', 'PackageSpec']

INIT_INPUTS = {'source': '--from', 'args': '--xacro-args', 'package_paths': '--package-path'}
"""How ``init`` (and ``ros2 pkg scaffold``) names the inputs of the front door."""
