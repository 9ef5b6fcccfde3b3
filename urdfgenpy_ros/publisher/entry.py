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
The ``publisher`` executable: one line naming the ``ros`` extra when ROS 2 is missing.

The node module imports rclpy and the message packages at its top; without them it would
end in ``ModuleNotFoundError: rcl_interfaces``. This entry point looks first.
"""

from __future__ import annotations

import importlib.util
import sys

NEEDED = ('rclpy', 'rcl_interfaces', 'std_msgs', 'sensor_msgs', 'std_srvs')
"""The Python packages of ROS 2 the node imports."""


def missing_ros() -> list[str]:
    """Return the ROS 2 Python packages the node needs that cannot be imported."""
    missing = []
    for name in NEEDED:
        try:
            found = importlib.util.find_spec(name) is not None
        except (ImportError, ValueError):
            found = False
        if not found:
            missing.append(name)
    return missing


def console_main() -> None:
    """Run the node, or say in one line how to get ROS 2's Python packages (exit 1)."""
    missing = missing_ros()
    if missing:
        print(f"publisher: the node needs ROS 2's Python packages ({', '.join(missing)} "
              "missing): pip install 'urdfgenpy_ros[ros]', or source /opt/ros/jazzy/"
              'setup.bash', file=sys.stderr)
        sys.exit(1)
    from urdfgenpy_ros.publisher.node import console_main as run
    run()
