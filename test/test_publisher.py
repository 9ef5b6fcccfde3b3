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

"""The publisher node on a real ROS 2 graph (Jazzy wheels, isolated domain)."""

from __future__ import annotations

import os
from pathlib import Path
import shutil
import statistics
import subprocess
import sys
import time

from helpers import check_urdf, FIXTURES, require_module

import pytest

from ros_helpers import Graph, stop
from urdfgenpy_ros.examples import pan_tilt_unit

try:  # without ROS 2, every test here skips through _ros below (and fails in CI)
    import rclpy
    from sensor_msgs.msg import JointState
    from std_msgs.msg import String
    from std_srvs.srv import Trigger
except ImportError:
    pass


@pytest.fixture(autouse=True)
def _ros() -> None:
    for module in ('rclpy', 'sensor_msgs.msg', 'std_msgs.msg', 'std_srvs.srv'):
        require_module(module)


MIMIC_CHAIN = FIXTURES / 'robots/mimic_fingers.urdf'
ARM_PACKAGE = FIXTURES / 'packages/fixture_description'
ARM = ARM_PACKAGE / 'urdf/arm.urdf.xacro'


def _executable(workspace: Path, name: str) -> list[str]:
    """Return the command that runs ``name`` as ``ros2 run urdfgenpy_ros name`` would."""
    locate = subprocess.run(
        ['bash', '-c', 'source install/setup.bash && python3 -c "from ament_index_python.'
         "packages import get_package_prefix; print(get_package_prefix('urdfgenpy_ros'))\""],
        cwd=workspace, capture_output=True, text=True, timeout=60,
        env=dict(os.environ, PATH=f'{Path(sys.executable).parent}:{os.environ["PATH"]}'))
    prefix = Path(locate.stdout.strip())
    return ['bash', '-c', f'source {workspace}/install/setup.bash && exec '
            f'{prefix}/lib/urdfgenpy_ros/{name} "$@"', name]


def test_colcon_built_publisher_publishes_the_example_to_late_subscribers(
        colcon_workspace: Path, graph: Graph) -> None:
    process = graph.start(command=_executable(colcon_workspace, 'publisher'))
    states = graph.collect(JointState, 'joint_states')
    assert graph.spin_until(lambda: len(states) >= 3, 15), 'no joint_states'
    late = graph.collect(String, 'robot_description', latched=True)  # joins after start
    assert graph.spin_until(lambda: late, 10), 'late subscriber got no robot_description'
    assert late[0].data == pan_tilt_unit().to_urdf()
    assert list(states[-1].name) == ['pan_joint', 'tilt_joint']
    assert list(states[-1].position) == [0.0, 0.0]
    code, output = stop(process)
    assert code == 0 and 'Traceback' not in output
    assert "publishing 'ptu': 4 links, 2 joint states at 10 Hz" in output


@pytest.mark.parametrize('rate', [10, 100.0])
def test_publishing_period_is_within_5_percent(graph: Graph, rate: float) -> None:
    # The median interval between stamps is the timer's period; a loaded machine that makes
    # the timer miss a tick lengthens single intervals but not the median.
    graph.start(f'rate:={rate}')
    states = graph.collect(JointState, 'joint_states')
    assert graph.spin_until(lambda: len(states) >= 2, 15)
    start = len(states)
    graph.spin_for(3.0 if rate > 10 else 4.0)
    stamps = [m.header.stamp.sec + m.header.stamp.nanosec * 1e-9 for m in states[start:]]
    assert len(stamps) >= 10, f'only {len(stamps)} joint_states in the window'
    intervals = [later - earlier for earlier, later in zip(stamps, stamps[1:])]
    assert statistics.median(intervals) == pytest.approx(1 / rate, rel=0.05)


