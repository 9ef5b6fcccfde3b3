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
Node start-up: process start to the first ``robot_description``, per model source.

Against a minimal rclpy node that publishes a fixed string on ``robot_description`` with
the same QoS (reliable, transient local, depth 1). One run, trials interleaved (each
round starts every contender once, so drift in the machine's load hits all alike), on an
isolated ROS domain, with one subscriber living in this process. Besides the wall time,
the contender's CPU time (user + system, from ``/proc/<pid>/stat``) when its description
arrives: on a shared machine it varies far less than the wall time. Last, each contender
once more in a wrapper that stops it at its first publish of the description and prints
the process's CPU time then (``time.process_time``), which leaves out discovery and what
runs after that publish.

Python files are byte-compiled first and ``PYTHONDONTWRITEBYTECODE`` is dropped, as in any
pip or colcon install: otherwise each start compiles the package from source (0.2 s of
CPU here), which no installed node does. Model sources: a URDF
file, a Xacro file with arguments (the fixture workspace's ``ws_robot.urdf``,
``prefix:=a_``, its packages in ``AMENT_PREFIX_PATH``), a DH table and a builder
function (``package.module:function``).

    python bench/bench_startup.py [--repeat 10]
"""

from __future__ import annotations

import argparse
import compileall
import os
from pathlib import Path
import random
import statistics
import subprocess
import sys
import tempfile
import time

from timing import p90

REPO = Path(__file__).resolve().parents[1]
PREFIX = REPO / 'test' / 'fixtures' / 'workspace' / 'prefix'

_MINIMAL = """
import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String
rclpy.init()
node = Node('minimal')
qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE,
                 durability=DurabilityPolicy.TRANSIENT_LOCAL)
node.create_publisher(String, 'robot_description', qos).publish(String(data='<robot/>'))
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""

_AT_PUBLISH = """
import os, runpy, sys, time
import rclpy.publisher
original = rclpy.publisher.Publisher.publish
def publish(self, message):
    original(self, message)
    if self.topic_name.endswith('robot_description'):
        print(time.process_time(), flush=True)
        os._exit(0)
rclpy.publisher.Publisher.publish = publish
if sys.argv[1] == '-m':
    sys.argv = [sys.argv[2], *sys.argv[3:]]
    runpy.run_module(sys.argv[0], run_name='__main__')
else:
    sys.argv = sys.argv[1:]
    runpy.run_path(sys.argv[0], run_name='__main__')
"""

_DH = """convention: standard
degrees: true
rows:
  - {joint: 1, a: 0, alpha: 90, d: 0.3}
  - {joint: 2, a: 0.4, alpha: 0, d: 0}
  - {joint: 3, a: 0.35, alpha: 0, d: 0}
  - {joint: 4, a: 0, alpha: 90, d: 0.1}
  - {joint: 5, a: 0, alpha: -90, d: 0.1}
  - {joint: 6, a: 0, alpha: 0, d: 0.08}
"""


def _cpu_seconds(pid: int) -> float:
    """Return the user + system CPU time of process ``pid`` so far."""
    fields = Path(f'/proc/{pid}/stat').read_text().rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')


def contenders(folder: Path) -> dict[str, list[str]]:
    """Return the command of each contender."""
    sys.path.insert(0, str(REPO))
    from urdfgenpy_ros.examples import pan_tilt_unit
    urdf = folder / 'ptu.urdf'
    pan_tilt_unit().save(urdf)
    table = folder / 'arm.yaml'
    table.write_text(_DH)
    minimal = folder / 'minimal.py'
    minimal.write_text(_MINIMAL)
    node = [sys.executable, '-m', 'urdfgenpy_ros.publisher', '--ros-args']
    xacro = PREFIX / 'share' / 'ws_robot_description' / 'urdf' / 'ws_robot.urdf'
    return {
        'minimal rclpy (fixed string)': [sys.executable, str(minimal)],
        'URDF file': [*node, '-p', f'model:={urdf}'],
        'Xacro with arguments': [*node, '-p', f'model:={xacro}',
                                 '-p', "xacro_args:=['prefix:=a_']"],
        'DH table': [*node, '-p', f'model:={table}'],
        'builder': [*node, '-p', 'model:=urdfgenpy_ros.examples:pan_tilt_unit'],
    }


def main() -> None:
    """Measure and print a Markdown table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--repeat', type=int, default=10)
    options = parser.parse_args()
    domain = str(random.randint(30, 220))
    os.environ.update(ROS_DOMAIN_ID=domain, ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST')
    env = dict(os.environ, AMENT_PREFIX_PATH=str(PREFIX))
    env.pop('PYTHONDONTWRITEBYTECODE', None)
    compileall.compile_dir(str(REPO / 'urdfgenpy_ros'), quiet=1)
    import rclpy
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from std_msgs.msg import String
    rclpy.init()
    listener = rclpy.create_node('startup_listener')
    received: list[float] = []
    qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE,
                     durability=DurabilityPolicy.TRANSIENT_LOCAL)
    listener.create_subscription(String, 'robot_description',
                                 lambda _: received.append(time.monotonic()), qos)
    times: dict[str, list[float]] = {}
    cpu: dict[str, list[float]] = {}
    with tempfile.TemporaryDirectory() as folder:
        commands = contenders(Path(folder))
        for _ in range(options.repeat):
            for name, command in commands.items():
                received.clear()
                started = time.monotonic()
                process = subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL,
                                           stderr=subprocess.DEVNULL)
                while not received and time.monotonic() - started < 30:
                    rclpy.spin_once(listener, timeout_sec=0.005)
                times.setdefault(name, []).append(
                    received[0] - started if received else float('nan'))
                cpu.setdefault(name, []).append(_cpu_seconds(process.pid))
                process.send_signal(2)
                try:
                    process.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    process.kill()
                    process.wait()
                time.sleep(0.2)  # let discovery forget the node
        at_publish: dict[str, list[float]] = {}
        wrapper = Path(folder) / 'at_publish.py'
        wrapper.write_text(_AT_PUBLISH)
        for _ in range(options.repeat):
            for name, command in commands.items():
                result = subprocess.run([command[0], str(wrapper), *command[1:]], env=env,
                                        capture_output=True, text=True, timeout=60)
                lines = result.stdout.split()
                at_publish.setdefault(name, []).append(float(lines[-1]) if lines
                                                       else float('nan'))
    listener.destroy_node()
    rclpy.try_shutdown()
    floor = statistics.median(times['minimal rclpy (fixed string)'])
    cpu_floor = statistics.median(cpu['minimal rclpy (fixed string)'])
    print(f'{options.repeat} trials each, interleaved; load average before: '
          f'{os.getloadavg()[0]:.1f}\n')
    print('| model source | wall median s | wall p90 s | wall × minimal | CPU median s | '
          'CPU p90 s | CPU × minimal |')
    print('|---|---:|---:|---:|---:|---:|---:|')
    for name, values in times.items():
        median, cpu_median = statistics.median(values), statistics.median(cpu[name])
        print(f'| {name} | {median:.3f} | {p90(values):.3f} | {median / floor:.2f} | '
              f'{cpu_median:.2f} | {p90(cpu[name]):.2f} | {cpu_median / cpu_floor:.2f} |')
    publish_floor = statistics.median(at_publish['minimal rclpy (fixed string)'])
    print('\n| model source | CPU at first publish, median s | p90 s | × minimal |')
    print('|---|---:|---:|---:|')
    for name, values in at_publish.items():
        median = statistics.median(values)
        print(f'| {name} | {median:.3f} | {p90(values):.3f} | {median / publish_floor:.2f} |')


if __name__ == '__main__':
    main()
