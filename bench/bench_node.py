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
The publisher node against joint_state_publisher and a minimal rclpy publisher.

Each contender runs alone, on an isolated ROS domain, publishing the same robot's
JointState at 10, 100 and 1000 Hz. The script measures:

- start-up: from process start to the first ``joint_states`` seen by a subscriber, and
  to the first ``robot_description`` (ours only: joint_state_publisher does not publish it);
- CPU per message: the process's CPU time (``/proc/<pid>/stat``) over a window divided by
  the messages received in it, and the CPU share;
- the achieved rate and the 99th percentile of the gaps between header stamps.

joint_state_publisher is not on PyPI: pass ``--jsp`` the ``joint_state_publisher``
package folder of a checkout of ros/joint_state_publisher (branch ros2). It is run with
this environment's rclpy; nothing of it is kept here.

    python bench/bench_node.py --jsp /tmp/jsp/joint_state_publisher [--repeat 3]
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path
import random
import signal
import statistics
import subprocess
import sys
import tempfile
import time

_FLOOR = """
import sys, rclpy
from rclpy.node import Node
from sensor_msgs.msg import JointState
names, rate = sys.argv[1].split(','), float(sys.argv[2])
rclpy.init()
node = Node('floor')
publisher = node.create_publisher(JointState, 'joint_states', 10)
message = JointState(name=names, position=[0.0] * len(names))
def tick():
    message.header.stamp = node.get_clock().now().to_msg()
    publisher.publish(message)
node.create_timer(1.0 / rate, tick)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
"""


def humanoid(path: Path) -> list[str]:
    """Write a 31-joint humanoid URDF (torso, head, two 7-DOF arms, two 6-DOF legs)."""
    from urdfgenpy_ros import Box, Inertial, Joint, JointLimit, Link, Origin, Robot, Visual
    robot = Robot('humanoid')
    shape = Box(0.1, 0.1, 0.2)

    def add(name: str, parent: str | None) -> None:
        link = Link(name).add_visual(Visual(shape))
        robot.add_link(link.set_inertial(Inertial.from_geometry(1.0, shape)))
        if parent:
            robot.add_joint(Joint(f'{name}_joint', 'revolute', parent, name,
                                  origin=Origin((0, 0, 0.2)), axis=(0, 1, 0),
                                  limit=JointLimit(-1.5, 1.5, effort=50, velocity=2)))

    add('base_link', None)
    add('torso', 'base_link')
    add('neck', 'torso')
    add('head', 'neck')
    for side in ('left', 'right'):
        parent = 'torso'
        for part in range(7):
            add(f'{side}_arm_{part}', parent)
            parent = f'{side}_arm_{part}'
        parent = 'base_link'
        for part in range(6):
            add(f'{side}_leg_{part}', parent)
            parent = f'{side}_leg_{part}'
    robot.to_urdf(path)
    return [joint.name for joint in robot.joints]


def _cpu_seconds(pid: int) -> float:
    fields = Path(f'/proc/{pid}/stat').read_text().rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')


