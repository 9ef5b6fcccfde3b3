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

"""A package search lists each folder once per process, and sees what changed since."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from urdfgenpy_ros.resources import PackageResolver

HOUR_AGO = 3600  # s: folders this old are kept in the listing cache (fresh ones never are)


def _package(folder: Path, name: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / 'package.xml').write_text(
        f'<package format="3"><name>{name}</name><version>1.0.0</version><description>d'
        '</description><maintainer email="someone@example.com">a</maintainer>'
        '<license>Apache-2.0</license></package>')
    return folder


def _age(root: Path) -> None:
    """Date every file and folder under ``root`` an hour back, so their listings are kept."""
    for path in [root, *root.rglob('*')]:
        stamp = path.stat().st_mtime - HOUR_AGO
        os.utime(path, (stamp, stamp))


def _catkin_finds(root: Path) -> dict[str, Path]:
    """Return catkin_pkg's answer: every package under ``root`` by name."""
    packages = pytest.importorskip('catkin_pkg.packages', reason='needs catkin_pkg')
    return {package.name: root / folder
            for folder, package in packages.find_packages(str(root)).items()}


def test_packages_found_are_the_ones_catkin_pkg_finds(tmp_path: Path) -> None:
    for folder, name in (('a/one', 'one'), ('b/c/two', 'two'), ('named_three', 'three')):
        _package(tmp_path / folder, name)
    _age(tmp_path)
    expected = _catkin_finds(tmp_path)
    for _ in range(2):  # the second search reads the listings the first one kept
        resolver = PackageResolver([tmp_path])
        assert {name: resolver.find(name) for name in expected} == expected
        assert resolver.find('missing') is None


def test_a_package_added_after_a_search_is_found(tmp_path: Path) -> None:
    _package(tmp_path / 'old' / 'first', 'first')
    _age(tmp_path)
    assert PackageResolver([tmp_path]).find('second') is None
    _package(tmp_path / 'old' / 'second', 'second')  # 'old' changes: listed again
    assert PackageResolver([tmp_path]).find('second') == tmp_path / 'old' / 'second'
    assert _catkin_finds(tmp_path)['second'] == tmp_path / 'old' / 'second'


def test_a_renamed_package_is_found_by_its_new_name(tmp_path: Path) -> None:
    _package(tmp_path / 'shelf' / 'thing', 'old_name')
    _age(tmp_path)
    assert PackageResolver([tmp_path]).find('old_name') == tmp_path / 'shelf' / 'thing'
    _package(tmp_path / 'shelf' / 'thing', 'new_name')  # its package.xml changes only
    resolver = PackageResolver([tmp_path])
    assert resolver.find('new_name') == tmp_path / 'shelf' / 'thing'
    assert resolver.find('old_name') is None
    assert set(_catkin_finds(tmp_path)) == {'new_name'}
