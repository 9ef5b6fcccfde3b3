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
A valid robot and, per check, the same robot with exactly one defect.

Each defect's line carries ``<!--D-->``: the finding must point at that line.
"""

from __future__ import annotations

VALID = """<?xml version="1.0"?>
<robot name="fixture">
  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
  <link name="base_link"/>
  <link name="arm">
    <inertial>
      <origin xyz="0 0 0.1"/>
      <mass value="1"/>
      <inertia ixx="0.0035583333" ixy="0" ixz="0" iyy="0.0035583333" iyz="0" izz="0.00045"/>
    </inertial>
    <visual>
      <origin xyz="0 0 0.1"/>
      <geometry><cylinder radius="0.03" length="0.2"/></geometry>
      <material name="grey"/>
    </visual>
    <collision>
      <origin xyz="0 0 0.1"/>
      <geometry><cylinder radius="0.03" length="0.2"/></geometry>
    </collision>
  </link>
  <link name="hand">
    <inertial>
      <mass value="0.5"/>
      <inertia ixx="0.0002" ixy="0" ixz="0" iyy="0.0002" iyz="0" izz="0.0002"/>
    </inertial>
    <collision>
      <geometry><sphere radius="0.03"/></geometry>
    </collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base_link"/>
    <child link="arm"/>
    <axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/>
  </joint>
  <joint name="wrist" type="revolute">
    <origin xyz="0 0 0.2"/>
    <parent link="arm"/>
    <child link="hand"/>
    <axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="5" velocity="1"/>
  </joint>
