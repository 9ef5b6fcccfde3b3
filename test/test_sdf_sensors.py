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

"""Sensors of links that SDF export lumps: judged against libsdformat's own conversion."""

from __future__ import annotations

from importlib import metadata
from pathlib import Path
import subprocess

from helpers import build_sdf_checker, require_module
from lxml import etree
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.model.errors import ModelError

FIXTURES = Path(__file__).parent / 'fixtures' / 'sdf'


@pytest.fixture(scope='session')
def sdformat_sensors(tmp_path_factory: pytest.TempPathFactory):
    """Return a function: file -> {(link, sensor): 4x4 pose in the link} as libsdformat sees it."""
    binary = build_sdf_checker(tmp_path_factory.mktemp('checker'))
    euler_matrix = require_module('trimesh.transformations').euler_matrix

    def run(path: Path) -> dict[tuple[str, str], object]:
        result = subprocess.run([str(binary), '--sdf', str(path)], capture_output=True,
                                text=True, timeout=120)
        assert result.returncode == 0, result.stderr
        sensors = {}
        for link in etree.fromstring(result.stdout.encode()).iter('link'):
            for sensor in link.findall('sensor'):
                pose = sensor.find('pose')
                assert pose is None or not pose.get('relative_to')
                values = [float(v) for v in (pose.text.split() if pose is not None else [0] * 6)]
                matrix = euler_matrix(*values[3:], axes='sxyz')
                matrix[:3, 3] = values[:3]
                sensors[(link.get('name'), sensor.get('name'))] = matrix
        return sensors
    return run


def _example_robot(relative: str) -> Path:
    """Return a robot of the example-robot-data wheel; skip when it is not installed."""
    try:
        distribution = metadata.distribution('example-robot-data')
    except metadata.PackageNotFoundError:
        pytest.skip('example-robot-data is not installed (pip install example-robot-data)')
    return Path(str(distribution.locate_file(
        f'cmeel.prefix/share/example-robot-data/robots/{relative}')))


@pytest.mark.parametrize('source', [
    'fixture', 'go1_description/urdf/go1.urdf', 'baxter_description/urdf/baxter.urdf'])
@pytest.mark.engine
def test_lumped_links_keep_their_sensors_where_sdformat_puts_them(
        source: str, sdformat_sensors, tmp_path: Path) -> None:
    urdf = (FIXTURES / 'lumped_sensors.urdf' if source == 'fixture'
            else _example_robot(source))
    ours = tmp_path / 'lumped.sdf'
    Robot.from_urdf(urdf).to_sdf(ours, lump_fixed=True)
    theirs = sdformat_sensors(urdf)  # libsdformat's conversion of the same URDF
    mine = sdformat_sensors(ours)
    assert set(mine) == set(theirs)
    if source == 'fixture':
        assert len(theirs) == 4  # three of them on links merged into their parents
    for key, matrix in theirs.items():
        # libsdformat writes its converted poses with six significant digits
        assert mine[key] == pytest.approx(matrix, abs=1e-5), key


def test_a_sensor_pose_relative_to_a_frame_stays_and_a_bad_one_is_named() -> None:
    robot = Robot.from_urdf(FIXTURES / 'lumped_sensors.urdf')
    pose = robot.get_link('camera_link').extensions[0].element.find('sensor/pose')
    pose.set('relative_to', 'mast')
    assert '<pose relative_to="mast">0.01 0 0.02 0 0.1 0.2</pose>' in robot.to_sdf(
        lump_fixed=True)
    del pose.attrib['relative_to']
    pose.text = '0.01 0 0.02'
    with pytest.raises(ModelError, match="sensor 'front_camera' has pose '0.01 0 0.02'"):
        robot.to_sdf(lump_fixed=True)


@pytest.mark.engine
def test_a_sensor_pose_in_degrees_is_merged_as_its_angles_mean(
        sdformat_sensors, tmp_path: Path) -> None:
    # libsdformat 12 reads the numbers of <pose degrees="true"> as radians when it merges the
    # link; the reference is its merge of the same pose written in radians.
    text = (FIXTURES / 'lumped_sensors.urdf').read_text()
    degrees = tmp_path / 'degrees.urdf'
    degrees.write_text(text.replace('<pose>0.01 0 0.02 0 0.1 0.2</pose>',
                                    '<pose degrees="true">0.01 0 0.02 0 10 20</pose>'))
    radians = tmp_path / 'radians.urdf'
    radians.write_text(text.replace('<pose>0.01 0 0.02 0 0.1 0.2</pose>',
                                    '<pose>0.01 0 0.02 0 0.17453292519943295 '
                                    '0.3490658503988659</pose>'))
    ours = tmp_path / 'ours.sdf'
    Robot.from_urdf(degrees).to_sdf(ours, lump_fixed=True)
    key = ('base_link', 'front_camera')
    assert sdformat_sensors(ours)[key] == pytest.approx(sdformat_sensors(radians)[key],
                                                        abs=1e-5)
