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
The formats urdfgenpy reads and writes, declared as data: one row per format.

A row names the format, the file suffixes it owns, its reader and writer (None when it
has none), its writer's options (each an :class:`~urdfgenpy_ros.formats.options.Option`,
giving both the Python keyword and ``convert``'s flag) and its ``prepare``, what the target
refuses. Every front end (the library's ``load``/``save``, the CLI, the node, assembly
files, the scaffold, the viewer) finds a format here, so a suffix nobody declares is
refused in one line everywhere, and adding a format is one module plus one row
(:func:`register` adds one at run time).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from functools import cached_property
from os import PathLike
from pathlib import Path
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.errors import ModelError

if TYPE_CHECKING:  # the writers' options and prepare load when asked for (start-up)
    from urdfgenpy_ros.formats.options import Option
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.model.review import ReviewRecord

PathArg = str | PathLike[str]
Reader = Callable[[Path, Mapping[str, str], Iterable[PathArg]], 'RobotModel']
Writer = Callable[..., str]
Options = tuple['Option', ...] | Callable[[], tuple['Option', ...]]


@dataclass(frozen=True)
class Format:
    """
    One format: its name, suffixes, reader, writer, the writer's options and ``prepare``.

    ``options`` may be a function returning them (called when first asked for).
    ``prepare(robot, options)`` returns the :class:`ReviewRecord` of what the target refuses;
    ``one_tree`` says ``convert`` refuses a robot that is not one tree before any other
    word; ``misplaced`` words the refusal of its flags on other output (``{flag}``: the
    first, ``{flags}``: all).
    """

    name: str
    suffixes: tuple[str, ...]
    description: str
    reader: Reader | None
    writer: Writer | None
    options: Options = ()
    not_read: str = ''  # why it cannot be read, and what to do instead
    prepare: Callable[[RobotModel, Mapping[str, Any]], ReviewRecord] | None = None
    one_tree: bool = False
    misplaced: str = '{flag} applies to {suffix} output only: drop it or write {suffix}'

    def matches(self, path: PathArg) -> bool:
        """Return whether the file name ``path`` ends in one of this format's suffixes."""
        return Path(path).name.lower().endswith(self.suffixes)

    def declared(self) -> tuple[Option, ...]:
        """Return the writer's options."""
        return self.options() if callable(self.options) else self.options

    def keywords(self) -> tuple[str, ...]:
        """Return the writer's Python keywords."""
        from urdfgenpy_ros.formats.options import keywords
        return keywords(self.declared())

    @cached_property
    def _taken(self) -> frozenset[str]:
        """Return the writer's Python keywords as a set (asked on every write)."""
        return frozenset(self.keywords())


def _read_urdf(path: Path, mappings: Mapping[str, str], search_paths: Iterable[PathArg]
               ) -> RobotModel:
    from urdfgenpy_ros.formats.detect import xacro_evidence_in
    from urdfgenpy_ros.formats.urdf_read import read_urdf_bytes
    data = path.read_bytes()
    evidence = xacro_evidence_in(data, str(path))
    if evidence is None:
        from urdfgenpy_ros.model.errors import ParseError
        try:
            return read_urdf_bytes(data, str(path))
        except ParseError as error:  # a file of materials only, included by robots
            from urdfgenpy_ros.formats.xacro_read import no_robot_in
            raise no_robot_in(path, data.decode('utf-8', 'replace')) or error from None
    if evidence.weak:  # only a $(...) in a mesh filename: read as urdfdom does, X104
        from urdfgenpy_ros.formats.detect import weak_evidence_warning
        robot = read_urdf_bytes(data, str(path))
        robot.read_warnings.insert(0, weak_evidence_warning(evidence))
        return robot
    from urdfgenpy_ros.model.errors import ReadWarning
    robot = _read_xacro(path, mappings, search_paths)
    given = ' '.join(f'{name}:={value}' for name, value in mappings.items())
    robot.read_warnings.insert(0, ReadWarning(evidence.location, 'X101', (
        f'the file is Xacro ({evidence.what}): expanded with xacro '
        f'({"arguments " + given if given else "no arguments"}); plain URDF tools cannot '
        'read it, so name it .urdf.xacro')))
    return robot


def _read_xacro(path: Path, mappings: Mapping[str, str], search_paths: Iterable[PathArg]
                ) -> RobotModel:
    from urdfgenpy_ros.formats.xacro_read import read_xacro
    return read_xacro(path, dict(mappings), search_paths=list(search_paths))


def _read_assembly(path: Path, mappings: Mapping[str, str],
                   search_paths: Iterable[PathArg]) -> RobotModel:
    from urdfgenpy_ros.formats.assembly_file import read_assembly
    return read_assembly(path, list(search_paths), load=load)  # parts: any format


