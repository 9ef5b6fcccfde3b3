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


"""A ROS 2 workspace as users have one: Xacro in .urdf files, packages, long-running reads."""

from __future__ import annotations

import os
from pathlib import Path
import re
import subprocess
import sys

from click.testing import CliRunner
from helpers import canonical, corpus_cases, environment, require_module
import pytest

from urdfgenpy_ros import ParseError, Robot
from urdfgenpy_ros.cli import main as cli
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.formats.detect import is_xacro, xacro_evidence_in
from urdfgenpy_ros.resources import PackageResolver

WORKSPACE = Path(__file__).resolve().parent / 'fixtures' / 'workspace'
PREFIX = WORKSPACE / 'prefix'
ROBOT = PREFIX / 'share' / 'ws_robot_description' / 'urdf' / 'ws_robot.urdf'
RELATIVE = PREFIX / 'share' / 'ws_robot_description' / 'urdf' / 'relative_uri.urdf'
SOURCED = {'AMENT_PREFIX_PATH': str(PREFIX)}


def real_xacro(path: Path, *arguments: str) -> str:
    """Expand ``path`` with the xacro command, in its own process, in the sourced prefix."""
    require_module('xacro')
    command = [str(Path(sys.executable).with_name('xacro')), str(path), *arguments]
    result = subprocess.run(command, capture_output=True, text=True, timeout=60,
                            env=dict(os.environ, **SOURCED))
    assert result.returncode == 0, result.stderr
    return result.stdout


def names(urdf: str) -> tuple[list[str], list[str]]:
    """Return the link and joint names of URDF text, read with lxml alone."""
    from lxml import etree
    root = etree.fromstring(urdf.encode())
    return ([e.get('name') for e in root.findall('link')],
            [e.get('name') for e in root.findall('joint')])


# ---- long-running processes ----------------------------------------------------------

@pytest.mark.slow
def test_200_reads_in_one_process_stay_the_same_and_flat() -> None:
    import gc
    import tracemalloc
    xacro = require_module('xacro')
    included = []
    tracemalloc.start()
    try:
        with environment(SOURCED):
            for index in range(200):
                robot = Robot.from_xacro(ROBOT, {'prefix': 'a_'})
                included.append(robot.included_files)
                if index == 19:
                    gc.collect()
                    early = tracemalloc.get_traced_memory()[0]
        gc.collect()
        late = tracemalloc.get_traced_memory()[0]
    finally:
        tracemalloc.stop()
    wheel = str((PREFIX / 'share' / 'ws_parts' / 'urdf' / 'wheel.xacro').resolve())
    assert included[0] == [str(ROBOT.resolve()), wheel]
    assert all(files == included[0] for files in included)
    assert xacro.all_includes == []  # nothing left in xacro's module state between reads
    # No times: what the process holds after 200 reads is what it held after 20 (one read
    # of this robot allocates about 0.3 MiB: 180 kept reads would be tens of MiB).
    assert late - early < 512 * 1024, f'{(late - early) / 1024:.0f} KiB more after 180 reads'


# ---- Xacro whatever the suffix -------------------------------------------------------

@pytest.mark.parametrize('text, what', [
    (b'<robot name="r"><link name="${p}base"/></robot>', '<link name> uses ${...}'),
    (b'<robot name="r"><link name="$(arg p)base"/></robot>', '<link name> uses $(...)'),
    (b'<robot name="r" xmlns:xacro="http://wiki.ros.org/xacro"><xacro:property name="a" '
     b'value="1"/><link name="b"/></robot>', 'it has <xacro:property> elements'),
    (b'<robot name="r" xmlns:xacro="http://ros.org/wiki/xacro"><gazebo><plugin filename="'
     b'a">$(find p)/c.yaml</plugin></gazebo></robot>', '<plugin> text uses $(...)'),
])
def test_xacro_is_told_by_content(text: bytes, what: str) -> None:
    evidence = xacro_evidence_in(text, 'r.urdf')
    assert evidence is not None and evidence.what.startswith(what)


@pytest.mark.parametrize('text', [
    b'<robot name="r"><link name="base"/></robot>',
    # a declaration alone, as xacro outputs keep it: xacro gives the same model
    b'<robot name="r" xmlns:xacro="http://ros.org/wiki/xacro"><link name="b"/></robot>',
    # text for Gazebo in a file that is not Xacro
    b'<robot name="r"><gazebo><plugin filename="a">$(find p)/c.yaml</plugin></gazebo></robot>',
    # the call of a macro nothing defines (urdf's pr2_desc.urdf): xacro could not expand it
    b'<robot name="r" xmlns:xacro="http://ros.org/wiki/xacro"><xacro:gazebo_v0 name="h"/>'
    b'</robot>',
    b'<!-- <xacro:include filename="$(find p)/a.xacro"/> ${x} --><robot name="r"/>',
])
def test_plain_urdf_is_not_taken_for_xacro(text: bytes) -> None:
    assert xacro_evidence_in(text) is None


