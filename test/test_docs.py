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
Every Python and shell block of README.md and docs/*.md runs as written, page by page.

One test per block, in page order, in a scratch folder per page; Python blocks share a
namespace per page. ``<!-- docs-test: given FILE ... -->`` before a shell block writes the
files the reader brings (docs_given.GIVEN); ``<!-- docs-test: skip REASON -->`` skips the
next block with that reason. What the blocks write is read back by check_urdf. A page's
Python blocks also run alone, in order, in an empty folder, as a reader pasting them into
a notebook runs them: they make what they need.
"""

from __future__ import annotations

from dataclasses import dataclass, field
import os
from pathlib import Path
import re
import subprocess
import sys
from typing import Any

from docs_given import GIVEN
from helpers import check_urdf, REPO, urdfdom6_tool
import pytest

pytestmark = pytest.mark.docs  # every block of every page, in order

PAGES = [REPO / 'README.md', *sorted((REPO / 'docs').glob('*.md'))]
FENCE = re.compile(r'^(?P<indent>[ \t]*)```(?P<lang>[\w+-]*)[^\n`]*\n(?P<body>.*?)'
                   r'^(?P=indent)```[ \t]*$', re.M | re.S)
MARKER = re.compile(r'^<!-- docs-test: (?P<what>given|skip)\b ?(?P<text>.*?) -->[ \t]*$', re.M)
RUNS = {'python': 'python', 'py': 'python', 'bash': 'shell', 'sh': 'shell',
        'shell': 'shell', 'console': 'shell'}
# Commands the environment of scripts/setup does not have, or that build whole workspaces.
NEEDS_SKIP = re.compile(r'(?:^|[;&|(]\s*)(ros2|rviz2|colcon)\b', re.M)


@dataclass
class Block:
    """One runnable fenced block of a page."""

    page: Path
    line: int
    language: str
    code: str
    given: tuple[str, ...] = ()
    skip: str | None = None

    @property
    def name(self) -> str:
        """Return ``page:line`` for the test id and messages."""
        return f'{self.page.relative_to(REPO)}:{self.line}'


def blocks_of(page: Path) -> list[Block]:
    """Return the runnable blocks of ``page`` in order, with their markers."""
    text = page.read_text(encoding='utf-8')
    events = sorted([(m.start(), 'marker', m) for m in MARKER.finditer(text)]
                    + [(m.start(), 'fence', m) for m in FENCE.finditer(text)],
                    key=lambda event: event[0])
    blocks: list[Block] = []
    given: tuple[str, ...] = ()
    skip: str | None = None
    inside_until = -1
    for start, kind, match in events:
        if start < inside_until:
            continue  # a marker quoted inside a fenced block
        if kind == 'marker':
            if match['what'] == 'given':
                given = tuple(match['text'].split())
                following = FENCE.search(text, match.end())
                assert following is None or RUNS.get(following['lang'].lower()) != 'python', (
                    f'{page.name}: a Python block makes the files it needs (a reader runs '
                    f'it in an empty folder): write {given} in the block, not "given"')
                unknown = [name for name in given if name not in GIVEN]
                assert not unknown, f'{page.name}: no given file {unknown} in docs_given.GIVEN'
            else:
                skip = match['text'] or 'no reason given'
            continue
        inside_until = match.end()
        language = RUNS.get(match['lang'].lower())
        if language is None:
            continue
        indent = len(match['indent'])
        body = ''.join(line[indent:] for line in match['body'].splitlines(keepends=True))
        if match['lang'].lower() == 'console':
            body = ''.join(line[2:] + '\n' for line in body.splitlines()
                           if line.startswith('$ '))
        line = text.count('\n', 0, start) + 2
        blocks.append(Block(page, line, language, body, given, skip))
        given, skip = (), None
    return blocks


BLOCKS = [block for page in PAGES for block in blocks_of(page)]


@dataclass
class PageRun:
    """The state of one page's blocks: its folder, namespace and how far it got."""

    folder: Path
    namespace: dict[str, Any] = field(default_factory=lambda: {'__name__': '__docs__'})
    done: int = 0
    failed: str | None = None


def _environment() -> dict[str, str]:
    """Return the environment of a shell block: this package's commands first on PATH."""
    env = dict(os.environ)
    env['PATH'] = os.pathsep.join([str(Path(sys.executable).parent), env.get('PATH', '')])
    env['PYTHONPATH'] = os.pathsep.join(filter(None, [str(REPO), env.get('PYTHONPATH')]))
    env['NO_COLOR'] = '1'
    return env


def _run(block: Block, run: PageRun) -> None:
    """Run ``block`` in its page's folder; fail with what it printed when it fails."""
    for name in block.given:
        if not (run.folder / name).exists():
            GIVEN[name](run.folder / name)
    if block.language == 'python':
        code = compile('\n' * (block.line - 1) + block.code, str(block.page), 'exec')
        cwd = os.getcwd()
        os.chdir(run.folder)
        try:
            exec(code, run.namespace)
        finally:
            os.chdir(cwd)
        return
    result = subprocess.run(['bash', '-e', '-o', 'pipefail', '-c', block.code], cwd=run.folder,
                            env=_environment(), capture_output=True, text=True, timeout=900)
    if result.returncode != 0:
        pytest.fail(f'{block.name}: exit status {result.returncode}\n{block.code}\n'
                    f'--- stdout\n{result.stdout}\n--- stderr\n{result.stderr}')


def _assert_urdfdom_reads(path: Path) -> None:
    """Fail unless urdfdom reads a URDF a page wrote: Jazzy's, or urdfdom 6 for 1.1/1.2."""
    declared = re.search(r'<robot\b[^>]*\bversion=["\'](1\.[12])', path.read_text())
    if declared:
        result = subprocess.run([urdfdom6_tool('check_urdf'), str(path)], capture_output=True,
                                text=True, timeout=30)
    else:
        result = check_urdf(path)
    assert result.returncode == 0, f'check_urdf refuses {path}:\n{result.stdout}{result.stderr}'


@pytest.fixture(scope='session')
def page_runs(tmp_path_factory: pytest.TempPathFactory) -> dict[Path, PageRun]:
    """Return a lazily filled map of page to its run."""
    return {}


def _page_run(page: Path, runs: dict[Path, PageRun],
              factory: pytest.TempPathFactory) -> PageRun:
    if page not in runs:
        runs[page] = PageRun(factory.mktemp(page.stem))
    return runs[page]


@pytest.mark.parametrize('block', BLOCKS, ids=[f'{b.name}-{b.language}' for b in BLOCKS])
def test_block_runs(block: Block, page_runs: dict[Path, PageRun],
                    tmp_path_factory: pytest.TempPathFactory) -> None:
    """Run the page's blocks up to ``block``, in order; skip it when the page says so."""
    if block.skip is None and block.language == 'shell':
        needs = NEEDS_SKIP.search(block.code)
        assert needs is None, (
            f'{block.name} calls {needs[1]!r}, which the tests do not have: put '
            f'"<!-- docs-test: skip REASON -->" before the block, or run something else')
    run = _page_run(block.page, page_runs, tmp_path_factory)
    page_blocks = [b for b in BLOCKS if b.page == block.page]
    target = page_blocks.index(block)
    while run.done <= target:
        if run.failed is not None:
            pytest.fail(f'{block.name}: not run, {run.failed} failed before it')
        current = page_blocks[run.done]
        run.done += 1
        if current.skip is not None:
            continue
        try:
            _run(current, run)
        except BaseException:
            run.failed = current.name
            raise
    if block.skip is not None:
        pytest.skip(f'{block.name}: {block.skip}')
    if block is page_blocks[-1]:
        for urdf in sorted(run.folder.rglob('*.urdf')):
            _assert_urdfdom_reads(urdf)


PYTHON_PAGES = [page for page in PAGES
                if any(b.language == 'python' and b.skip is None for b in blocks_of(page))]


@pytest.mark.parametrize('page', PYTHON_PAGES, ids=[page.name for page in PYTHON_PAGES])
def test_python_blocks_run_alone_in_an_empty_folder(page: Path, tmp_path: Path) -> None:
    """A page's Python blocks, without its shell blocks or given files, run in order."""
    run = PageRun(tmp_path)
    for block in blocks_of(page):
        if block.language == 'python' and block.skip is None:
            assert block.given == ()
            _run(block, run)


def test_every_page_is_found_and_every_marker_is_used() -> None:
    """The glob finds the pages; a marker with no block after it is a mistake."""
    assert REPO / 'README.md' in PAGES and REPO / 'docs' / 'index.md' in PAGES
    for page in PAGES:
        text = page.read_text(encoding='utf-8')
        markers = len([m for m in MARKER.finditer(text)
                       if not any(f.start() < m.start() < f.end()
                                  for f in FENCE.finditer(text))])
        used = sum(1 for block in blocks_of(page) if block.given) + sum(
            1 for block in blocks_of(page) if block.skip is not None)
        assert used >= markers, f'{page.name}: a docs-test marker without a block after it'


def test_readme_lists_every_command() -> None:
    """The table of commands in README.md names each command of ``urdfgenpy --help``."""
    from urdfgenpy_ros.cli import main
    readme = (REPO / 'README.md').read_text(encoding='utf-8')
    table = set(re.findall(r'^\| `urdfgenpy (\w+)', readme, re.M))
    assert table == set(main.commands), sorted(set(main.commands) ^ table)  # type: ignore


def test_readme_links_lead_to_files_that_exist() -> None:
    """README.md is read on the forge, outside the site: its relative links must resolve."""
    readme = (REPO / 'README.md').read_text(encoding='utf-8')
    targets = re.findall(r'\]\(([^)#\s]+)(?:#[^)]*)?\)', readme)
    missing = [target for target in targets
               if '://' not in target and not (REPO / target).exists()]
    assert targets and not missing, missing