def _read_table(path: Path, mappings: Mapping[str, str], search_paths: Iterable[PathArg]
                ) -> RobotModel:
    from urdfgenpy_ros.formats.assembly_file import is_assembly
    if is_assembly(path):  # a YAML file with a top-level parts:
        return _read_assembly(path, mappings, search_paths)
    from urdfgenpy_ros.formats.dh_table import read_table
    from urdfgenpy_ros.model.dh_skeleton import skeleton, TableRows
    return skeleton(read_table(path, TableRows), path.name.split('.')[0])


def _write_urdf(robot: RobotModel, path: PathArg, version: str | None = None) -> str:
    from urdfgenpy_ros.formats.urdf import write_urdf
    if version is not None:
        from urdfgenpy_ros.caller import warn_caller
        from urdfgenpy_ros.formats.urdf_downgrade import as_version
        robot, changes = as_version(robot, version)
        for change in changes:
            warn_caller(str(change))
    return write_urdf(robot, path)


def _write_xacro(robot: RobotModel, path: PathArg, macro: bool = False) -> str:
    from urdfgenpy_ros.formats import xacro
    return xacro.write_macro_xacro(robot, path) if macro else xacro.write_xacro(robot, path)


def _write_sdf(robot: RobotModel, path: PathArg, lump_fixed: bool = False,
               version: str | None = None) -> str:
    from urdfgenpy_ros.formats.sdf import write_sdf
    return write_sdf(robot, path, lump_fixed, version)


def write_mjcf_warning(robot: RobotModel, path: PathArg | None, **options: Any) -> str:
    """
    Return the MJCF text (and write it with ``path``), warning at the caller's line.

    Each thing the MJCF cannot carry is a ``UserWarning`` in ``check``'s format, as is
    what asks the user to act (no actuator written, a servo that needs damping).
    """
    from urdfgenpy_ros.caller import warn_caller
    from urdfgenpy_ros.formats.mjcf import write_mjcf
    result = write_mjcf(robot, path, **options)
    for finding in result.findings:
        warn_caller(str(finding))
    for advice in result.advice:
        warn_caller(f'{robot.name}: {advice}')
    return result.text


def _options(name: str) -> Callable[[], tuple[Option, ...]]:
    """Return the writer options ``writer_options.name`` gives, imported when asked (start-up)."""
    def options() -> tuple[Option, ...]:
        from urdfgenpy_ros.formats import writer_options
        found: tuple[Option, ...] = getattr(writer_options, name)()
        return found
    return options


def _prepare(name: str) -> Callable[[RobotModel, Mapping[str, Any]], ReviewRecord]:
    """Return ``prepare.name``, the format's prepare, imported at its first call (start-up)."""
    def prepare(robot: RobotModel, options: Mapping[str, Any]) -> ReviewRecord:
        from urdfgenpy_ros.formats import prepare as module
        found: ReviewRecord = getattr(module, name)(robot, options)
        return found
    return prepare


FORMATS: list[Format] = [
    Format('xacro', ('.urdf.xacro', '.xacro'), 'Xacro', _read_xacro, _write_xacro,
           _options('xacro_options')),
    Format('urdf', ('.urdf',), 'URDF', _read_urdf, _write_urdf, _options('urdf_options'),
           misplaced='{flag} applies to .urdf and .xacro output only: drop it or write .urdf'),
    Format('sdf', ('.sdf',), 'SDF', None, _write_sdf, _options('sdf_options'),
           not_read='reading SDF is not supported (convert from URDF or Xacro)',
           prepare=_prepare('prepare_sdf'), one_tree=True),
    Format('mjcf', ('.xml', '.mjcf'), 'MuJoCo MJCF', None, write_mjcf_warning,
           _options('mjcf_options'),
           not_read='reading MJCF is not supported: urdfgenpy writes it (a URDF or Xacro '
                    'file named .xml: rename it .urdf or .urdf.xacro)',
           prepare=_prepare('prepare_mjcf'), one_tree=True,
           misplaced='{flags} apply to MJCF output (.xml, .mjcf) only: drop them or write .xml'),
    Format('assembly', ('.assembly.yaml', '.assembly.yml'), 'assembly file',
           _read_assembly, None),
    Format('dh', ('.yaml', '.yml', '.csv'), 'DH table', _read_table, None),
]
"""Every format, most specific suffix first (``.urdf.xacro`` before ``.urdf``)."""


def register(row: Format) -> None:
    """
    Add the format ``row`` (a suffix it shares with a row already there is refused).

    It goes first, so a suffix more specific than another row's (``.toy.json``) wins.
    """
    taken = [f'suffix {suffix}' for suffix in row.suffixes
             if find_format(f'x{suffix}') is not None]
    taken += ['name'] if any(other.name == row.name for other in FORMATS) else []
    if taken:
        raise ModelError(f'format {row.name!r}: its {" and ".join(taken)} already belong '
                         'to another format: choose another')
    FORMATS.insert(0, row)