def measure(command: list[str], env: dict[str, str], window: float) -> dict[str, float]:
    """Start ``command``; return start-up, CPU and rate figures seen by a subscriber."""
    import rclpy
    from rclpy.qos import DurabilityPolicy, QoSProfile
    from sensor_msgs.msg import JointState
    from std_msgs.msg import String
    context = rclpy.context.Context()
    saved = dict(os.environ)
    os.environ.update(env)
    rclpy.init(context=context)
    os.environ.clear()
    os.environ.update(saved)
    node = rclpy.create_node('bench_listener', context=context)
    executor = rclpy.executors.SingleThreadedExecutor(context=context)
    executor.add_node(node)
    stamps: list[float] = []
    first: dict[str, float] = {}

    def on_state(message: JointState) -> None:
        first.setdefault('joint_states', time.monotonic())
        stamps.append(message.header.stamp.sec + message.header.stamp.nanosec * 1e-9)

    node.create_subscription(JointState, 'joint_states', on_state, 1000)
    node.create_subscription(String, 'robot_description',
                             lambda _: first.setdefault('robot_description', time.monotonic()),
                             QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
    started = time.monotonic()
    process = subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 20
        while 'joint_states' not in first and time.monotonic() < deadline:
            executor.spin_once(timeout_sec=0.01)
        end = time.monotonic() + 1.0  # settle
        while time.monotonic() < end:
            executor.spin_once(timeout_sec=0.01)
        count, cpu = len(stamps), _cpu_seconds(process.pid)
        end = time.monotonic() + window
        while time.monotonic() < end:
            executor.spin_once(timeout_sec=0.01)
        cpu = _cpu_seconds(process.pid) - cpu
        seen = stamps[count:]
    finally:
        process.send_signal(signal.SIGINT)
        try:
            process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            process.kill()
        node.destroy_node()
        context.try_shutdown()
    gaps = sorted(b - a for a, b in zip(seen, seen[1:]))
    return {
        'startup_states': first.get('joint_states', float('nan')) - started,
        'startup_description': first.get('robot_description', float('nan')) - started,
        'rate': (len(seen) - 1) / (seen[-1] - seen[0]) if len(seen) > 1 else 0.0,
        'cpu_share': cpu / window,
        'cpu_per_message_us': cpu / max(len(seen), 1) * 1e6,
        'p99_gap_ms': gaps[int(0.99 * (len(gaps) - 1))] * 1e3 if gaps else float('nan'),
    }


def main() -> None:
    """Run every contender at every rate and print a Markdown table of medians."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--jsp', type=Path, required=True,
                        help='the joint_state_publisher package folder of a checkout')
    parser.add_argument('--repeat', type=int, default=3)
    parser.add_argument('--window', type=float, default=4.0)
    parser.add_argument('--rates', type=int, nargs='+', default=[10, 100, 1000])
    args = parser.parse_args()
    corpus = Path(os.environ.get('URDFGENPY_CORPUS', 'corpus-not-set'))
    folder = Path(tempfile.mkdtemp())
    jsp_robot = corpus / 'joint_state_publisher/test/64_joint_robot.urdf'
    robots = {'64-joint (jsp test)': (jsp_robot, [f'joint{n}' for n in range(1, 65)]),
              'humanoid (30 joints)': (folder / 'humanoid.urdf',
                                       humanoid(folder / 'humanoid.urdf'))}
    jsp = (f'import sys; sys.path.insert(0, {str(args.jsp)!r}); '
           'from joint_state_publisher.joint_state_publisher import main; main()')
    print('| robot | Hz | contender | start-up to joint_states s | to robot_description s |'
          ' CPU % | CPU µs/msg | x floor CPU | achieved Hz | p99 gap ms |')
    print('|---|---:|---|---:|---:|---:|---:|---:|---:|---:|')
    for label, (urdf, names) in robots.items():
        for rate in args.rates:
            contenders = {
                'minimal rclpy (floor)': [sys.executable, '-c', _FLOOR, ','.join(names),
                                          str(rate)],
                'joint_state_publisher': [sys.executable, '-c', jsp, str(urdf), '--ros-args',
                                          '-p', f'rate:={rate}'],
                'urdfgenpy_ros publisher': [sys.executable, '-m', 'urdfgenpy_ros.publisher',
                                            '--ros-args', '-p', f'model:={urdf}', '-p',
                                            f'rate:={rate}'],
            }
            results = {}
            for name, command in contenders.items():
                runs = []
                for _ in range(args.repeat):
                    env = dict(os.environ, ROS_DOMAIN_ID=str(random.randint(30, 220)),
                               ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST')
                    runs.append(measure(command, env, args.window))
                results[name] = {key: statistics.median(run[key] for run in runs)
                                 for key in runs[0]}
            floor = results['minimal rclpy (floor)']['cpu_per_message_us']
            for name, figures in results.items():
                print(f"| {label} | {rate} | {name} | {figures['startup_states']:.2f} | "
                      f"{figures['startup_description']:.2f} | {figures['cpu_share'] * 100:.0f}"
                      f" | {figures['cpu_per_message_us']:.0f} | "
                      f"{figures['cpu_per_message_us'] / floor:.2f} | {figures['rate']:.1f} | "
                      f"{figures['p99_gap_ms']:.2f} |", flush=True)


if __name__ == '__main__':
    main()
