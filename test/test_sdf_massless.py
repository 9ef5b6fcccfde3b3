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
Masses as libsdformat's URDF conversion sees them, judged by libsdformat itself.

A ``<mass>`` without ``<inertia>`` is kept with a zero tensor (not SDF's default 1 kg), and
a root that the conversion leaves out with everything below it is a finding (I209).
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
import pytest
import test_sdf

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main

pytestmark = pytest.mark.engine  # libsdformat's checker

check_sdf = test_sdf.check_sdf  # the session fixture running libsdformat's checker
TENSOR = '<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>'
CAMERA = f"""<?xml version="1.0"?>
<robot name="cam">
  <link name="base_link"><inertial><mass value="1"/>{TENSOR}</inertial></link>
  <link name="camera">
    <inertial><origin xyz="0.01 0 0.02"/><mass value="0.072"/></inertial>
    <visual><geometry><box size="0.02 0.09 0.025"/></geometry></visual>
  </link>
  <joint name="cam_joint" type="revolute"><parent link="base_link"/><child link="camera"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_a_mass_without_inertia_keeps_its_mass_in_sdf(check_sdf, tmp_path: Path) -> None:
    source = tmp_path / 'cam.urdf'
    source.write_text(CAMERA)
    code, _, theirs, _, _ = check_sdf(source)  # libsdformat's own URDF conversion
    assert code == 0 and theirs['camera'][0] == pytest.approx(0.072)
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'cam.sdf')])
    assert result.exit_code == 0, result.output
    notes = [line for line in result.stderr.splitlines() if ': note: ' in line]
    assert len(notes) == 1 and "link 'camera'" in notes[0] and '0.072 kg' in notes[0]
    assert notes[0].startswith(f'{source}:5:')
    code, _, ours, _, _ = check_sdf(tmp_path / 'cam.sdf')
    assert code == 0
    assert ours['camera'] == pytest.approx(theirs['camera'])  # mass, centre, moments


def _robot(links: dict[str, bool], joints: list[tuple[str, str, str]]) -> str:
    body = ''.join(f'<link name="{name}">'
                   + (f'<inertial><mass value="1"/>{TENSOR}</inertial>' if heavy else '')
                   + '<visual><geometry><box size="0.1 0.1 0.1"/></geometry></visual></link>'
                   for name, heavy in links.items())
    for parent, child, kind in joints:
        extra = '<axis xyz="0 0 1"/>' if kind != 'fixed' else ''
        body += (f'<joint name="{child}_joint" type="{kind}"><parent link="{parent}"/>'
                 f'<child link="{child}"/>{extra}</joint>')
    return f'<?xml version="1.0"?><robot name="r">{body}</robot>'


@pytest.mark.parametrize('links, joints', [
    ({'base_link': False, 'arm': False}, [('base_link', 'arm', 'continuous')]),
    ({'base_footprint': False, 'base_link': False, 'wheel': True},
     [('base_footprint', 'base_link', 'fixed'), ('base_link', 'wheel', 'continuous')]),
    ({'base_link': False}, []),
    ({'base_footprint': False, 'base_link': True, 'wheel': True},  # kept: lumped mass
     [('base_footprint', 'base_link', 'fixed'), ('base_link', 'wheel', 'continuous')]),
    ({'base_link': True, 'arm': False}, [('base_link', 'arm', 'continuous')]),
], ids=['all-massless', 'massless-root-and-fixed-child', 'one-massless-link',
        'massless-root-with-mass-fixed-below', 'massive-root'])
def test_a_root_libsdformat_leaves_out_is_a_finding(
        check_sdf, tmp_path: Path, links: dict[str, bool],
        joints: list[tuple[str, str, str]]) -> None:
    path = tmp_path / 'r.urdf'
    path.write_text(_robot(links, joints))
    code, _, _, _, errors = check_sdf(path)
    refused = 'A model must have at least one link' in errors
    assert refused == (code != 0), errors
    found = [f for f in Robot.from_urdf(path).validate() if f.code == 'I209']
    assert bool(found) == refused
    if found:
        assert found[0].element == f"link '{next(iter(links))}'"


TOOL = f"""<?xml version="1.0"?>
<robot name="tcp">
  <link name="base_link"/>
  <link name="arm"><inertial><mass value="0.3"/>{TENSOR}</inertial></link>
  <joint name="j" type="revolute"><parent link="base_link"/><child link="arm"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <link name="tool0"/>
  <joint name="tcp_joint" type="fixed"><parent link="arm"/><child link="tool0"/>
    <origin xyz="0 0 0.2"/></joint>
</robot>
"""


def test_each_link_sdf_gives_its_default_kilogram_is_said(check_sdf, tmp_path: Path) -> None:
    """A massless root weighs 1 kg in the SDF: convert says so; a massless tool is a frame."""
    source = tmp_path / 'tcp.urdf'
    source.write_text(TOOL)
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'tcp.sdf')])
    assert result.exit_code == 0, result.output
    said = {line.split("link '")[1].split("'")[0]: line for line in result.stderr.splitlines()
            if 'SDF gives it its default mass of 1 kg' in line}
    code, _, ours, _, _ = check_sdf(tmp_path / 'tcp.sdf')
    assert code == 0
    defaulted = {name for name, inertial in ours.items()
                 if inertial == pytest.approx((1, 0, 0, 0, 1, 1, 1))}
    assert set(said) == defaulted == {'base_link'}  # what libsdformat reads
    frames = test_sdf.sdf_frames(check_sdf, tmp_path / 'tcp.sdf')
    assert set(frames) == {'tcp_joint', 'tool0'} and 'tool0' not in ours
    assert frames['tool0'][:3] == pytest.approx([0, 0, 0.2])


def _box(size: str = '0.1 0.1 0.1') -> str:
    return f'<visual><geometry><box size="{size}"/></geometry></visual>'


# A mobile base as Panther describes itself: a heavy body, wheels, and massless links on
# fixed joints (a cover with a visual, sensors' frames), a camera whose model gives a mass
# and no tensor, and a massless frame below a massless frame.
PANTHER_LIKE = f"""<?xml version="1.0"?>
<robot name="base">
  <link name="base_link"><inertial><origin xyz="0 0 0.1"/><mass value="40"/>
    <inertia ixx="1" ixy="0" ixz="0" iyy="2" iyz="0" izz="2.5"/></inertial>{_box('0.8 0.6 0.2')}
  </link>
  <link name="cover_link">{_box('0.8 0.6 0.01')}</link>
  <joint name="cover_joint" type="fixed"><parent link="base_link"/><child link="cover_link"/>
    <origin xyz="0 0 0.2"/></joint>
  <link name="imu_link"/>
  <joint name="imu_joint" type="fixed"><parent link="cover_link"/><child link="imu_link"/>
    <origin xyz="0.1 0 0.01" rpy="0 0 1.5707963267948966"/></joint>
  <link name="imu_frame"/>
  <joint name="imu_frame_joint" type="fixed"><parent link="imu_link"/>
    <child link="imu_frame"/><origin xyz="0 0.02 0"/></joint>
  <link name="camera_link"><inertial><origin xyz="0.01 0 0.02"/><mass value="0.072"/>
    </inertial>{_box('0.02 0.09 0.025')}</link>
  <joint name="camera_joint" type="fixed"><parent link="base_link"/>
    <child link="camera_link"/><origin xyz="0.4 0 0.15" rpy="0 0.3 0"/></joint>
  <link name="wheel"><inertial><mass value="3"/>{TENSOR}</inertial>{_box()}</link>
  <joint name="wheel_joint" type="continuous"><parent link="base_link"/>
    <child link="wheel"/><origin xyz="0.3 0.35 -0.25"/><axis xyz="0 1 0"/></joint>
</robot>
"""


@pytest.mark.parametrize('lump', [False, True], ids=['links', 'lump-fixed'])
def test_massless_fixed_links_are_frames_and_weigh_nothing(
        check_sdf, tmp_path: Path, lump: bool) -> None:
    source = tmp_path / 'base.urdf'
    source.write_text(PANTHER_LIKE)
    code, _, theirs, _, errors = check_sdf(source)  # libsdformat's own URDF conversion
    assert code == 0, errors
    options = ['--lump-fixed'] if lump else []
    result = CliRunner().invoke(main, ['convert', *options, str(source),
                                       str(tmp_path / 'base.sdf')])
    assert result.exit_code == 0, result.output
    code, _, ours, _, errors = check_sdf(tmp_path / 'base.sdf')
    assert code == 0, errors
    total = sum(inertial[0] for inertial in ours.values())
    assert total == pytest.approx(sum(inertial[0] for inertial in theirs.values()))
    assert total == pytest.approx(43.072)
    frames = test_sdf.sdf_frames(check_sdf, tmp_path / 'base.sdf')
    massless = {'cover_link', 'imu_link', 'imu_frame'}
    assert massless <= set(frames) and not massless & set(ours)
    if lump:  # the camera's mass and centre of mass, merged into the base as libsdformat does
        assert 'camera_link' in frames and set(ours) == set(theirs) == {'base_link', 'wheel'}
        assert ours['base_link'] == pytest.approx(theirs['base_link'], rel=1e-9, abs=1e-12)
    else:
        assert ours['camera_link'][:4] == pytest.approx([0.072, 0.01, 0, 0.02])
