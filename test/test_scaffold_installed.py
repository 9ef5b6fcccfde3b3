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


"""Templates in a sourced shell: a non-editable install finds its own before the index."""

from __future__ import annotations

import os
from pathlib import Path
import shutil
import subprocess
import sys
import sysconfig

from helpers import REPO
import pytest

pytestmark = pytest.mark.slow  # a wheel installed in a new venv

PREFIX = REPO / 'test' / 'fixtures' / 'workspace' / 'prefix'  # holds other packages only
_SOURCES = ('setup.py', 'setup.cfg', 'package.xml', 'README.md', 'LICENSE', 'resource',
            'templates', 'urdfgenpy_ros')


@pytest.fixture(scope='module')
def installed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Return a fresh venv holding urdfgenpy_ros installed from a wheel (not editable)."""
    root = tmp_path_factory.mktemp('installed')
    source = root / 'src'
    for name in _SOURCES:
        origin = REPO / name
        if origin.is_dir():
            shutil.copytree(origin, source / name,
                            ignore=shutil.ignore_patterns('__pycache__', '*.egg-info'))
        else:
            source.mkdir(exist_ok=True)
            shutil.copy(origin, source / name)
    pip = [sys.executable, '-m', 'pip', '--disable-pip-version-check', '-q']
    subprocess.run([*pip, 'wheel', '--no-deps', '--no-build-isolation', '-w',
                    str(root / 'wheels'), str(source)], check=True, timeout=300,
                   capture_output=True)
    venv = root / 'venv'
    subprocess.run([sys.executable, '-m', 'venv', '--without-pip', str(venv)], check=True,
                   timeout=120)
    python = venv / 'bin' / 'python'
    # The dependencies come from the test environment, after the venv's own packages (a
    # plain path in a .pth file: the editable install there is not activated).
    site = subprocess.run([str(python), '-c', 'import sysconfig; print(sysconfig.get_path('
                           '"purelib"))'], capture_output=True, text=True, check=True)
    Path(site.stdout.strip(), 'dependencies.pth').write_text(
        sysconfig.get_path('purelib') + '\n')
    wheel = next((root / 'wheels').glob('urdfgenpy_ros-*.whl'))
    subprocess.run([*pip, '--python', str(python), 'install', '--no-deps', '--no-index',
                    str(wheel)], check=True, timeout=300, capture_output=True)
    return venv


def _sourced_shell() -> dict[str, str]:
    environment = {key: value for key, value in os.environ.items()
                   if key not in ('PYTHONPATH', 'VIRTUAL_ENV')}
    environment['AMENT_PREFIX_PATH'] = str(PREFIX)
    return environment


def test_init_in_a_sourced_shell_uses_the_installed_templates(installed: Path,
                                                              tmp_path: Path) -> None:
    where = subprocess.run(
        [str(installed / 'bin' / 'python'), '-c',
         'import urdfgenpy_ros; print(urdfgenpy_ros.__file__)'],
        capture_output=True, text=True, cwd=tmp_path, env=_sourced_shell())
    assert where.stdout.startswith(str(installed)), where.stdout + where.stderr
    result = subprocess.run(
        [str(installed / 'bin' / 'urdfgenpy'), 'init', 'demo_description',
         '--destination-directory', str(tmp_path)],
        capture_output=True, text=True, cwd=tmp_path, env=_sourced_shell(), timeout=120)
    assert result.returncode == 0, result.stderr
    assert 'created' in result.stdout
    package = tmp_path / 'demo_description'
    assert (package / 'launch' / 'display.launch.py').is_file()
    assert (package / 'CMakeLists.txt').is_file()


def test_the_ros2_pkg_verb_class_in_a_sourced_shell(installed: Path, tmp_path: Path) -> None:
    script = (
        'import argparse, sys\n'
        'from urdfgenpy_ros.scaffold.verb import ScaffoldVerb\n'
        'verb = ScaffoldVerb()\n'
        'parser = argparse.ArgumentParser()\n'
        "verb.add_arguments(parser, 'ros2 pkg scaffold')\n"
        'args = parser.parse_args(sys.argv[1:])\n'
        'sys.exit(verb.main(args=args))\n')
    result = subprocess.run(
        [str(installed / 'bin' / 'python'), '-c', script, 'verb_description',
         '--build-type', 'ament_python', '--destination-directory', str(tmp_path)],
        capture_output=True, text=True, cwd=tmp_path, env=_sourced_shell(), timeout=120)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / 'verb_description' / 'setup.py').is_file()