def test_mimic_joints_follow_their_leaders_through_chains(graph: Graph) -> None:
    graph.start(f'model:={MIMIC_CHAIN}', 'zeros.drive:=0.5')
    states = graph.collect(JointState, 'joint_states')
    assert graph.spin_until(lambda: states, 15)
    message = states[-1]
    assert list(message.name) == ['drive', 'left', 'right']
    # left = drive + 0.1 (multiplier defaults to 1); right = -1 * left
    assert list(message.position) == pytest.approx([0.5, 0.6, -0.6], abs=1e-12)


def test_source_list_values_are_merged_clamped_and_bad_input_ignored(graph: Graph) -> None:
    process = graph.start('source_list:=[input]')
    states = graph.collect(JointState, 'joint_states')
    publisher = graph.node.create_publisher(JointState, 'input', 10)
    assert graph.spin_until(lambda: states, 15)

    def send(names, positions) -> None:
        publisher.publish(JointState(name=names, position=positions))

    def settled(expected) -> bool:
        return bool(states) and list(states[-1].position) == pytest.approx(expected)

    assert graph.spin_until(lambda: (send(['pan_joint', 'ghost'], [0.7, 1.0]),
                                     settled([0.7, 0.0]))[1], 10)
    assert graph.spin_until(lambda: (send(['tilt_joint'], [5.0]), settled([0.7, 1.57]))[1],
                            10), 'tilt_joint not clamped to its upper limit 1.57'
    send(['pan_joint', 'tilt_joint'], [0.1])  # mismatched arrays: ignored, no crash
    send(['pan_joint'], [float('nan')])
    graph.spin_for(1.0)
    assert process.poll() is None and settled([0.7, 1.57])
    code, output = stop(process)
    assert code == 0
    assert 'ignored unknown joint(s): ghost' in output
    assert '2 names but 1 position values' in output and 'position holds NaN' in output


def test_reload_publishes_a_valid_change_and_keeps_the_last_good_model(
        graph: Graph, tmp_path: Path) -> None:
    model = tmp_path / 'ptu.urdf'
    pan_tilt_unit().to_urdf(model)
    graph.start(f'model:={model}')
    descriptions = graph.collect(String, 'robot_description', latched=True)
    assert graph.spin_until(lambda: descriptions, 15)
    robot = pan_tilt_unit()
    robot.get_joint('pan_joint').limit.upper = 2.0
    robot.to_urdf(model)
    response = graph.call(Trigger, '/urdfgenpy_publisher/reload')
    assert response.success, response.message
    assert graph.spin_until(lambda: len(descriptions) == 2, 30)
    assert 'upper="2"' in descriptions[-1].data
    model.write_text(model.read_text().replace('upper="2"', 'upper="-9"'))  # J104
    response = graph.call(Trigger, '/urdfgenpy_publisher/reload')
    assert not response.success and 'validation error' in response.message
    graph.spin_for(1.0)
    assert len(descriptions) == 2


def test_watch_reloads_when_an_included_file_changes(graph: Graph, tmp_path: Path) -> None:
    package = tmp_path / 'fixture_description'
    shutil.copytree(ARM_PACKAGE, package)
    graph.start(f'model:={package / "urdf/arm.urdf.xacro"}', 'watch:=true',
                f"package_paths:=['{tmp_path}']")
    descriptions = graph.collect(String, 'robot_description', latched=True)
    assert graph.spin_until(lambda: descriptions, 20)
    included = package / 'urdf/arm_parts.xacro'  # $(find fixture_description)/urdf/...
    time.sleep(0.05)
    included.write_text(included.read_text().replace('name="joint_${index}"',
                                                     'name="axis_${index}"'))
    assert graph.spin_until(lambda: len(descriptions) == 2, 30)
    assert '<joint name="axis_3" type="revolute">' in descriptions[-1].data


