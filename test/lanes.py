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
The fast lane: a marker says what makes a test slow; a slow test without one is named.

``scripts/test --fast`` (pytest's ``--fast``) leaves out the tests marked with one of
LANE_MARKS (setup.cfg says what each means). A test that asks for conftest.py's colcon
workspace, browser or ROS graph gets its marker here; the others carry theirs in their
file. When asked (``--fast-lane-budget``, with ``fast_lane_budget`` of setup.cfg, or
``--fast-lane-budget SECONDS``), the end of the run names the tests without such a marker
that took longer than the budget, so that they get one: a summary line, never a failure
(a unit test never asserts a time). Unasked, a run prints nothing of it.
"""

from __future__ import annotations

import os

import pytest

LANE_MARKS = ('colcon', 'browser', 'engine', 'ros', 'docs', 'slow')
FIXTURE_MARKS = {'colcon_workspace': 'colcon', 'browser': 'browser', 'graph': 'ros'}
FAST = ' and '.join(f'not {mark}' for mark in LANE_MARKS)
_THE_INI = -1.0  # --fast-lane-budget without SECONDS: setup.cfg's fast_lane_budget


def add_options(parser: pytest.Parser) -> None:
    """Declare ``--fast`` and the budget (an ini value and a command-line option)."""
    parser.addoption('--fast', action='store_true',
                     help='the inner loop: leave out the tests marked ' + ', '.join(LANE_MARKS)
                     + ' (with -m, both apply)')
    parser.addini('fast_lane_budget', 'seconds a test without a lane marker may take '
                  'before the run names it (0: never)', default='2')
    parser.addoption('--fast-lane-budget', type=float, nargs='?', const=_THE_INI,
                     default=None, metavar='SECONDS',
                     help='name the tests without a marker of ' + ', '.join(LANE_MARKS)
                     + ' that take longer than SECONDS (without SECONDS: fast_lane_budget '
                     'in setup.cfg; unasked or 0: none)')


def configure(config: pytest.Config) -> None:
    """Select the fast lane when asked; register the lane's hooks for this run."""
    if config.getoption('fast'):
        chosen = config.option.markexpr
        config.option.markexpr = f'({chosen}) and {FAST}' if chosen else FAST
    budget = config.getoption('fast_lane_budget')
    if budget is None:  # not asked: the run says nothing of it
        budget = 0.0
    elif budget == _THE_INI:
        budget = float(config.getini('fast_lane_budget'))
    config.pluginmanager.register(FastLane(budget), 'urdfgenpy_fast_lane')


class FastLane:
    """Marks tests by the fixtures they ask for; names the unmarked ones over the budget."""

    def __init__(self, budget: float) -> None:
        self.budget = budget
        self.unmarked: set[str] = set()
        self.seconds: dict[str, float] = {}

    @pytest.hookimpl(tryfirst=True)  # before -m deselects by these markers
    def pytest_collection_modifyitems(self, items: list[pytest.Item]) -> None:
        """Mark what asks for a slow fixture; remember what has no lane marker."""
        for item in items:
            for fixture, mark in FIXTURE_MARKS.items():
                if fixture in getattr(item, 'fixturenames', ()):
                    item.add_marker(mark)
            if not any(item.get_closest_marker(mark) for mark in LANE_MARKS):
                self.unmarked.add(item.nodeid)

    def pytest_runtest_logreport(self, report: pytest.TestReport) -> None:
        """Add up set-up, call and tear-down (a shared fixture counts for its first user)."""
        if report.nodeid in self.unmarked:
            self.seconds[report.nodeid] = self.seconds.get(report.nodeid, 0.0) + report.duration

    def over_budget(self) -> list[tuple[float, str]]:
        """Return (seconds, test) of the unmarked tests over the budget, slowest first."""
        if self.budget <= 0:
            return []
        return sorted(((seconds, nodeid) for nodeid, seconds in self.seconds.items()
                       if seconds > self.budget), reverse=True)

    def pytest_terminal_summary(self, terminalreporter) -> None:
        """Name the unmarked tests over the budget, one line each."""
        over = self.over_budget()
        if not over:
            return
        terminalreporter.section('fast lane budget', sep='-', yellow=True)
        terminalreporter.write_line(
            f'{len(over)} test(s) without a marker of {", ".join(LANE_MARKS)} took over '
            f'{self.budget:g} s: mark each by what makes it slow (setup.cfg lists them)')
        for seconds, nodeid in over:
            terminalreporter.write_line(f'{seconds:6.1f} s  {nodeid}')
        load, cpus = os.getloadavg()[0], os.cpu_count() or 1
        if load > cpus:
            terminalreporter.write_line(f'(load average {load:.1f} on {cpus} CPUs: times are '
                                        'longer than on a quiet machine)')
