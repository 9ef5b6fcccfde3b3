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


"""The node's GUI mode: a slider moved in a real browser drives ``joint_states``."""

from __future__ import annotations

import re
import signal
import threading

from helpers import require_module
import pytest

from ros_helpers import Graph


def _lines(process) -> list[str]:
    """Collect the node's output lines as they come (in a thread)."""
    lines: list[str] = []

    def read() -> None:
        for line in process.stdout:
            lines.append(line)

    threading.Thread(target=read, daemon=True).start()
    return lines


def test_a_slider_moved_in_the_browser_drives_joint_states(graph: Graph, browser) -> None:
    pytest.importorskip('viser')
    from browser import free_port
    from selenium.webdriver.common.keys import Keys
    JointState = require_module('sensor_msgs.msg').JointState
    process = graph.start('gui:=true', f'gui_port:={free_port()}', 'source_list:=[input]')
    output = _lines(process)
    states = graph.collect(JointState, 'joint_states')
    assert graph.spin_until(lambda: states, 30), ''.join(output)
    assert graph.spin_until(lambda: any('joint sliders at' in line for line in output), 30), \
        ''.join(output)
    url = next(re.search(r'joint sliders at (http://\S+)', line).group(1)
               for line in output if 'joint sliders at' in line)
    browser.load(url)
    sliders = browser.sliders()
    assert set(sliders) == {'pan_joint', 'tilt_joint'}

    def published(name: str, value: float) -> bool:
        if not states:
            return False
        message = states[-1]
        return dict(zip(message.name, message.position))[name] == pytest.approx(value)

    sliders['tilt_joint'].send_keys(Keys.END)  # the browser, not Python, moves it
    assert graph.spin_until(lambda: published('tilt_joint', 1.57), 20)
    sliders['pan_joint'].send_keys(Keys.HOME)
    assert graph.spin_until(lambda: published('pan_joint', -3.14), 20)
    assert published('tilt_joint', 1.57)  # merged, not replaced

    source = graph.node.create_publisher(JointState, 'input', 10)  # source_list still merges
    assert graph.spin_until(lambda: (source.publish(JointState(
        name=['pan_joint'], position=[0.75])), published('pan_joint', 0.75))[1], 20)
    browser.wait_for(lambda: float(browser.sliders()['pan_joint'].get_attribute(
        'aria-valuenow')) == pytest.approx(0.75, abs=0.01))  # and the page follows
    process.send_signal(signal.SIGINT)
    assert process.wait(timeout=15) == 0
