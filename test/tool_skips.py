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
A pytest plugin (conftest loads it): a tool missing skips naming it; in CI it fails.

Without an optional tool (trimesh, mujoco, pinocchio, ...), a test that imports it
inside its body skips with the tool's name instead of erroring. With
``URDFGENPY_REQUIRE_TOOLS`` set (scripts/test sets it, so CI does) a tool missing fails
the test instead, whichever way the test looked for it (``helpers.require_module``,
``pytest.importorskip`` or a plain import): CI installs every tool, so a skip there
would hide a test that never ran.
"""

from __future__ import annotations

from collections.abc import Iterator
import os
import re
from typing import Any

import pytest

REQUIRED = frozenset({'urdfgenpy_ros', 'lxml', 'click', 'yaml', 'jinja2', 'numpy',
                      'setuptools', 'pytest', '_pytest'})
"""What is no optional tool: the package, its install_requires and pytest itself."""
MISSING = re.compile(r"^Skipped: (could not import '[\w.]+'|[\w.-]+ not importable \(|"
                     r'[\w.-]+( of urdfdom 6)? not installed \((apt|pip) install)')
"""How a skip for a missing tool reads: pytest.importorskip's and helpers.require_*'s."""


def require_tools() -> bool:
    """Return whether a missing tool is a failure (``URDFGENPY_REQUIRE_TOOLS``, in CI)."""
    return bool(os.environ.get('URDFGENPY_REQUIRE_TOOLS'))


def missing_tool(error: BaseException | None) -> str | None:
    """Return the optional tool whose absence raised ``error``, or None."""
    if not isinstance(error, ModuleNotFoundError) or not error.name:
        return None
    top = error.name.split('.')[0]
    return None if top in REQUIRED else top


def _skip_reason(longrepr: Any) -> str:
    return longrepr[2] if isinstance(longrepr, tuple) and len(longrepr) == 3 else ''


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[None]
                              ) -> Iterator[None]:
    """Turn an import error of a tool into a skip naming it, a tool skip in CI a failure."""
    outcome = yield
    report = outcome.get_result()  # type: ignore[attr-defined]
    tool = missing_tool(call.excinfo.value if call.excinfo else None)
    if tool is not None and not require_tools():
        report.outcome = 'skipped'
        report.longrepr = (str(item.path), item.location[1] or 0,
                           f'Skipped: {tool} not importable: pip install -e ".[test]"')
    elif report.skipped and require_tools() and MISSING.search(_skip_reason(report.longrepr)):
        report.outcome = 'failed'
        report.longrepr = (f'{_skip_reason(report.longrepr)} (URDFGENPY_REQUIRE_TOOLS is '
                           'set: CI installs every tool, so none may be skipped)')
