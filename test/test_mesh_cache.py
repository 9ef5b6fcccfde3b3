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

"""The mesh cache: where it is, what a key covers, and a folder that cannot be written."""

from __future__ import annotations

from pathlib import Path
import subprocess
import sys

import pytest

from urdfgenpy_ros import mesh_cache


@pytest.fixture
def fresh(monkeypatch, tmp_path: Path) -> Path:
    monkeypatch.setattr(mesh_cache, '_memory', {})
    monkeypatch.setenv('URDFGENPY_CACHE_DIR', str(tmp_path / 'cache'))
    return tmp_path / 'cache'


def test_the_folder_follows_the_variables(monkeypatch, tmp_path: Path) -> None:
    monkeypatch.delenv('URDFGENPY_CACHE_DIR', raising=False)
    monkeypatch.setenv('XDG_CACHE_HOME', str(tmp_path / 'xdg'))
    assert mesh_cache.folder() == tmp_path / 'xdg' / 'urdfgenpy'
    monkeypatch.setenv('URDFGENPY_CACHE_DIR', 'off')
    assert mesh_cache.folder() is None


def test_an_entry_is_read_by_another_process(fresh: Path) -> None:
    name = mesh_cache.key('test', b'source bytes')
    mesh_cache.put(name, b'converted')
    code = ('from urdfgenpy_ros import mesh_cache; import sys; '
            f'sys.stdout.write(repr(mesh_cache.get({name!r})))')
    done = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True,
                          check=True, env={**__import__('os').environ,
                                           'PYTHONPATH': str(Path(__file__).parents[1])})
    assert done.stdout == "b'converted'"
    assert mesh_cache.key('test', b'source bytes!') != name  # another content, another key
    assert mesh_cache.key('other', b'source bytes') != name  # another conversion too


def test_a_folder_that_cannot_be_written_costs_only_time(fresh: Path) -> None:
    fresh.parent.mkdir(parents=True, exist_ok=True)
    fresh.write_text('a file where the folder would be')
    made = []
    name = mesh_cache.key('test', b'x')
    assert mesh_cache.cached(name, lambda: made.append(1) or b'y') == b'y'
    assert mesh_cache.cached(name, lambda: made.append(1) or b'z') == b'y'  # this process
    assert made == [1]