def test_from_urdf_refuses_xacro_in_one_line_naming_from_xacro() -> None:
    assert is_xacro(ROBOT) and not is_xacro(RELATIVE)
    with pytest.raises(ParseError) as raised:
        Robot.from_urdf(ROBOT)
    message = str(raised.value)
    assert message.startswith(f'{ROBOT}:4:3: error X002 this file is Xacro (it has '
                              '<xacro:arg> elements)'), message
    assert 'Robot.from_xacro' in message and '\n' not in message


@pytest.mark.parametrize('arguments, prefix', [((), ''), (('prefix:=left_',), 'left_')])
def test_tree_check_and_convert_expand_xacro_in_a_urdf_file(
        arguments: tuple[str, ...], prefix: str, tmp_path: Path) -> None:
    expected = real_xacro(ROBOT, *arguments)
    links, joints = names(expected)
    assert links[0] == f'{prefix}base_link'
    runner = CliRunner()
    with environment(SOURCED):
        tree = runner.invoke(cli, ['tree', str(ROBOT), *arguments])
        check = runner.invoke(cli, ['check', '--strict', str(ROBOT), *arguments])
        target = tmp_path / 'out.urdf'
        convert = runner.invoke(cli, ['convert', str(ROBOT), str(target), *arguments])
    assert tree.exit_code == 0, tree.output
    assert set(links + joints) <= set(re.findall(r'[\w/]+', tree.stdout))
    assert tree.stdout.rstrip() == Robot.from_urdf_string(expected).tree_string().rstrip()
    note = tree.stderr.strip().splitlines()
    assert len(note) == 1 and 'warning X101 the file is Xacro' in note[0], tree.stderr
    assert (' '.join(arguments) or 'no arguments') in note[0]
    # check: the model xacro makes is clean but for the note itself
    assert check.exit_code == 1 and 'warning X101' in check.stdout, check.output
    assert 'error' not in check.stdout.replace('0 error(s)', '')
    allowed = ('X101', 'C401') if prefix else ('X101',)  # no base_link with a prefix
    assert [line for line in check.stdout.splitlines() if ' warning ' in line
            and line.split(' warning ')[1][:4] not in allowed] == [], check.stdout
    assert convert.exit_code == 0, convert.output
    assert canonical(target.read_text()) == canonical(expected)


def test_arguments_reach_the_loader_the_node_and_init_use() -> None:
    with environment(SOURCED):
        robot = load(ROBOT, {'prefix': 'r_'})
    expected = real_xacro(ROBOT, 'prefix:=r_')
    assert canonical(robot.to_urdf()) == canonical(expected)
    assert [w.code for w in robot.read_warnings] == ['X101']


# ---- package:// and file:// ----------------------------------------------------------

def test_a_folder_named_like_a_package_without_package_xml_is_passed_by() -> None:
    decoy = WORKSPACE / 'decoy'
    assert (decoy / 'ws_parts').is_dir() and not (decoy / 'ws_parts' / 'package.xml').exists()
    resolver = PackageResolver([decoy, PREFIX / 'share'])
    assert resolver.find('ws_parts') == PREFIX / 'share' / 'ws_parts'
    mesh = resolver.resolve('package://ws_parts/meshes/wheel.stl')
    assert mesh == PREFIX / 'share' / 'ws_parts' / 'meshes' / 'wheel.stl'
    with environment(SOURCED):  # ahead of the ament index too
        assert PackageResolver([decoy]).find('ws_parts') == PREFIX / 'share' / 'ws_parts'
    # and the check of the robot finds every mesh: no false missing-mesh findings
    with environment(SOURCED):
        robot = Robot.from_xacro(ROBOT)
        findings = robot.validate(search_paths=[decoy])
    assert [f.code for f in findings] == [], [str(f) for f in findings]


