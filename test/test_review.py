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
The library review: ``check``, the node and the viewer render the same one.

One robot and one set of options (an ignored code, and a finding silenced by a comment in
the file): ``urdfgenpy check``'s lines, the lines the publisher node logs (started for real
on an isolated ROS graph) and the findings ``urdfgenpy view`` serves must be the same.
"""

from __future__ import annotations

import importlib
from pathlib import Path
import re
from types import SimpleNamespace
from typing import Any

from click.testing import CliRunner
from helpers import require_module
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.validation import CHECKS, review, ReviewOptions, validate

PROBE = """<?xml version="1.0"?>
<robot name="probe">
  <link name="base_link"/>
  <!-- urdfgenpy: ignore J102 -->
  <joint name="pan" type="revolute">
    <parent link="base_link"/>
    <child link="pan_link"/>
    <axis xyz="0 0 2"/>
    <limit lower="-1" upper="1" effort="0" velocity="1"/>
  </joint>
  <link name="pan_link">
    <inertial>
      <mass value="1"/>
      <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/>
    </inertial>
    <visual>
      <geometry><box size="0.1 0.1 0.1"/></geometry>
      <material name="nowhere"/>
    </visual>
  </link>
</robot>
"""
IGNORED = 'R301'  # the undefined material: silenced by the option
IN_FILE = 'J102'  # the axis of length 2: silenced by the comment before the joint
_FINDING = re.compile(r'^\S+:\d+:\d+: (warning|error) [A-Z]\d{3} ')


@pytest.fixture
def probe(tmp_path: Path) -> Path:
    path = tmp_path / 'probe.urdf'
    path.write_text(PROBE)
    return path


def _check_lines(path: Path) -> list[str]:
    result = CliRunner().invoke(main, ['check', str(path), '--ignore', IGNORED])
    assert result.exit_code == 0, result.output
    return [line for line in result.stdout.splitlines() if _FINDING.match(line)]


def _viewer_lines(path: Path, monkeypatch: pytest.MonkeyPatch) -> tuple[list[str], int]:
    """Run ``urdfgenpy view --ignore`` until its page is up; return what the page lists."""
    pytest.importorskip('viser')
    from browser import free_port
    view_command = importlib.import_module('urdfgenpy_ros.cli.view')  # not the command
    from urdfgenpy_ros.viewer.web import RobotViewer
    served: list[Any] = []
    close = RobotViewer.close

    def closing(viewer: RobotViewer) -> None:
        served.append(viewer)
        close(viewer)

    def interrupted() -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(RobotViewer, 'close', closing)
    monkeypatch.setattr(view_command, 'threading', SimpleNamespace(
        Event=lambda: SimpleNamespace(wait=interrupted)))
    result = CliRunner().invoke(main, ['view', str(path), '--ignore', IGNORED,
                                       '--port', str(free_port())])
    assert result.exit_code == 0, result.output
    (viewer,) = served
    return [str(finding) for finding in viewer.findings], len(viewer.suppressed)


def _node_lines(path: Path, graph: Any) -> tuple[list[str], str]:
    require_module('std_msgs')
    from ros_helpers import stop
    from std_msgs.msg import String
    process = graph.start(f'model:={path}', f"ignore:=['{IGNORED}']")
    descriptions = graph.collect(String, 'robot_description', latched=True)
    assert graph.spin_until(lambda: descriptions, 20)
    code, output = stop(process)
    assert code == 0, output
    said = [line.split(']: ', 1)[1] for line in output.splitlines() if ']: ' in line]
    ignored = [line for line in said if 'ignored' in line]
    return [line for line in said if _FINDING.match(line)], ''.join(ignored)


@pytest.mark.slow
def test_check_the_node_and_the_viewer_give_the_same_findings(
        probe: Path, graph: Any, monkeypatch: pytest.MonkeyPatch) -> None:
    checked = _check_lines(probe)
    assert [line.split()[2] for line in checked] == ['J106']  # the one left
    shown, silenced = _viewer_lines(probe, monkeypatch)
    logged, ignored = _node_lines(probe, graph)
    assert shown == checked
    assert logged == checked
    assert silenced == 2 and f'({IN_FILE}, {IGNORED})' in ignored


def test_the_review_says_what_silenced_each_finding(probe: Path) -> None:
    robot = Robot.from_urdf(probe)
    result = review(robot, ReviewOptions(ignore={IGNORED}))
    assert [finding.code for finding in result.findings] == ['J106']
    assert {(item.finding.code, item.reason, item.source) for item in result.suppressed} == {
        (IN_FILE, 'inSource', 'the ignore comment before line 5'),
        (IGNORED, 'external', 'the ignore option')}
    everything = validate(robot)  # nothing silenced: validate() keeps its promise
    assert sorted(f.code for f in everything) == sorted(
        [f.code for f in result.findings] + [item.finding.code for item in result.suppressed])
    unsilenced = review(robot, ReviewOptions(suppressions=False))
    assert {f.code for f in unsilenced.findings} == {IN_FILE, IGNORED, 'J106'}


def test_fix_repairs_what_the_review_calls_repairable(probe: Path) -> None:
    """The J106 zero effort needs a default; the review says so, and fix applies it."""
    robot = Robot.from_urdf(probe)
    result = review(robot, ReviewOptions(suppressions=False))
    assert [f.code for f in result.repairable] == ['J102', 'J106']
    assert result.needs and 'J106' in result.needs[0] and 'effort' in result.needs[0]
    with_default = review(robot, ReviewOptions(suppressions=False,
                                               limit_defaults={'effort': 5.0}))
    assert with_default.needs == []
    planned = with_default.preview()
    assert robot.get_joint('pan').axis == (0.0, 0.0, 2.0)  # a preview changes nothing
    repairs = with_default.fix()
    assert repairs == planned
    assert [repair.code for repair in repairs] == ['J102', 'J106']
    joint = robot.get_joint('pan')
    assert joint.axis == (0.0, 0.0, 1.0) and joint.limit.effort == 5.0
    left = review(robot, ReviewOptions(suppressions=False)).findings
    assert [finding.code for finding in left] == [IGNORED]  # no repair for a material


def test_each_check_is_one_declared_row() -> None:
    names = [check.name for check in CHECKS]
    assert names[:6] == ['read', 'topology', 'joints', 'inertia', 'versions', 'references']
    assert {'statics', 'efforts', 'gazebo', 'mujoco', 'libsdformat'} <= set(names)
    fields = set(ReviewOptions.__dataclass_fields__)
    assert all(set(check.options) <= fields for check in CHECKS)
    with pytest.raises(ValueError, match="unknown engine 'bullet'"):
        ReviewOptions(engines=('bullet',))


FRONT_ENDS = ('cli', 'publisher', 'viewer', 'scaffold')
CHECK_CALLS = {'validate', 'preflight', 'read_suppressions', 'sdformat_findings',
               'mujoco_findings', 'sdformat_refusals', 'fix', 'run_checks'}


def test_no_front_end_runs_a_check_itself() -> None:
    """The front ends import the review, never a check, and call no validate()."""
    import ast
    from helpers import REPO
    offences = []
    for folder in FRONT_ENDS:
        for path in sorted((REPO / 'urdfgenpy_ros' / folder).glob('*.py')):
            for node in ast.walk(ast.parse(path.read_text(), str(path))):
                if isinstance(node, ast.ImportFrom) and (node.module or '').startswith(
                        'urdfgenpy_ros.validation'):
                    offences += [f'{path.name}: imports {alias.name}' for alias in node.names
                                 if alias.name.startswith('check_')
                                 or alias.name in CHECK_CALLS]
                if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                        and node.func.attr == 'validate':
                    offences.append(f'{path.name}:{node.lineno}: calls .validate()')
    assert offences == []
