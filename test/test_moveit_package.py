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
``urdfgenpy init NAME --moveit --from SOURCE``: a moveit_config package for Jazzy.

The YAML files are read back with PyYAML and compared with the URDF read with lxml
(every active joint) and the SRDF read with lxml (every chain group); colcon builds the
package beside its description package, xacro expands its robot with the sourced install,
and ``check --srdf`` finds its SRDF in step with that robot.
"""

from __future__ import annotations

import os
from pathlib import Path
import re
import subprocess
import sys

from helpers import require_module
from lxml import etree
import pytest
from test_moveit_srdf import _share, _urdf
from urdfgenpy_ros.cli.init import init
from urdfgenpy_ros.scaffold.moveit_package import main
import yaml

ARM = """<?xml version="1.0"?>
<robot name="arm">
  <link name="base_link"><collision><geometry><cylinder radius="0.1" length="0.1"/>
    </geometry></collision></link>
  <link name="upper"><collision><origin xyz="0 0 0.25"/><geometry>
    <cylinder radius="0.04" length="0.5"/></geometry></collision></link>
  <link name="fore"><collision><origin xyz="0 0 0.2"/><geometry>
    <cylinder radius="0.04" length="0.4"/></geometry></collision></link>
  <link name="palm"><collision><geometry><box size="0.1 0.1 0.02"/></geometry></collision>
    </link>
  <link name="left"><collision><geometry><box size="0.01 0.02 0.05"/></geometry>
    </collision></link>
  <link name="right"><collision><geometry><box size="0.01 0.02 0.05"/></geometry>
    </collision></link>
  <joint name="shoulder" type="revolute"><parent link="base_link"/><child link="upper"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="10" velocity="1.5"/></joint>
  <joint name="elbow" type="continuous"><parent link="upper"/><child link="fore"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 1 0"/><limit effort="5" velocity="2"/></joint>
  <joint name="wrist" type="fixed"><parent link="fore"/><child link="palm"/>
    <origin xyz="0 0 0.4"/></joint>
  <joint name="left_finger" type="prismatic"><parent link="palm"/><child link="left"/>
    <origin xyz="0 0.02 0.03"/><axis xyz="0 1 0"/>
    <limit lower="0" upper="0.03" effort="5" velocity="0.1"/></joint>
  <joint name="right_finger" type="prismatic"><parent link="palm"/><child link="right"/>
    <origin xyz="0 -0.02 0.03"/><axis xyz="0 -1 0"/>
    <limit lower="0" upper="0.03" effort="5" velocity="0.1"/>
    <mimic joint="left_finger"/></joint>
