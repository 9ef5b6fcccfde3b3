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

"""Every ```python and ```bash block of docs/reshaping.md runs as written, in order."""

from __future__ import annotations

import os
from pathlib import Path
import re
import subprocess
import sys

import pytest

REPO = Path(__file__).resolve().parents[1]
PAGE = REPO / 'docs' / 'reshaping.md'


def test_every_block_of_the_reshaping_page_runs(tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    pytest.importorskip('trimesh')
    blocks = re.findall(r'```(python|bash)\n(.*?)```', PAGE.read_text(), re.S)
    assert len(blocks) >= 8 and PAGE.read_text().startswith('# ')
    monkeypatch.chdir(tmp_path)
    environment = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(REPO), os.environ.get('PYTHONPATH', '')]),
        PATH=os.pathsep.join([str(Path(sys.executable).parent), os.environ['PATH']]))
    namespace: dict[str, object] = {}
    for number, (language, code) in enumerate(blocks, start=1):
        if language == 'python':
            exec(compile(code, f'{PAGE.name} block {number}', 'exec'), namespace)
            continue
        for line in code.strip().splitlines():
            result = subprocess.run(line, shell=True, capture_output=True, text=True,
                                    env=environment, timeout=120)
            assert result.returncode == 0, f'block {number}: {line}\n{result.stderr}'
