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
The node's GUI mode (``gui:=true``): the viewer's page with sliders that drive joint_states.

It replaces joint_state_publisher_gui where there is no Qt: a browser is enough. Slider moves
are merged into the node's joint states like a ``source_list`` message; values that arrive
from ``source_list`` (or ``delta``) move the sliders, so the page shows what is published.
"""

from __future__ import annotations

from typing import Any

from urdfgenpy_ros.robot import Robot


class NodeGui:
    """Serve the robot of a PublisherNode with joint sliders on ``http://127.0.0.1:PORT``."""

    def __init__(self, node: Any, port: int, host: str = '127.0.0.1') -> None:
        from urdfgenpy_ros.viewer.web import RobotViewer
        self.node = node
        states = node.states
        self.viewer = RobotViewer(
            lambda: node.robot, host=host, port=port,
            search_paths=node.values['package_paths'], on_positions=self._moved,
            review_options=node.review_options,
            initial={name: joint.position for name, joint in states.free.items()})
        self._seen = (states, states.version)
        node.create_timer(0.1, self._follow)
        node.get_logger().info(f'joint sliders at {self.viewer.url} (open it in a browser)')

    def _moved(self, values: dict[str, float]) -> None:
        """Merge the sliders' values into the published joint states."""
        states = self.node.states
        free = {name: value for name, value in values.items() if name in states.free}
        states.merge(list(free), list(free.values()), [], [])
        self._seen = (states, states.version)

    def _follow(self) -> None:
        """Move the sliders to values that came from elsewhere (source_list, delta)."""
        states = self.node.states
        if (states, states.version) != self._seen:
            self._seen = (states, states.version)
            self.viewer.set_positions({name: joint.position
                                       for name, joint in states.free.items()})

    def show(self, robot: Robot) -> None:
        """Show a reloaded model."""
        self.viewer.show(robot)

    def close(self) -> None:
        """Stop serving the page."""
        self.viewer.close()