</robot>
"""


def _description(root: Path) -> Path:
    """Return the URDF of a description package made by hand (package.xml, urdf/)."""
    package = root / 'arm_description'
    (package / 'urdf').mkdir(parents=True)
    (package / 'package.xml').write_text(
        '<?xml version="1.0"?><package format="3"><name>arm_description</name>'
        '<version>0.0.1</version><description>d</description><maintainer email="a@b.c">'
        'a</maintainer><license>MIT</license></package>')
    (package / 'urdf' / 'arm.urdf').write_text(ARM)
    return package / 'urdf' / 'arm.urdf'


def test_yaml_files_cover_every_active_joint_and_chain_group(tmp_path: Path) -> None:
    require_module('coal')
    require_module('jinja2')
    source = _description(tmp_path)
    assert main(['arm_moveit_config', '--from', str(source), '--destination-directory',
                 str(tmp_path), '--samples', '300']) == 0
    config = tmp_path / 'arm_moveit_config' / 'config'
    urdf = etree.parse(str(source)).getroot()
    active = [j.get('name') for j in urdf.iter('joint') if j.get('type') != 'fixed'
              and j.find('mimic') is None]
    srdf = etree.parse(str(config / 'arm.srdf')).getroot()
    chains = {g.get('name') for g in srdf.iter('group') if g.find('chain') is not None}
    grippers = {g.get('name') for g in srdf.iter('group') if g.find('chain') is None}
    assert chains and grippers
    load = lambda name: yaml.safe_load((config / f'{name}.yaml').read_text())  # noqa: E731
    assert set(load('kinematics')) == chains
    assert list(load('joint_limits')['joint_limits']) == active
    velocity = {j.get('name'): float(j.find('limit').get('velocity'))
                for j in urdf.iter('joint') if j.find('limit') is not None}
    for name, limit in load('joint_limits')['joint_limits'].items():
        assert limit['max_velocity'] == velocity[name]
        assert isinstance(limit['max_acceleration'], float)  # ROS 2 parameters are typed
    assert list(load('initial_positions')['initial_positions']) == active
    controllers = load('moveit_controllers')['moveit_simple_controller_manager']
    names = controllers['controller_names']
    assert {name.removesuffix('_controller') for name in names} == chains | grippers
    controlled = {joint for name in names for joint in controllers[name]['joints']}
    assert controlled == set(active)
    ros2 = load('ros2_controllers')
    assert set(names) <= set(ros2['controller_manager']['ros__parameters'])
    # the launch files are Python that compiles; package.xml names the description
    for launch in (tmp_path / 'arm_moveit_config' / 'launch').glob('*.py'):
        compile(launch.read_text(), str(launch), 'exec')
    manifest = etree.parse(str(tmp_path / 'arm_moveit_config' / 'package.xml'))
    assert 'arm_description' in [e.text for e in manifest.iter('exec_depend')]


def test_a_source_outside_a_package_is_one_line(tmp_path: Path,
                                                capsys: pytest.CaptureFixture) -> None:
    (tmp_path / 'arm.urdf').write_text(ARM)
    assert main(['x_moveit_config', '--from', str(tmp_path / 'arm.urdf')]) == 2
    error = capsys.readouterr().err.strip().splitlines()
    assert len(error) == 1 and 'is in no ROS package' in error[0]


@pytest.mark.colcon
def test_colcon_builds_panda_config_and_its_robot_expands(tmp_path: Path) -> None:
    require_module('colcon_core')
    require_module('coal')
    src = tmp_path / 'src'
    with pytest.raises(SystemExit) as made:
        init.main(['panda_description', '--from', str(_urdf('panda')), '-p', str(_share()),
                   '--destination-directory', str(src)], standalone_mode=False)
    assert made.value.code == 0
    assert main(['panda_moveit_config', '--from',
                 str(src / 'panda_description/urdf/panda.urdf.xacro'),
                 '--destination-directory', str(src), '--samples', '1000']) == 0
    env = dict(os.environ, PATH=f'{Path(sys.executable).parent}:{os.environ["PATH"]}')
    colcon = str(Path(sys.executable).with_name('colcon'))
    for verb in (['build'], ['test'], ['test-result', '--verbose']):
        result = subprocess.run([colcon, *verb], cwd=tmp_path, capture_output=True,
                                text=True, env=env, timeout=900)
        assert result.returncode == 0, result.stdout[-3000:] + result.stderr[-3000:]
    share = tmp_path / 'install/panda_moveit_config/share/panda_moveit_config'
    assert (share / '.setup_assistant').is_file()
    expanded = subprocess.run(
        ['bash', '-c', f'source install/setup.bash && xacro {share}/config/panda.urdf.xacro'],
        cwd=tmp_path, capture_output=True, text=True, env=env, timeout=120)
    assert expanded.returncode == 0, expanded.stderr
    robot = etree.fromstring(expanded.stdout.encode())
    assert robot.find('ros2_control/hardware/plugin').text == 'mock_components/GenericSystem'
    (tmp_path / 'robot.urdf').write_text(expanded.stdout)
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main as cli
    checked = CliRunner().invoke(cli, ['check', str(tmp_path / 'robot.urdf'), '--srdf',
                                       str(share / 'config/panda.srdf'), '-p',
                                       str(tmp_path / 'install')])
    assert not re.search('K90[1235]', checked.output), checked.output
    for count in re.findall(r'collide in (\d+) of 10000', checked.output):
        assert int(count) < 30, checked.output  # made from 1000 states: under 3 in 1000


def test_init_help_lists_the_moveit_options() -> None:
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main as cli
    result = CliRunner().invoke(cli, ['init', '--help'])
    assert result.exit_code == 0
    for option in ('--moveit', '--samples', '--seed', '--group NAME=BASE:TIP'):
        assert f'  {option}' in result.output, option
    result = CliRunner().invoke(cli, ['init', 'arm_description', '--seed', '3'])
    assert result.exit_code == 2 and '--seed: for a moveit_config package, give --moveit' \
        in result.output


def test_init_moveit_group_names_the_chain(tmp_path: Path) -> None:
    require_module('coal')
    require_module('jinja2')
    source = _description(tmp_path)
    assert main(['arm_moveit_config', '--from', str(source), '--destination-directory',
                 str(tmp_path), '--samples', '20', '--group', 'manipulator=base_link:palm']) == 0
    config = tmp_path / 'arm_moveit_config' / 'config'
    parent = {j.find('child').get('link'): j.find('parent').get('link')
              for j in etree.parse(str(source)).getroot().iter('joint')}
    srdf = etree.parse(str(config / 'arm.srdf')).getroot()
    chains = {g.get('name'): g.find('chain') for g in srdf.iter('group')
              if g.find('chain') is not None}
    assert list(chains) == ['manipulator']
    assert parent[chains['manipulator'].get('tip_link')] == 'fore'
    kinematics = yaml.safe_load((config / 'kinematics.yaml').read_text())
    assert list(kinematics) == ['manipulator']