def test_xacro_with_arguments_and_a_module_function(graph: Graph, tmp_path: Path) -> None:
    graph.start(f'model:={ARM}', "xacro_args:=['dof:=2', 'gripper:=true']",
                f"package_paths:=['{FIXTURES / 'packages'}']")
    states = graph.collect(JointState, 'joint_states')
    assert graph.spin_until(lambda: states, 20)
    assert list(states[-1].name) == ['joint_1', 'joint_2']  # the gripper's mount is fixed
    other = Graph()
    try:
        other.start('model:=urdfgenpy_ros.examples:pan_tilt_unit')
        names = other.collect(JointState, 'joint_states')
        assert other.spin_until(lambda: names, 15)
        assert list(names[-1].name) == ['pan_joint', 'tilt_joint']
    finally:
        other.close()


@pytest.mark.parametrize('parameters, words', [
    (['model:=/no/such/robot.urdf'], '/no/such/robot.urdf does not exist'),
    ([f"model:={FIXTURES / 'broken/unclosed_attribute.urdf'}"], 'error P001'),
    (['rate:=-5'], "parameter 'rate': -5 is not a positive number"),
    (['model:=no_such_module:build'], "cannot import 'no_such_module:build'"),
    (["xacro_args:=['oops']", f'model:={ARM}'],
     "'oops' is not name:=value"),
])
def test_bad_input_exits_1_with_one_line_and_no_traceback(
        graph: Graph, parameters: list[str], words: str) -> None:
    process = graph.start(*parameters)
    output, _ = process.communicate(timeout=20)  # it exits by itself; a hang times out
    assert process.returncode == 1
    assert 'Traceback' not in output
    errors = [line for line in output.splitlines() if '[ERROR]' in line]
    assert len(errors) == 1 and words in errors[0], output


def test_invalid_model_logs_each_finding_and_exits_1(graph: Graph, tmp_path: Path) -> None:
    robot = pan_tilt_unit()
    robot.get_joint('pan_joint').limit.lower = 4.0
    robot.get_link('pan_link').inertial.mass = 0.0
    robot.to_urdf(tmp_path / 'bad.urdf')
    process = graph.start(f'model:={tmp_path / "bad.urdf"}')
    output, _ = process.communicate(timeout=10)
    assert process.returncode == 1 and 'Traceback' not in output
    errors = [line for line in output.splitlines() if '[ERROR]' in line]
    assert [' J104 ' in errors[0], len(errors)] == [True, 2]
    # a massless moving link is for simulators to refuse: a warning naming them
    assert any(' I201 ' in line and 'MuJoCo' in line and 'physics only' in line
               for line in output.splitlines() if '[WARN]' in line), output


def test_physics_only_errors_are_published_with_warnings_unless_strict(
        graph: Graph, tmp_path: Path) -> None:
    """A tensor MuJoCo and libsdformat refuse, which urdfdom reads, is published (TIAGo)."""
    mujoco = require_module('mujoco')
    model = FIXTURES / 'problems' / 'impossible_tensor_on_fixed_link.urdf'
    assert check_urdf(model).returncode == 0  # what robot_state_publisher's parser says
    with pytest.raises(ValueError, match='A \\+ B >= C'):
        mujoco.MjModel.from_xml_path(str(model))
    graph.start(f'model:={model}')
    descriptions = graph.collect(String, 'robot_description', latched=True)
    assert graph.spin_until(lambda: descriptions, 20)
    assert descriptions[0].data == model.read_text()
    process = graph.start(f'model:={model}', 'strict:=true')
    output, _ = process.communicate(timeout=20)
    assert process.returncode == 1 and 'Traceback' not in output
    assert [line for line in output.splitlines() if ' I203 ' in line and '[ERROR]' in line]
    assert "ignore:=['I203']" in output, output


