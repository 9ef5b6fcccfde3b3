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


"""Every ``python`` and ``bash`` block of docs/mujoco.md runs as written, in order."""

from __future__ import annotations

import os
from pathlib import Path
import re
import subprocess
import sys

from helpers import REPO, require_module

PAGE = REPO / 'docs' / 'mujoco.md'


def test_every_block_of_the_mujoco_page_runs(tmp_path: Path) -> None:
    require_module('mujoco')
    blocks = re.findall(r'```(python|bash)\n(.*?)```', PAGE.read_text(), re.DOTALL)
    assert [kind for kind, _ in blocks].count('python') >= 2 and blocks
    environment = {**os.environ, 'PYTHONPATH': os.pathsep.join(
        [str(REPO), os.environ.get('PYTHONPATH', '')]),
        'PATH': os.pathsep.join([str(Path(sys.executable).parent), os.environ['PATH']])}
    namespace: dict[str, object] = {}
    here = os.getcwd()
    os.chdir(tmp_path)
    try:
        for kind, code in blocks:
            if kind == 'python':
                exec(compile(code, str(PAGE), 'exec'), namespace)  # noqa: S102
            else:
                result = subprocess.run(['bash', '-e', '-c', code], env=environment,
                                        capture_output=True, text=True, timeout=120)
                assert result.returncode == 0, result.stdout + result.stderr
    finally:
        os.chdir(here)
    assert (tmp_path / 'scene.xml').is_file() and (tmp_path / 'strict.xml').is_file()
