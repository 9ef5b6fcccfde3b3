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

"""A real rclpy graph for tests: an isolated domain, a listener node, bounded waits."""

from __future__ import annotations

from collections.abc import Callable
import os
import random
import signal
import subprocess
import sys
import time
from typing import Any

from helpers import environment, require_module


class Graph:
    """An isolated ROS domain with a listener node living in the test process."""

    def __init__(self) -> None:
        rclpy = require_module('rclpy')
        self.env = dict(os.environ, ROS_DOMAIN_ID=str(random.randint(30, 220)),
                        ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST')
        isolated = {key: self.env[key] for key in ('ROS_DOMAIN_ID',
                                                   'ROS_AUTOMATIC_DISCOVERY_RANGE')}
        with environment(isolated):  # rclpy reads them at init
            self.context = rclpy.context.Context()
            rclpy.init(context=self.context)
        self.node = rclpy.create_node(f'listener_{random.randint(0, 10**6)}',
                                      context=self.context)
        self.executor = rclpy.executors.SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self.processes: list[subprocess.Popen] = []

    def collect(self, kind: Any, topic: str, latched: bool = False) -> list[Any]:
        """Subscribe to ``topic``; return the list that received messages are put in."""
        from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
        received: list[Any] = []
        qos = QoSProfile(depth=1 if latched else 100, reliability=ReliabilityPolicy.RELIABLE,
                         durability=DurabilityPolicy.TRANSIENT_LOCAL if latched
                         else DurabilityPolicy.VOLATILE)
        self.node.create_subscription(kind, topic, received.append, qos)
        return received

    def spin_until(self, done: Callable[[], bool], timeout: float) -> bool:
        """Spin until ``done()`` or ``timeout`` seconds; return ``done()``."""
        deadline = time.monotonic() + timeout
        while not done() and time.monotonic() < deadline:
            self.executor.spin_once(timeout_sec=0.05)
        return done()

    def spin_for(self, seconds: float) -> None:
        """Spin for ``seconds``."""
        self.spin_until(lambda: False, seconds)

    def start(self, *parameters: str, command: list[str] | None = None) -> subprocess.Popen:
        """Start the publisher node (``python -m``) with ``name:=value`` parameters."""
        arguments = []
        for parameter in parameters:
            arguments += ['-p', parameter]
        command = command or [sys.executable, '-m', 'urdfgenpy_ros.publisher']
        process = subprocess.Popen([*command, '--ros-args', *arguments], env=self.env,
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        self.processes.append(process)
        return process

    def call(self, kind: Any, name: str, timeout: float = 5.0) -> Any:
        """Call a service and return its response (None on timeout)."""
        client = self.node.create_client(kind, name)
        if not self.spin_until(client.service_is_ready, timeout):
            return None
        future = client.call_async(kind.Request())
        self.spin_until(future.done, timeout)
        return future.result()

    def close(self) -> None:
        """Stop every process started and shut the context down."""
        for process in self.processes:
            if process.poll() is None:
                process.send_signal(signal.SIGINT)
                try:
                    process.wait(timeout=5)
                except subprocess.TimeoutExpired:
                    process.kill()
            if process.stdout is not None:
                process.stdout.close()
        self.node.destroy_node()
        self.context.try_shutdown()


def stop(process: subprocess.Popen, timeout: float = 5.0) -> tuple[int, str]:
    """Send SIGINT; return the exit code and everything the process printed."""
    process.send_signal(signal.SIGINT)
    output, _ = process.communicate(timeout=timeout)
    return process.returncode, output
