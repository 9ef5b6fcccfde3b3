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
A continuous joint (a wheel, PR2's forearm and wrist rolls) stays continuous through DH.

Its row keeps the type, the effort and the velocity the source gives (none when it has no
``<limit>``) through YAML, CSV, ``urdfgenpy dh``/``convert`` and ``apply_dh``. Judged by
yourdfpy reading the source and the URDF made from the table: the same joint types,
efforts and velocities, and the same forward kinematics at angles past pi; and by
robotics-toolbox's kinematics of the rows.
"""

from __future__ import annotations

import math
from pathlib import Path
import random

from click.testing import CliRunner
from helpers import assert_check_urdf_accepts, require_module
import pytest
from test_reshape_dh import example_robot

from urdfgenpy_ros import Cylinder, Joint, JointLimit, Link, ModelError, Origin, Robot, Visual
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.dh import DHRow, DHTable

PR2 = 'pr2_description/urdf/pr2.urdf'
ARM = ('torso_lift_link', 'r_gripper_palm_link')  # two continuous rolls, effort 30 and 10


def _rover() -> Robot:
    """Return a steered wheel: a revolute steering joint, a continuous wheel, no <limit>."""
    robot = Robot('rover').add_link(Link('base_link')).add_link(Link('fork'))
    robot.add_link(Link('wheel').add_visual(Visual(Cylinder(0.1, 0.04))))
    robot.add_link(Link('hub'))
    robot.add_joint(Joint('steer', 'revolute', 'base_link', 'fork', origin=Origin((0.3, 0, 0)),
                          axis=(0, 0, 1), limit=JointLimit(-0.6, 0.6, effort=8, velocity=1.5)))
    robot.add_joint(Joint('wheel_joint', 'continuous', 'fork', 'wheel',
                          origin=Origin((0.0, 0.1, -0.2), (-math.pi / 2, 0, 0)),
                          axis=(0, 0, 1)))
    return robot.add_joint(Joint('hub_joint', 'fixed', 'wheel', 'hub',
                                 origin=Origin((0, 0, 0.03))))


def _joints(path: Path) -> dict[str, tuple]:
    """Return each moving joint's type, effort and velocity, as yourdfpy reads them."""
    yourdfpy = require_module('yourdfpy')
    robot = yourdfpy.URDF.load(str(path), load_meshes=False, build_scene_graph=False).robot
    return {joint.name: (joint.type, None if joint.limit is None else joint.limit.effort,
                         None if joint.limit is None else joint.limit.velocity)
            for joint in robot.joints if joint.type != 'fixed'}


def _tip_poses(path: Path, base: str, tip: str, names: list[str], seed: int = 3):
    """Return yourdfpy's tip pose in the base frame at random values, rolls past pi."""
    yourdfpy = require_module('yourdfpy')
    model = yourdfpy.URDF.load(str(path), load_meshes=False)
    rng = random.Random(seed)
    poses = []
    for _ in range(20):
        model.update_cfg({name: rng.uniform(-0.5, 0.5) if model.joint_map[name].type !=
                          'continuous' else rng.uniform(-9.0, 9.0) for name in names})
        poses.append(model.get_transform(tip, base))
    return poses


def _source(tmp_path: Path, name: str) -> tuple[Path, str, str]:
    if name == 'pr2':
        return example_robot(PR2), *ARM
    path = tmp_path / 'rover.urdf'
    _rover().to_urdf(path)
    return path, 'base_link', 'hub'


@pytest.mark.parametrize('suffix', ['.yaml', '.csv'])
@pytest.mark.parametrize('name', ['pr2', 'rover'])
def test_a_continuous_joint_keeps_its_type_effort_and_velocity(name: str, suffix: str,
                                                               tmp_path: Path) -> None:
    numpy = require_module('numpy')
    source, base, tip = _source(tmp_path, name)
    table_file, urdf = tmp_path / f'table{suffix}', tmp_path / 'from_table.urdf'
    robot = Robot.from_urdf(source)
    table = DHTable.from_robot(robot, base, tip, 'modified')
    if suffix == '.csv':  # CSV holds the rows only: the chain from DH frame 0 to the last
        table.base, table.tool = Origin(), Origin()
        table.save(table_file, degrees=True)
    else:
        assert CliRunner().invoke(main, ['dh', str(source), '--base', base, '--tip', tip,
                                         '--convention', 'modified', '-o',
                                         str(table_file)]).exit_code == 0
    assert CliRunner().invoke(main, ['convert', str(table_file), str(urdf)]).exit_code == 0
    assert_check_urdf_accepts(urdf)
    theirs = {joint: value for joint, value in _joints(source).items()
              if joint in {row.name for row in table.rows}}
    assert 'continuous' in {kind for kind, _, _ in theirs.values()}
    assert _joints(urdf) == theirs  # 'revolute', 100, 2 for a continuous one before
    text = urdf.read_text()
    assert str(math.pi) not in text  # no invented -pi..pi on a continuous joint
    if suffix == '.yaml':  # the whole table: the tip's pose is the source's
        names = [row.name for row in table.rows]
        mine = _tip_poses(urdf, 'base_link', 'flange', names)
        assert max(float(numpy.abs(a - b).max()) for a, b in
                   zip(mine, _tip_poses(source, base, tip, names))) < 1e-9
        robot.apply_dh(DHTable.from_file(table_file), base, tip)  # back: accepted
        robot.to_urdf(tmp_path / 'applied.urdf')
        applied = _joints(tmp_path / 'applied.urdf')
        assert {joint: applied[joint] for joint in theirs} == theirs


def test_a_row_follows_the_chains_motion_not_its_spelling(tmp_path: Path) -> None:
    robot = _rover()
    table = DHTable.from_robot(robot, 'base_link', 'hub')
    assert [row.joint_type for row in table.rows] == ['revolute', 'continuous']
    assert (table.rows[1].effort, table.rows[1].velocity) == (None, None)
    table.rows[1].joint_type = 'revolute'  # a table written before continuous rows
    robot.apply_dh(table, 'base_link', 'hub')
    assert robot.get_joint('wheel_joint').type.value == 'continuous'
    table.rows[1].joint_type = 'prismatic'
    with pytest.raises(ModelError, match="DH row 'wheel_joint' is prismatic, joint "
                       "'wheel_joint' is continuous"):
        robot.apply_dh(table, 'base_link', 'hub')
    with pytest.raises(ModelError, match='joint_type must be revolute, continuous or '
                       'prismatic'):
        DHRow(1, joint_type='hinge')


@pytest.mark.slow  # robotics-toolbox alone takes 2-3 s to import
def test_robotics_toolbox_turns_a_continuous_row_as_the_urdf_does(tmp_path: Path) -> None:
    rtb = require_module('roboticstoolbox')
    numpy = require_module('numpy')
    path = example_robot(PR2)
    table = DHTable.from_robot(Robot.from_urdf(path), *ARM, 'standard')
    from spatialmath import SE3

    def pose(origin):
        return SE3(*origin.xyz) * SE3.RPY(*origin.rpy, order='zyx')
    links = [rtb.RevoluteDH(a=row.a, alpha=row.alpha, d=row.d, offset=row.theta_offset,
                            qlim=None if row.joint_type == 'continuous'
                            else [row.lower, row.upper]) for row in table.rows]
    theirs = rtb.DHRobot(links, base=pose(table.base), tool=pose(table.tool))
    names = [row.name for row in table.rows]
    yourdfpy = require_module('yourdfpy')
    model = yourdfpy.URDF.load(str(path), load_meshes=False)
    rng = random.Random(9)
    for _ in range(20):
        q = [rng.uniform(-9.0, 9.0) if row.joint_type == 'continuous'
             else rng.uniform(-0.5, 0.5) for row in table.rows]
        model.update_cfg(dict(zip(names, q)))
        assert numpy.abs(theirs.fkine(q).A - model.get_transform(ARM[1], ARM[0])).max() < 1e-9
