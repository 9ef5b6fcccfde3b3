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
The project's own .pre-commit-config.yaml, run by the real pre-commit on a small repository.

A copy of the configuration and setup.cfg, this suite's .venv, one clean module and one that
breaks each rule: every hook passes the first and fails the second, naming it.
"""

from __future__ import annotations

import os
from pathlib import Path
import shutil
import subprocess
import sys

from helpers import REPO, require_module, require_tool
import pytest

HEADER = (REPO / 'urdfgenpy_ros' / 'model' / 'errors.py').read_text().split('\n\n')[0] + '\n\n'
CLEAN = HEADER + '"""A clean module."""\n\n\ndef double(value: int) -> int:\n' \
    '    """Return twice ``value``."""\n    return 2 * value\n'
BROKEN = '"""no header, a summary in lower case"""\nimport os\n\n\n' \
    'def double(value: int) -> int:\n    return "twice"\n'
"""No Apache header (copyright), an unused import (flake8), no docstring (pep257), a str
returned as an int (mypy)."""


def _pre_commit(folder: Path, *arguments: str) -> subprocess.CompletedProcess[str]:
    require_module('pre_commit')
    env = dict(os.environ, PRE_COMMIT_HOME=str(folder.parent / 'cache'))
    return subprocess.run([str(Path(sys.executable).with_name('pre-commit')), *arguments],
                          cwd=folder, env=env, capture_output=True, text=True, timeout=600)


def _repository(root: Path, text: str) -> Path:
    require_tool('git', 'git')
    (root / 'urdfgenpy_ros').mkdir(parents=True)
    for name in ('.pre-commit-config.yaml', 'setup.cfg'):
        shutil.copy(REPO / name, root / name)
    (root / '.venv').symlink_to(Path(sys.executable).parent.parent)
    (root / 'urdfgenpy_ros' / 'module.py').write_text(text)
    for command in (['init', '-q'], ['add', '.pre-commit-config.yaml', 'setup.cfg',
                                     'urdfgenpy_ros']):
        subprocess.run(['git', *command], cwd=root, check=True, capture_output=True)
    return root


def test_the_configuration_is_valid() -> None:
    result = _pre_commit(REPO, 'validate-config', '.pre-commit-config.yaml')
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.slow
def test_each_hook_passes_clean_code_and_fails_what_breaks_its_rule(tmp_path: Path) -> None:
    clean = _pre_commit(_repository(tmp_path / 'clean', CLEAN), 'run', '--all-files')
    assert clean.returncode == 0, clean.stdout + clean.stderr
    broken = _pre_commit(_repository(tmp_path / 'broken', BROKEN), 'run', '--all-files')
    assert broken.returncode == 1, broken.stdout + broken.stderr
    for hook in ('ament_flake8', 'ament_pep257', 'Apache-2.0 header', 'mypy'):
        line = next(line for line in broken.stdout.splitlines() if line.startswith(hook))
        assert line.endswith('Failed'), broken.stdout
