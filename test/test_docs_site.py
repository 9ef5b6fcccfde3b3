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
The documentation site builds with ``mkdocs build --strict``; its generated parts follow the code.

Strict: a broken link or anchor, a missing API reference or a page left out fails the build.
The version is written once (``__init__.py``); setup.py reads it and package.xml, a literal
for ROS's tools, must agree, as must CHANGELOG.md's newest release.
"""

from __future__ import annotations

from pathlib import Path
import re
import subprocess
import sys

from helpers import REPO, require_module
from lxml import etree
import pytest

import urdfgenpy_ros

pytestmark = pytest.mark.docs  # mkdocs build --strict


@pytest.fixture(scope='module')
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Build the site once, strictly, into a scratch folder."""
    for module in ('mkdocs', 'material', 'mkdocstrings_handlers.python'):
        require_module(module)  # the docs (and test) extra; CI fails without it
    folder = tmp_path_factory.mktemp('site')
    result = subprocess.run([sys.executable, '-m', 'mkdocs', 'build', '--strict', '--site-dir',
                             str(folder)], cwd=REPO, capture_output=True, text=True,
                            timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    return folder


def _text(page: Path) -> str:
    """Return the visible text of a built page."""
    return ''.join(etree.parse(str(page), etree.HTMLParser()).getroot().itertext())


def test_every_page_is_built(site: Path) -> None:
    for page in (REPO / 'docs').glob('*.md'):
        built = site / ('index.html' if page.stem == 'index' else f'{page.stem}/index.html')
        assert built.is_file(), f'{page.name} was not built'


def test_the_code_table_lists_every_code_with_its_severity_and_title(site: Path) -> None:
    from urdfgenpy_ros.model.codes import CODES
    rows = {}
    for row in etree.parse(str(site / 'validation' / 'index.html'),
                           etree.HTMLParser()).iter('tr'):
        cells = [''.join(cell.itertext()).strip() for cell in row.iter('td')]
        if cells and re.fullmatch(r'[A-Z]\d{3}', cells[0]):
            rows[cells[0]] = (cells[1], cells[2])
    assert rows == {code: (severity.value, title) for code, (severity, title) in CODES.items()}


def test_the_parameter_table_is_what_the_node_declares(site: Path) -> None:
    """Compared with the parameters a running node lists (rclpy), not with the hook."""
    rclpy = pytest.importorskip('rclpy')
    from urdfgenpy_ros.publisher.node import PublisherNode
    from rclpy.node import Node
    rclpy.init()
    try:
        bare = Node('bare')  # the parameters every rclpy node has
        node = PublisherNode()
        ours = set(node._parameters) - set(bare._parameters) - {'robot_description'}
        declared = {name: node.get_parameter(name).value for name in ours}
        node.destroy_node()
        bare.destroy_node()
    finally:
        rclpy.try_shutdown()
    shown = {}
    for row in etree.parse(str(site / 'node' / 'index.html'), etree.HTMLParser()).iter('tr'):
        cells = [''.join(cell.itertext()).strip() for cell in row.iter('td')]
        if cells:
            shown[cells[0]] = cells[2]
    spelt = {name: ('true' if value else 'false') if isinstance(value, bool) else
             repr(value) if isinstance(value, str) else str(value)
             for name, value in declared.items()}
    assert shown == spelt


@pytest.mark.parametrize('page, instead', [
    ('commands.md', 'urdfgenpy COMMAND --help')])
def test_a_generated_table_says_on_github_where_it_is(site: Path, page: str,
                                                      instead: str) -> None:
    """Python-Markdown shows the page as GitHub does (no hooks): comments are not text."""
    markdown = require_module('markdown')
    raw = (REPO / 'docs' / page).read_text(encoding='utf-8')
    github = ' '.join(''.join(etree.fromstring(f'<div>{markdown.markdown(raw)}</div>',
                                               etree.HTMLParser()).itertext()).split())
    after = github.split('when the site is built', 1)
    assert len(after) == 2 and instead in after[1][:300]
    built = _text(site / page.removesuffix('.md') / 'index.html')
    assert 'when the site is built' not in built and 'end generated' not in built


def test_the_api_reference_documents_robot(site: Path) -> None:
    text = _text(site / 'api' / 'robot' / 'index.html')
    for name in ('from_urdf', 'from_xacro', 'validate', 'save', 'to_urdf', 'attach'):
        assert name in text, name


def test_the_version_is_the_same_everywhere() -> None:
    version = urdfgenpy_ros.__version__
    package_xml = etree.parse(str(REPO / 'package.xml')).findtext('version')
    assert package_xml == version, 'package.xml <version> differs from __init__.__version__'
    result = subprocess.run([sys.executable, 'setup.py', '--version'], cwd=REPO,
                            capture_output=True, text=True, timeout=120)
    assert result.stdout.strip().splitlines()[-1] == version
    released = re.findall(r'^## \[(\d+\.\d+\.\d+)\]', (REPO / 'CHANGELOG.md').read_text(), re.M)
    assert released and released[0] == version, 'CHANGELOG.md newest release differs'
