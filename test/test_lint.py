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

"""The ament linter trio, as colcon test runs it on a ROS 2 Jazzy install."""

from __future__ import annotations

import re

from helpers import REPO, require_module
import pytest


@pytest.mark.linter
@pytest.mark.flake8
@pytest.mark.slow
def test_flake8() -> None:
    main = require_module('ament_flake8.main').main_with_errors
    require_module('flake8_quotes')
    rc, errors = main(argv=[str(REPO / 'urdfgenpy_ros'), str(REPO / 'test'),
                            str(REPO / 'bench'), str(REPO / 'docs'), str(REPO / 'setup.py')])
    assert rc == 0, f'Found {len(errors)} code style errors / warnings:\n' + '\n'.join(errors)


@pytest.mark.linter
@pytest.mark.pep257
@pytest.mark.slow
def test_pep257() -> None:
    main = require_module('ament_pep257.main').main
    require_module('pydocstyle')
    rc = main(argv=[str(REPO / 'urdfgenpy_ros'), str(REPO / 'test'), str(REPO / 'bench'),
                    str(REPO / 'docs')])
    assert rc == 0, 'Found code style errors / warnings'


@pytest.mark.linter
@pytest.mark.copyright
def test_copyright() -> None:
    try:
        from ament_copyright.main import main
    except ImportError:
        header = re.compile(r'# Copyright \d{4} .+\n#\n# Licensed under the Apache License, '
                            r'Version 2\.0')
        missing = [str(path.relative_to(REPO))
                   for folder in ('urdfgenpy_ros', 'test', 'bench', 'docs')
                   for path in sorted((REPO / folder).rglob('*.py'))
                   if not header.match(path.read_text(encoding='utf-8'))]
        assert missing == [], 'files without the Apache-2.0 header: ' + ', '.join(missing)
        assert (REPO / 'LICENSE').read_text().lstrip().startswith('Apache License')
    else:
        assert main(argv=['.', 'test']) == 0, 'Found errors'


def test_only_robot_py_touches_the_robots_own_tables() -> None:
    """
    Links, joints and materials are reached through Robot's methods everywhere else.

    Robot's methods are in robot.py and in model/__init__.py, its base RobotModel.
    """
    import ast
    private = {'_links', '_joints', '_materials'}
    found = []
    for path in sorted((REPO / 'urdfgenpy_ros').rglob('*.py')):
        relative = path.relative_to(REPO / 'urdfgenpy_ros').as_posix()
        if relative in ('robot.py', 'model/__init__.py'):
            continue
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.Attribute) and node.attr in private:
                found.append(f'{path.relative_to(REPO)}:{node.lineno} .{node.attr}')
    assert not found, found