def test_relative_file_uris_resolve_beside_the_file_with_a_warning() -> None:
    resolver = PackageResolver()
    found = resolver.resolve('file://meshes/cover.stl', RELATIVE.parent)
    assert found == RELATIVE.parent / 'meshes' / 'cover.stl'
    trimesh = pytest.importorskip('trimesh')
    assert trimesh.load(str(found)).is_watertight  # a real mesh, read by another tool
    result = CliRunner().invoke(cli, ['check', str(RELATIVE)])
    # (its one link has no mass: I209 says libsdformat keeps no link of it)
    lines = [line for line in result.stdout.strip().splitlines() if ' I209 ' not in line]
    assert result.exit_code == 0, result.output
    assert len(lines) == 1 and 'warning R308' in lines[0] and 'not portable' in lines[0]
    assert lines[0].startswith(f'{RELATIVE}:7:9: ')


# ---- init --from a saved robot keeps its sensors -------------------------------------

def sensor_robot() -> Robot:
    """Return the pan-tilt unit with a camera, a lidar, an IMU and a force-torque sensor."""
    from urdfgenpy_ros.examples import pan_tilt_unit
    from urdfgenpy_ros.model.geometry import Origin
    from urdfgenpy_ros.model.sensors import Camera, ForceTorque, Imu, Lidar
    robot = pan_tilt_unit()
    robot.get_link('tilt_link').add_sensor(Camera('head_cam', origin=Origin(xyz=(0.05, 0, 0))))
    robot.get_link('base_plate').add_sensor(Lidar('scan', topic='laser/scan'))
    robot.get_link('base_plate').add_sensor(Imu('imu'))
    robot.get_joint('pan_joint').add_sensor(ForceTorque('pan_ft'))
    return robot


