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

"""Renaming a link renames the plugin texts that name it, never a topic or a namespace."""

from __future__ import annotations

from lxml import etree
import pytest

from urdfgenpy_ros import Robot

PLUGIN = """<?xml version="1.0"?>
<robot name="r">
  <link name="base_link"/>
  <link name="trunk"/>
  <joint name="j" type="fixed"><parent link="base_link"/><child link="trunk"/></joint>
  <gazebo>
    <plugin name="p" filename="libp.so">
      <bodyName>trunk</bodyName>
      <frameName>trunk</frameName>
      <topicName>trunk</topicName>
      <robotNamespace>trunk</robotNamespace>
      <serviceName>trunk</serviceName>
      <ros><namespace>trunk</namespace><remapping>trunk</remapping></ros>
    </plugin>
  </gazebo>
</robot>
"""


@pytest.mark.parametrize('tag, renamed', [
    ('bodyName', True), ('frameName', True), ('topicName', False), ('robotNamespace', False),
    ('serviceName', False), ('namespace', False), ('remapping', False)])
def test_only_frame_texts_follow_a_renamed_link(tag: str, renamed: bool) -> None:
    robot = Robot.from_urdf_string(PLUGIN)
    robot.rename_link('trunk', 'body')
    written = etree.fromstring(robot.to_urdf().encode())  # read back by lxml alone
    assert written.find(f'.//{tag}').text == ('body' if renamed else 'trunk')