</robot>
"""

_WRIST = '<joint name="wrist" type="revolute">'
_SHOULDER = '<joint name="shoulder" type="revolute">'
_WRIST_LIMIT = '<limit lower="-1" upper="1" effort="5" velocity="1"/>'
_ARM_TENSOR = 'ixx="0.0035583333" ixy="0" ixz="0" iyy="0.0035583333" iyz="0" izz="0.00045"'
_END = '</robot>'
_TOOL = '<link name="tool"/>\n'


def _fixed(name: str, parent: str, child: str) -> str:
    return (f'<joint name="{name}" type="fixed"><parent link="{parent}"/>'
            f'<child link="{child}"/></joint>\n')


# code: (the codes the one defect causes, [(text, replacement), ...])
DEFECTS: dict[str, tuple[set[str], list[tuple[str, str]]]] = {
    'S003': ({'S001', 'S003'}, [
        (_SHOULDER, f'{_SHOULDER}<!--D-->'),
        (_END, '<joint name="back" type="fixed"><parent link="hand"/>'
               f'<child link="base_link"/></joint>\n{_END}')]),
    'S002': ({'S002'}, [(_END, f'<link name="stray"/><!--D-->\n{_END}')]),
    'S004': ({'S004'}, [('<parent link="arm"/>', '<parent link="ghost"/><!--D-->')]),
    'S005': ({'S005', 'S002', 'I205'}, [('<child link="hand"/>',
                                         '<child link="ghost"/><!--D-->')]),
    'S006': ({'S006', 'S007'}, [(_END, '<joint name="self" type="fixed"><!--D--><parent '
                                       'link="hand"/><child link="hand"/></joint>\n' + _END)]),
    'S007': ({'S007'}, [(_END, _TOOL + _fixed('a', 'arm', 'tool') + _fixed('b', 'hand', 'tool')
                         + _END), ('<link name="tool"/>', '<link name="tool"/><!--D-->')]),
    'S008': ({'S008'}, [('<link name="hand">', '<link name=""><!--D-->'),
                        ('<child link="hand"/>', '<child link=""/>')]),
    'S009': ({'S009'}, [('<link name="hand">', '<link name="hand link"><!--D-->'),
                        ('<child link="hand"/>', '<child link="hand link"/>')]),
    'C401': ({'C401'}, [('<link name="base_link"/>', '<link name="base"/><!--D-->'),
                        ('<parent link="base_link"/>', '<parent link="base"/>')]),
    'J101': ({'J101'}, [('<axis xyz="0 1 0"/>', '<axis xyz="0 0 0"/><!--D-->')]),
    'J102': ({'J102'}, [('<axis xyz="0 1 0"/>', '<axis xyz="0 2 0"/><!--D-->')]),
    'J103': ({'J103'}, [(_WRIST, f'{_WRIST}<!--D-->'), (_WRIST_LIMIT, '')]),
    'J104': ({'J104'}, [(_WRIST_LIMIT, '<limit lower="1" upper="-1" effort="5" '
                                       'velocity="1"/><!--D-->')]),
    'J105': ({'J105'}, [(_WRIST_LIMIT, '<limit lower="-1" upper="1" effort="-5" '
                                       'velocity="1"/><!--D-->')]),
    'J106': ({'J106'}, [(_WRIST_LIMIT, '<limit lower="-1" upper="1" effort="5" '
                                       'velocity="0"/><!--D-->')]),
    'J107': ({'J107'}, [(_WRIST_LIMIT, _WRIST_LIMIT + '<mimic joint="ghost"/><!--D-->')]),
    'J108': ({'J108'}, [(_END, _TOOL + _fixed('mount', 'hand', 'tool') + _END),
                        (_WRIST_LIMIT, _WRIST_LIMIT + '<mimic joint="mount"/><!--D-->')]),
    'J109': ({'J109'}, [(_WRIST_LIMIT, _WRIST_LIMIT + '<mimic joint="shoulder"/>'),
                        ('effort="10" velocity="1"/>',
                         'effort="10" velocity="1"/><mimic joint="wrist"/><!--D-->')]),
    'J110': ({'J110'}, [(_WRIST_LIMIT, _WRIST_LIMIT + '<safety_controller soft_lower_limit='
                                                      '"-2" soft_upper_limit="0.9" '
                                                      'k_velocity="10"/><!--D-->')]),
    'J111': ({'J111'}, [(_END, _TOOL + _fixed('mount', 'hand', 'tool').replace(
        '</joint>', '<mimic joint="wrist"/><!--D--></joint>') + _END)]),
    'I201': ({'I201'}, [('<mass value="1"/>', '<mass value="0"/><!--D-->')]),
    'I202': ({'I202'}, [(_ARM_TENSOR, _ARM_TENSOR.replace('izz="0.00045"', 'izz="-0.00045"')
                         + '/><!--D--><x')]),
    'I203': ({'I203'}, [(_ARM_TENSOR, 'ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" '
                                      'izz="0.01"/><!--D--><x')]),
    'I204': ({'I204'}, [(_ARM_TENSOR, 'ixx="3558.3333" ixy="0" ixz="0" iyy="3558.3333" '
                                      'iyz="0" izz="450"/><!--D--><x')]),
    'I205': ({'I205'}, [('<link name="base_link"/>', '<link name="base_link"><!--D-->'
                         '<inertial><mass value="2"/><inertia ixx="0.01" ixy="0" ixz="0" '
                         'iyy="0.01" iyz="0" izz="0.01"/></inertial></link>')]),
    'I210': ({'I210'}, [('<link name="base_link"/>', '<link name="base_link"><inertial>'
                         '<mass value="-1"/><!--D--><inertia ixx="0.01" ixy="0" ixz="0" '
                         'iyy="0.01" iyz="0" izz="0.01"/></inertial></link>')]),
    'I206': ({'I206', 'I209'}, [('<link name="base_link"/>', '<link name="base_link"/>\n'
                                 '<link name="mount"/><!--D-->'),
                                ('<parent link="base_link"/>', '<parent link="mount"/>'),
                                (_END, '<joint name="fix" type="fixed">'
                                       '<parent link="base_link"/>'
                                       '<child link="mount"/></joint>\n' + _END)]),
    'I207': ({'I207'}, [('<link name="hand">', '<link name="hand"/><!--D--><unused>'),
                        ('</collision>\n  </link>\n  <joint name="shoulder"',
                         '</collision>\n  </unused>\n  <joint name="shoulder"')]),
    'R301': ({'R301'}, [('<material name="grey"/>', '<material name="blue"/><!--D-->')]),
    'R302': ({'R302'}, [('<geometry><sphere radius="0.03"/></geometry>',
                         '<geometry><mesh filename="missing.stl"/><!--D--></geometry>')]),
    'R303': ({'R303'}, [('<geometry><sphere radius="0.03"/></geometry>',
                         '<geometry><mesh filename="package://no_such_pkg/a.stl"/><!--D-->'
                         '</geometry>')]),
    'R304': ({'R304'}, [('<geometry><sphere radius="0.03"/></geometry>',
                         '<geometry><box size="0 0.1 0.1"/><!--D--></geometry>')]),
    'R307': ({'R307'}, [('<material name="grey"/>\n    </visual>',
                         '<material name="grey"/>\n    </visual>\n    <visual><geometry>'
                         '<box size="0 0.1 0.1"/><!--D--></geometry></visual>')]),
    'R305': ({'R305'}, [('<limit lower="-1" upper="1" effort="10" velocity="1"/>',
                         '<limit lower="-1" upper="1" effort="10" velocity="nan"/><!--D-->')]),
    'R306': ({'R306'}, [('<material name="grey"/>\n    </visual>',
                         '<material name="grey"/>\n    </visual>\n    <visual><geometry>'
                         '<mesh filename="missing.dae"/><!--D--></geometry></visual>')]),
    'R309': ({'R309', 'R306'}, [('<material name="grey"/>\n    </visual>',
                                 '<material name="grey"/>\n    </visual>\n    <visual>'
                                 '<geometry><mesh filename="/no_such_folder/arm.dae"/><!--D-->'
                                 '</geometry></visual>')]),
}


def broken(code: str) -> str:
    """Return the valid robot with the defect of ``code``."""
    text = VALID
    for old, new in DEFECTS[code][1]:
        assert old in text, (code, old)
        text = text.replace(old, new, 1)
    return text


def defect_line(text: str) -> int:
    """Return the line of the ``<!--D-->`` marker."""
    return text[:text.index('<!--D-->')].count('\n') + 1