def test_init_from_a_saved_robot_bridges_what_the_builder_does(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import yaml
    from urdfgenpy_ros.scaffold.command import main as init
    module = tmp_path / 'sensor_robot_module.py'
    module.write_text('from test_workspace import sensor_robot\n')
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.syspath_prepend(str(Path(__file__).parent))
    saved = tmp_path / 'saved.urdf'
    sensor_robot().save(saved)
    for kind, source in (('built', 'sensor_robot_module:sensor_robot'), ('read', str(saved))):
        assert init(['ptu_description', '--destination-directory', str(tmp_path / kind),
                     '--from', source]) == 0
    built, read = tmp_path / 'built' / 'ptu_description', tmp_path / 'read' / 'ptu_description'
    bridge = yaml.safe_load((built / 'config' / 'ros_gz_bridge.yaml').read_text())
    assert [entry['ros_topic_name'] for entry in bridge] == [
        'clock', 'laser/scan', 'imu', 'head_cam', 'pan_ft']
    rviz = yaml.safe_load((built / 'rviz' / 'display.rviz').read_text())
    displays = {display['Name']: (display['Class'], display.get('Topic', {}).get('Value'))
                for display in rviz['Visualization Manager']['Displays']}
    assert displays['head_cam'] == ('rviz_default_plugins/Image', '/head_cam')
    assert displays['scan'] == ('rviz_default_plugins/LaserScan', '/laser/scan')
    compared = [path.relative_to(built) for folder in ('config', 'launch', 'rviz')
                for path in sorted((built / folder).rglob('*')) if path.is_file()]
    assert len(compared) >= 4
    for relative in compared:
        assert (read / relative).read_bytes() == (built / relative).read_bytes(), relative


# ---- the node and init on the workspace ----------------------------------------------

def test_the_node_publishes_what_xacro_makes_of_a_urdf_file_with_arguments(graph) -> None:
    from std_msgs.msg import String
    expected = real_xacro(ROBOT, 'prefix:=n_')
    graph.env['AMENT_PREFIX_PATH'] = str(PREFIX)
    descriptions = graph.collect(String, 'robot_description', latched=True)
    graph.start(f'model:={ROBOT}', "xacro_args:=['prefix:=n_']")
    assert graph.spin_until(lambda: descriptions, 30)
    assert canonical(descriptions[-1].data) == canonical(expected)


def _meshes_by_name(urdf: str) -> str:
    """Return URDF text with every mesh URI reduced to its file name."""
    return re.sub(r'filename="[^"]*/([^"/]+)"', r'filename="\1"', urdf)


def test_init_from_a_xacro_urdf_makes_a_package_xacro_expands_to_the_same_model(
        tmp_path: Path) -> None:
    from helpers import load_yourdfpy, snapshot
    from urdfgenpy_ros.scaffold.command import main as init
    with environment(SOURCED):
        assert init(['wsbot_description', '--destination-directory', str(tmp_path / 'src'),
                     '--from', str(ROBOT), '--xacro-args', 'prefix:=i_']) == 0
    package = tmp_path / 'src' / 'wsbot_description'
    # A prefix that holds the new package, as `colcon build` would install it.
    prefix = tmp_path / 'install'
    (prefix / 'share' / 'ament_index' / 'resource_index' / 'packages').mkdir(parents=True)
    (prefix / 'share' / 'ament_index' / 'resource_index' / 'packages' /
     'wsbot_description').write_text('')
    (prefix / 'share' / 'wsbot_description').symlink_to(package, target_is_directory=True)
    main = package / 'urdf' / 'ws_robot.urdf.xacro'
    require_module('xacro')
    result = subprocess.run([str(Path(sys.executable).with_name('xacro')), str(main)],
                            capture_output=True, text=True, timeout=60,
                            env=dict(os.environ, AMENT_PREFIX_PATH=str(prefix)))
    assert result.returncode == 0, result.stderr
    ours, theirs = tmp_path / 'ours.urdf', tmp_path / 'theirs.urdf'
    ours.write_text(_meshes_by_name(result.stdout))
    theirs.write_text(_meshes_by_name(real_xacro(ROBOT, 'prefix:=i_')))
    assert snapshot(load_yourdfpy(ours)) == snapshot(load_yourdfpy(theirs))
    # the meshes were copied in, byte for byte
    assert (package / 'meshes' / 'wheel.stl').read_bytes() == (
        PREFIX / 'share' / 'ws_parts' / 'meshes' / 'wheel.stl').read_bytes()
    assert 'package://wsbot_description/meshes/cover.stl' in result.stdout


# ---- the corpus: description packages of several vendors -----------------------------

CORPUS_MODELS = [
    ('turtlebot3/turtlebot3_description/urdf/turtlebot3_burger.urdf', ()),
    ('turtlebot3/turtlebot3_description/urdf/turtlebot3_waffle.urdf', ('namespace:=tb3_0/',)),
    ('turtlebot3/turtlebot3_description/urdf/turtlebot3_waffle_pi.urdf',
     ('namespace:=tb3_1/',)),
    ('ur_description/urdf/ur.urdf.xacro', ('name:=ur', 'ur_type:=ur5e')),
    ('kortex/kortex_description/robots/gen3.xacro', ('dof:=7', 'vision:=true')),
    ('husky/husky_description/urdf/husky.urdf.xacro', ('is_sim:=true',)),
]


@pytest.fixture(scope='module')
def corpus_index(tmp_path_factory: pytest.TempPathFactory) -> dict[str, str]:
    """Return the environment of a shell with the corpus packages sourced."""
    from helpers import ament_index, CORPUS, NO_CORPUS
    if not CORPUS.is_dir():
        pytest.skip(NO_CORPUS)
    return ament_index(tmp_path_factory.mktemp('corpus_prefix'))


@pytest.mark.parametrize('name, arguments', corpus_cases(
    CORPUS_MODELS, [f'{n} {" ".join(a)}' for n, a in CORPUS_MODELS]))
def test_corpus_packages_convert_like_xacro_in_a_sourced_shell(
        name: str, arguments: tuple[str, ...], corpus_index: dict[str, str],
        tmp_path: Path) -> None:
    from helpers import CORPUS
    path = CORPUS / name
    require_module('xacro')
    expected = subprocess.run([str(Path(sys.executable).with_name('xacro')), str(path),
                               *arguments], capture_output=True, text=True, timeout=120,
                              env=dict(os.environ, **corpus_index))
    assert expected.returncode == 0, expected.stderr
    target = tmp_path / 'out.urdf'
    with environment(corpus_index):
        result = CliRunner().invoke(cli, ['convert', str(path), str(target), *arguments])
        tree = CliRunner().invoke(cli, ['tree', str(path), *arguments])
    assert result.exit_code == 0, result.output
    assert canonical(target.read_text()) == canonical(expected.stdout)
    links, _ = names(expected.stdout)
    assert tree.exit_code == 0 and links[0] in tree.stdout
    if path.suffix == '.urdf':  # said once, on stderr
        assert result.stderr.count('warning X101') == 1, result.stderr


def test_init_from_turtlebot3_urdf_expands_in_xacro_to_the_same_model(
        corpus_index: dict[str, str], tmp_path: Path) -> None:
    from helpers import CORPUS, load_yourdfpy, snapshot
    from urdfgenpy_ros.scaffold.command import main as init
    source = CORPUS / 'turtlebot3/turtlebot3_description/urdf/turtlebot3_waffle_pi.urdf'
    with environment(corpus_index):
        assert init(['waffle_pi_description', '--destination-directory', str(tmp_path),
                     '--from', str(source), '--xacro-args', 'namespace:=tb3_0/']) == 0
    package = tmp_path / 'waffle_pi_description'
    prefix = Path(corpus_index['AMENT_PREFIX_PATH'])
    (prefix / 'share' / 'ament_index' / 'resource_index' / 'packages' /
     'waffle_pi_description').write_text('')
    (prefix / 'share' / 'waffle_pi_description').symlink_to(package)
    xacro = str(Path(sys.executable).with_name('xacro'))
    ours = subprocess.run([xacro, str(package / 'urdf' / 'turtlebot3_waffle_pi.urdf.xacro')],
                          capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, **corpus_index))
    assert ours.returncode == 0, ours.stderr  # was: "Property names must not start ..."
    theirs = subprocess.run([xacro, str(source), 'namespace:=tb3_0/'], capture_output=True,
                            text=True, timeout=120, env=dict(os.environ, **corpus_index))
    (tmp_path / 'ours.urdf').write_text(_meshes_by_name(ours.stdout))
    (tmp_path / 'theirs.urdf').write_text(_meshes_by_name(theirs.stdout))
    assert snapshot(load_yourdfpy(tmp_path / 'ours.urdf')) == \
        snapshot(load_yourdfpy(tmp_path / 'theirs.urdf'))
    assert names(ours.stdout)[0][0] == 'tb3_0/base_footprint'