def test_errors_named_in_ignore_do_not_stop_publishing(graph: Graph) -> None:
    """With strict:=true, an error named in 'ignore' is let through; a misspelt code is not."""
    model = FIXTURES / 'problems' / 'impossible_tensor_on_fixed_link.urdf'
    graph.start(f'model:={model}', 'strict:=true', "ignore:=['I203']")
    descriptions = graph.collect(String, 'robot_description', latched=True)
    assert graph.spin_until(lambda: descriptions, 20)
    assert descriptions[0].data == model.read_text()
    process = graph.start(f'model:={model}', "ignore:=['I2O3']")  # a letter O for a zero
    output, _ = process.communicate(timeout=20)
    assert process.returncode == 1, output
    assert "parameter 'ignore': I2O3 is not a finding code" in output, output


def test_robot_description_parameter_is_the_text_and_read_only(graph: Graph) -> None:
    from rcl_interfaces.srv import GetParameters, SetParameters
    graph.start()
    client = graph.node.create_client(GetParameters, '/urdfgenpy_publisher/get_parameters')
    assert graph.spin_until(client.service_is_ready, 15)
    future = client.call_async(GetParameters.Request(names=['robot_description']))
    assert graph.spin_until(future.done, 5)
    assert future.result().values[0].string_value == pan_tilt_unit().to_urdf()
    setter = graph.node.create_client(SetParameters, '/urdfgenpy_publisher/set_parameters')
    assert graph.spin_until(setter.service_is_ready, 5)
    request = SetParameters.Request(parameters=[rclpy.parameter.Parameter(
        'robot_description', value='<robot/>').to_parameter_msg()])
    future = setter.call_async(request)
    assert graph.spin_until(future.done, 5)
    result = future.result().results[0]
    assert not result.successful and 'read-only' in result.reason


def test_publish_description_false_leaves_the_topic_to_robot_state_publisher(
        graph: Graph) -> None:
    graph.start('publish_description:=false')
    states = graph.collect(JointState, 'joint_states')
    assert graph.spin_until(lambda: states, 15)
    graph.spin_for(0.5)
    assert graph.node.count_publishers('robot_description') == 0


def test_publish_tf_without_tf2_msgs_says_so_in_one_line(graph: Graph) -> None:
    try:
        import tf2_msgs  # noqa: F401
    except ImportError:
        pass
    else:
        pytest.skip('tf2_msgs is installed: the TF topics themselves are available')
    process = graph.start('publish_tf:=true')
    output, _ = process.communicate(timeout=10)
    assert process.returncode == 1 and 'Traceback' not in output
    errors = [line for line in output.splitlines() if '[ERROR]' in line]
    assert len(errors) == 1 and 'needs the tf2_msgs package' in errors[0]


def test_zeros_outside_the_limits_are_clamped_as_joint_state_publisher_does() -> None:
    from urdfgenpy_ros.publisher.joint_states import JointStateOptions, JointStates
    robot = pan_tilt_unit()
    upper = robot.get_joint('tilt_joint').limit.upper
    states = JointStates(robot, JointStateOptions(zeros={'tilt_joint': 9.0,
                                                         'pan_joint': 0.25}))
    names, positions, _, _ = states.message_arrays()
    assert dict(zip(names, positions)) == {'pan_joint': 0.25, 'tilt_joint': upper}


def test_a_urdf_version_the_target_cannot_read_is_refused_as_its_publisher_would(
        graph: Graph, tmp_path: Path) -> None:
    """Jazzy's robot_state_publisher refuses a URDF 1.1 file: so does the node, by default."""
    text = pan_tilt_unit().to_urdf().replace('<robot name="ptu">',
                                             '<robot name="ptu" version="1.1">')
    model = tmp_path / 'ptu11.urdf'
    model.write_text(text)
    process = graph.start(f'model:={model}')
    output, _ = process.communicate(timeout=20)
    assert process.returncode == 1 and 'Traceback' not in output
    assert ' V701 ' in output and 'write version="1.0"' in output, output
    graph.start(f'model:={model}', 'target:=rolling')
    descriptions = graph.collect(String, 'robot_description', latched=True)
    assert graph.spin_until(lambda: descriptions, 20)
    assert descriptions[0].data == text
