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
Merging fixed links for URDF output: judged by libsdformat, pinocchio and check_urdf.

libsdformat's own URDF conversion lumps fixed joints; the merged links' masses, centres
of mass and principal moments must be its figures. pinocchio gives every kept frame's pose.
"""

from __future__ import annotations

from pathlib import Path
import random
import subprocess

from click.testing import CliRunner
from helpers import assert_check_urdf_accepts, build_sdf_checker, require_module
import pytest
from registry_robots import robot as registry_robot

from urdfgenpy_ros import ModelError, Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.reshape.lumping import lumps

ROBOTS = ['upkie.urdf', 'icub.urdf', 'so101.urdf', 'kinova_robotiq.urdf', 'panda.urdf',
          'cookie.urdf']


@pytest.fixture(scope='module')
def sdformat_inertials(tmp_path_factory: pytest.TempPathFactory):
    """Return a function giving libsdformat's inertial of each link of a file."""
    binary = build_sdf_checker(tmp_path_factory.mktemp('checker'))

    def run(path: Path) -> dict[str, list[float]]:
        result = subprocess.run([str(binary), str(path)], capture_output=True, text=True,
                                timeout=60)
        assert result.returncode == 0, result.stderr
        return {name: [float(value) for value in rest]
                for kind, name, *rest in (line.split() for line in result.stdout.splitlines())
                if kind == 'inertial'}
    return run


def _without_mimic(robot: Robot) -> Robot:
    for joint in robot.joints:  # libsdformat's SDF 1.9 has no mimic joints
        joint.mimic = None
    return robot


def _frames(path: Path, configuration_seed: int, names: list[str]):
    """Return pinocchio's pose of every named frame at a random configuration."""
    pin = require_module('pinocchio')
    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()
    rng = random.Random(configuration_seed)
    q = pin.neutral(model)
    for joint in model.joints[1:]:
        for index in range(joint.idx_q, joint.idx_q + joint.nq):
            q[index] = rng.uniform(-1.0, 1.0)
    by_name = {model.names[j]: j for j in range(1, model.njoints)}
    pin.framesForwardKinematics(model, data, q)
    return {name: data.oMf[model.getFrameId(name)].homogeneous for name in names}, \
        {name: q[model.joints[index].idx_q] for name, index in by_name.items()}


@pytest.mark.parametrize('name', ROBOTS)
@pytest.mark.engine
def test_merged_links_carry_libsdformats_lumped_inertia(name: str, sdformat_inertials,
                                                        tmp_path: Path) -> None:
    numpy = require_module('numpy')
    source = tmp_path / 'source.urdf'
    robot = _without_mimic(Robot.from_urdf(registry_robot(name)))
    robot.to_urdf(source)
    theirs = sdformat_inertials(source)
    merged = robot.merge_fixed()
    written = tmp_path / 'merged.urdf'
    merged.to_urdf(written)
    again = sdformat_inertials(written)  # its principal moments, by libsdformat's algorithm
    absorbed = {joint.parent for joint in robot.joints if joint.type.value == 'fixed'}
    compared = 0
    for link in merged.links:
        if link.name not in theirs or link.inertial is None:
            continue
        mass, *centre = theirs[link.name][:4]
        inertial = link.inertial
        assert inertial.mass == pytest.approx(mass, rel=1e-12, abs=1e-12), link.name
        assert inertial.origin.xyz == pytest.approx(centre, abs=1e-9), link.name
        assert sorted(again[link.name][4:]) == pytest.approx(sorted(theirs[link.name][4:]),
                                                             rel=1e-9, abs=1e-12), link.name
        compared += link.name in absorbed
    assert compared or not absorbed
    assert_check_urdf_accepts(written)
    # frames survive: every link is still there, massless where it was merged
    assert [link.name for link in merged.links] == [link.name for link in robot.links]
    names = [link.name for link in robot.links]
    before, q = _frames(source, 3, names)
    after, q_after = _frames(written, 3, names)
    assert q == q_after
    for link in names:
        assert numpy.abs(before[link] - after[link]).max() < 1e-12, link


@pytest.mark.parametrize('name', ['icub.urdf', 'panda.urdf'])
def test_drop_frames_removes_merged_links_and_keeps_the_others_in_place(
        name: str, tmp_path: Path) -> None:
    numpy = require_module('numpy')
    robot = _without_mimic(Robot.from_urdf(registry_robot(name)))
    source, written = tmp_path / 'source.urdf', tmp_path / 'merged.urdf'
    robot.to_urdf(source)
    # (a fixed joint a <gazebo> block preserves stays, as in libsdformat: iCub's F/T sensors)
    fixed = [joint.child for joint in robot.joints if lumps(joint)]
    keep = fixed[:1]
    merged = robot.merge_fixed(keep=keep, drop_frames=True)
    merged.to_urdf(written)
    assert_check_urdf_accepts(written)
    left = {link.name for link in merged.links}
    assert set(keep) <= left and not (set(fixed) - set(keep)) & left
    assert all(not lumps(joint) or joint.child in keep for joint in merged.joints)
    assert sum(link.inertial.mass for link in merged.links if link.inertial) == pytest.approx(
        sum(link.inertial.mass for link in robot.links if link.inertial), rel=1e-12)
    before, _ = _frames(source, 5, sorted(left))
    after, _ = _frames(written, 5, sorted(left))
    for link in left:
        assert numpy.abs(before[link] - after[link]).max() < 1e-12, link


def test_keep_names_only_links_and_convert_merges_from_the_shell(tmp_path: Path) -> None:
    robot = Robot.from_urdf(registry_robot('panda.urdf'))
    with pytest.raises(ModelError, match="keep names no link of 'panda': 'nope'"):
        robot.merge_fixed(keep=['nope'])
    source = tmp_path / 'panda.urdf'
    robot.to_urdf(source)
    for options, links in (([], len(robot.links)), (['--drop-frames'], None)):
        target = tmp_path / f'out{len(options)}.urdf'
        result = CliRunner().invoke(main, ['convert', str(source), str(target),
                                           '--merge-fixed', *options])
        assert result.exit_code == 0, result.output
        out = Robot.from_urdf(target)
        assert len(out.links) == (links or len(robot.merge_fixed(drop_frames=True).links))
        assert_check_urdf_accepts(target)