def unregister(name: str) -> None:
    """Remove the format called ``name``."""
    FORMATS[:] = [row for row in FORMATS if row.name != name]


@contextmanager
def registered(row: Format) -> Iterator[Format]:
    """Add the format ``row`` for the ``with`` block (a test's format, say)."""
    register(row)
    try:
        yield row
    finally:
        unregister(row.name)


def _known(role: str) -> str:
    rows = [row for row in FORMATS if (row.reader if role == 'read' else row.writer)]
    if role == 'read':  # the descriptions first, then the other rows
        rest = [f"{row.description}s ({', '.join(row.suffixes)})" for row in rows
                if row.name not in ('urdf', 'xacro')]
        return '.urdf, .xacro and .urdf.xacro files, ' + ' and '.join(rest)
    return ', '.join(f"{' '.join(row.suffixes)} ({row.description})" for row in rows)


def find_format(path: PathArg) -> Format | None:
    """Return the row whose suffix ``path`` ends in, or None."""
    return next((row for row in FORMATS if row.matches(path)), None)


def readable_suffixes() -> tuple[str, ...]:
    """Return every suffix some format reads."""
    return tuple(suffix for row in FORMATS if row.reader for suffix in row.suffixes)


def reader_for(path: PathArg) -> Format:
    """
    Return the format that reads ``path``.

    :raises ModelError: one line naming the file, the suffix and what is read instead.
    """
    row = find_format(path)
    if row is None:
        raise ModelError(f'{path}: unknown suffix {Path(path).suffix.lower()!r} (urdfgenpy '
                         f'reads {_known("read")})')
    if row.reader is None:
        raise ModelError(f'{path}: {row.not_read}')
    return row


def writer_for(path: PathArg) -> Format:
    """
    Return the format that writes ``path``.

    :raises ModelError: one line naming the file, the suffix and what is written instead.
    """
    row = find_format(path)
    if row is None or row.writer is None:
        what = ('unknown suffix' if row is None
                else f'{row.description} is read, not written: suffix')
        raise ModelError(f'{path}: {what} {Path(path).suffix.lower()!r} (urdfgenpy writes '
                         f'{_known("write")})')
    return row


def _named(name: str) -> Format:
    """Return the row called ``name`` (asked on every ``Robot.to_*``: a plain loop)."""
    for row in FORMATS:
        if row.name == name:
            return row
    raise KeyError(f'no format called {name!r}')  # a bug of ours: names are the table's


def write_as(robot: RobotModel, name: str, path: PathArg | None, **options: Any) -> str:
    """Return the text of ``robot`` in the format called ``name``; write it with ``path``."""
    return _write(_named(name), robot, path, options)


def save(robot: RobotModel, path: PathArg, **options: Any) -> None:
    """
    Write ``robot`` to ``path`` in the format its suffix names, with the writer's options.

    :raises ModelError: for a suffix no format writes, or an option its writer lacks.
    """
    _write(writer_for(path), robot, path, options)


def _write(row: Format, robot: RobotModel, path: PathArg | None, options: Mapping[str, Any]
           ) -> str:
    """Return ``row``'s writer's text; refuse an option it lacks in one line."""
    if options.keys() <= row._taken:
        assert row.writer is not None
        return row.writer(robot, path, **options)
    taken = row.keywords()
    unknown = sorted(set(options) - set(taken))
    if unknown:
        raise ModelError(f'{path}: {row.description} output takes no option '
                         f"{', '.join(unknown)} (it takes {', '.join(taken) or 'none'})")
    assert row.writer is not None
    return row.writer(robot, path, **options)


def load(path: str | PathLike[str], mappings: Mapping[str, str] | None = None,
         search_paths: Iterable[str | PathLike[str]] = ()) -> RobotModel:
    """
    Read a robot from ``path`` in the format its suffix names.

    ``mappings`` are Xacro arguments; ``search_paths`` folders holding ROS packages. An
    assembly file (``*.assembly.yaml``, or YAML with a top-level ``parts:``) gives the
    robot its parts make; any other .yaml, .yml or .csv file is a DH table and gives its
    skeleton. A ``.urdf`` file that is Xacro (TurtleBot3's are) is expanded with xacro, as
    ROS launch files do, and the robot gets a read warning (X101) saying so. A suffix no
    format reads (``.sdf``, ``.xml``, ``.txt``) is refused in one line.

    :raises ModelError: for a suffix no format reads.
    """
    row = reader_for(path)
    assert row.reader is not None
    return row.reader(Path(path), dict(mappings or {}), search_paths)
