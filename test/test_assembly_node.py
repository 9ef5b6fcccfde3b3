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


"""The publisher node with an assembly file: it publishes it and follows every part."""

from __future__ import annotations

from pathlib import Path
import time

from assembly_parts import gripper, mobile_base
from helpers import require_module
import pytest

from ros_helpers import Graph
from urdfgenpy_ros import Origin, Robot

try:  # without ROS 2, every test here skips through _ros below (and fails in CI)
    from sensor_msgs.msg import JointState
    from std_msgs.msg import String
except ImportError:
    pass


@pytest.fixture(autouse=True)
def _ros() -> None:
    for module in ('rclpy', 'sensor_msgs.msg', 'std_msgs.msg'):
        require_module(module)


def test_node_publishes_an_assembly_and_reloads_when_a_part_changes(
        graph: Graph, tmp_path: Path) -> None:
    mobile_base().to_urdf(tmp_path / 'rover.urdf')
    part = tmp_path / 'gripper.urdf'
    gripper().to_urdf(part)
    assembly = tmp_path / 'rover.assembly.yaml'
    assembly.write_text('parts:\n  - file: rover.urdf\n  - file: gripper.urdf\n'
                        '    at: mast\n    prefix: g_\n    origin: {xyz: [0, 0, 0.3]}\n')
    graph.start(f'model:={assembly}', 'watch:=true')
    descriptions = graph.collect(String, 'robot_description', latched=True)
    states = graph.collect(JointState, 'joint_states')
    assert graph.spin_until(lambda: descriptions and states, 20)
    expected = Robot.from_urdf(tmp_path / 'rover.urdf').attach(
        Robot.from_urdf(part), 'mast', Origin((0, 0, 0.3)), prefix='g_')
    assert descriptions[0].data == expected.to_urdf()
    assert list(states[-1].name) == ['left_wheel_joint', 'right_wheel_joint',
                                     'g_left_finger_joint', 'g_right_finger_joint']
    time.sleep(0.05)
    part.write_text(part.read_text().replace('left_finger_joint', 'thumb_joint'))
    assert graph.spin_until(lambda: len(descriptions) == 2, 15), 'no reload'
    assert '<joint name="g_thumb_joint" type="prismatic">' in descriptions[-1].data
    assert '<mimic joint="g_thumb_joint"' in descriptions[-1].data
    assert graph.spin_until(lambda: 'g_thumb_joint' in states[-1].name, 10)