def test_an_unfound_find_is_one_line_naming_the_package(
        monkeypatch: pytest.MonkeyPatch) -> None:
    require_module('xacro')
    monkeypatch.delenv('AMENT_PREFIX_PATH', raising=False)
    monkeypatch.delenv('ROS_PACKAGE_PATH', raising=False)
    with pytest.raises(ParseError) as raised:
        Robot.from_xacro(ROBOT)
    assert str(raised.value) == (
        f"{ROBOT}: error X001 xacro: $(find ws_parts): package 'ws_parts' not found (source "
        'the workspace that holds it, or pass its folder in search_paths / --package-path)')
    # and the next read, with the package found, is not disturbed by the failed one
    robot = Robot.from_xacro(ROBOT, search_paths=[PREFIX / 'share'])
    assert len(robot.included_files) == 2


def _description_files() -> list[Path]:
    """Every URDF and Xacro file at hand: fixtures, installed robots, the corpus."""
    from registry_robots import robots
    files = sorted((Path(__file__).parent / 'fixtures').rglob('*.urdf'))
    files += sorted((Path(__file__).parent / 'fixtures').rglob('*.xacro'))
    files += robots()
    if os.environ.get('URDFGENPY_CORPUS') and Path(os.environ['URDFGENPY_CORPUS']).is_dir():
        corpus = Path(os.environ['URDFGENPY_CORPUS'])
        files += sorted(corpus.rglob('*.urdf')) + sorted(corpus.rglob('*.xacro'))
    return files


@pytest.mark.parametrize('text', [
    # a prefix of another name bound to the xacro namespace
    b'<robot name="r" xmlns:x="http://ros.org/wiki/xacro"><x:property name="a" value="1"/>'
    b'</robot>',
    b"<robot name='r' xmlns:x='http://www.ros.org/wiki/xacro'><link name='a' x:b='1'/></robot>",
    # the default namespace is xacro's
    b'<robot xmlns="http://ros.org/wiki/xacro" name="r"><macro name="m"/></robot>',
    b'<robot name="r"><!-- ${x} --><link name="${p}"/></robot>',
    b'<robot name="r" xmlns:xacro="http://ros.org/wiki/xacro"><!-- xacro: --><xacro:if '
    b'value="1"/></robot>',
])
def test_xacro_in_less_usual_spellings_is_told(text: bytes) -> None:
    assert xacro_evidence_in(text, 'r.urdf') is not None


def test_quick_decision_agrees_with_the_full_look_on_every_file(monkeypatch) -> None:
    """Files are decided 'not Xacro' without parsing; the full walk must say the same."""
    from urdfgenpy_ros.formats import detect
    files = _description_files()
    assert len(files) > 20
    quick = {path: xacro_evidence_in(path.read_bytes(), str(path)) for path in files}
    monkeypatch.setattr(detect, '_may_be_xacro', lambda data: True)
    full = {path: xacro_evidence_in(path.read_bytes(), str(path)) for path in files}
    assert quick == full
    assert any(found is None for found in full.values())
    assert any(found is not None for found in full.values())
