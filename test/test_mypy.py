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

"""The package's annotations hold, and the Python examples of README and docs/ type-check."""

from __future__ import annotations

from pathlib import Path
import subprocess
import sys

from helpers import REPO
import pytest

from test_docs import BLOCKS, PAGES


def _mypy(*arguments: str) -> subprocess.CompletedProcess[str]:
    pytest.importorskip('mypy')
    return subprocess.run([sys.executable, '-m', 'mypy', '--no-error-summary', *arguments],
                          cwd=REPO, capture_output=True, text=True, timeout=600)


@pytest.mark.slow
def test_package_type_checks() -> None:
    result = _mypy('--config-file', 'setup.cfg')
    assert result.returncode == 0, result.stdout + result.stderr


def test_documentation_examples_type_check(tmp_path: Path) -> None:
    # One module per page, its blocks in order, as a user pasting them into one script would
    # have it; the skipped blocks too (they are read, if not run).
    scripts = []
    for number, page in enumerate(PAGES):
        code = [block.code for block in BLOCKS if block.page == page
                and block.language == 'python']
        if code:
            script = tmp_path / f'page_{number}_{page.stem.replace("-", "_")}.py'
            # The examples read optional parts of what they just built or read
            # (joint.limit.lower): a None check before each would bury the point, so that
            # one code is off, in these scripts only.
            script.write_text(f'# {page.relative_to(REPO)}\n'
                              '# mypy: disable-error-code="union-attr"\n'
                              + '\n\n'.join(code))
            scripts.append(str(script))
    result = _mypy('--config-file', 'setup.cfg', *scripts)
    assert result.returncode == 0, result.stdout + result.stderr


def test_documentation_scripts_type_check() -> None:
    result = _mypy('--config-file', 'setup.cfg', 'docs/hooks.py', 'docs/make_pictures.py',
                   'docs/sarif_picture.py')
    assert result.returncode == 0, result.stdout + result.stderr
