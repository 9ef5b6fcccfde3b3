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

"""Xacro reading: the real ``xacro`` expands the file, then the URDF reader reads it."""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager, redirect_stderr
import io
import os
from os import PathLike
from pathlib import Path
import re
import threading
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.formats.urdf_read import read_urdf_bytes
from urdfgenpy_ros.formats.xacro_args import misspelt_arguments, unknown_arguments
from urdfgenpy_ros.formats.xacro_map import pretty_print, recording, XacroMap
from urdfgenpy_ros.model.errors import (
    MissingDependencyError, PACKAGE_FOLDER, ParseError, ReadWarning, SourceLocation)
from urdfgenpy_ros.resources import PackageResolver

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


class _PackageMissing(LookupError):
    """A ``$(find pkg)`` nothing answers; its message is the whole story."""


_LOCK = threading.Lock()  # xacro keeps its state in module globals: one read at a time


def _xacro() -> Any:
    try:
        import xacro
    except ImportError:
        raise MissingDependencyError('xacro', 'xacro', 'Reading Xacro') from None
    return xacro


@contextmanager
def _fresh_state(xacro: Any) -> Iterator[list[str]]:
    """
    Give one expansion xacro's module state of its own; yield the list of its includes.

    xacro appends every file it includes to the module-level ``all_includes`` and never
    empties it, so in a long-running process each read would report (and the node watch)
    the files of every earlier read. Reset it, and the file and macro stacks, around
    each read, so that nothing grows with the number of reads.
    """
    included: list[str] = []
    xacro.all_includes = included
    try:
        yield included
    finally:
        xacro.all_includes = []
        xacro.init_stacks(None)
        xacro.substitution_args_context.clear()


@contextmanager
def _finding_with(resolver: PackageResolver) -> Iterator[None]:
    """Answer xacro's ``$(find pkg)`` from ``resolver`` first, then as xacro would."""
    from xacro import substitution_args
    original = substitution_args._eval_find

    def find(package: str) -> str:
        found = resolver.find(package)
        if found is not None:
            return str(found)
        try:
            return original(package)
        except Exception:  # noqa: B902 - ament's, rospkg's or an unset AMENT_PREFIX_PATH
            raise _PackageMissing(
                f'$(find {package}): package {package!r} not found (source the workspace '
                f'that holds it, or {PACKAGE_FOLDER.text})'
            ) from None

    substitution_args._eval_find = find
    try:
        yield
    finally:
        substitution_args._eval_find = original


def _failure(error: Exception, context: str, printed: str) -> str:
    """Return the one line saying why xacro failed, with where and what it warned."""
    cause = getattr(error, 'exc', None)  # xacro wraps what substitutions raise
    shown = cause if isinstance(cause, _PackageMissing) else error
    message = ' '.join(str(shown).split()) or type(error).__name__
    message = _ERRNO_AGAIN.sub('', message)  # xacro adds the OSError it already told
    if ('ament_index_python' in message or 'PackageNotFound' in type(error).__name__) \
            and 'search_paths' not in message:
        message += ' (pass the package folders in search_paths)'
    if context:
        message += f' ({context})'
    said = _xacro_warnings(printed)
    if said:
        message += f' (xacro warned: {"; ".join(said)})'
    return message


def expand_xacro(path: str | PathLike[str], mappings: Mapping[str, str] | None = None,
                 resolver: PackageResolver | None = None,
                 warnings: list[ReadWarning] | None = None,
                 maps: list[XacroMap] | None = None,
                 texts: Mapping[str, str] | None = None) -> tuple[str, list[str]]:
    """
    Return the URDF text ``xacro`` makes of ``path`` and every file it included.

    What xacro would print on stderr is not printed: its warnings are appended to
    ``warnings`` (code X102) and, when expansion fails, end the error's one line.
    Given ``maps``, the source map of the text (where each element was written) is
    appended to it; the text is the same either way. ``texts`` (absolute path: text,
    with ``maps``) are expanded instead of those files, as if they had been saved.

    :raises ParseError: with xacro's message, when expansion fails (code X001).
    """
    xacro = _xacro()
    resolver = resolver or PackageResolver()
    where = SourceLocation(str(path))
    printed = io.StringIO()
    context = ''
    stack: list[str] = []
    seen: list[str] = [str(path)]  # the files read when expansion fails
    try:
        with _LOCK, redirect_stderr(printed), _fresh_state(xacro) as includes, \
                _finding_with(resolver), _mapping(xacro, maps is not None, texts) as recorder:
            try:
                document = xacro.process_file(str(path), mappings=dict(mappings or {}))
            except Exception:  # noqa: B902 - where it was, before the stacks are reset
                context = _macro_context(xacro)
                stack = [str(name) for name in getattr(xacro, 'filestack', None) or []]
                seen += [*includes, *stack]
                raise
            names = list(dict.fromkeys(includes))
            if recorder is not None:  # xacro's own print, with where each tag starts
                text, source_map = pretty_print(recorder, document)
    except Exception as error:  # noqa: B902 - xacro raises many types; all are one line
        message = _failure(error, context, printed.getvalue()) + misspelt_arguments(
            dict.fromkeys(seen), mappings or {})
        raise ParseError(f'xacro: {message}', _error_place(where, stack, message), 'X001',
                         (PACKAGE_FOLDER,) if PACKAGE_FOLDER.text in message else ()) from None
    if warnings is not None:
        warnings += [ReadWarning(where, 'X102', f'xacro: {line}')
                     for line in _xacro_warnings(printed.getvalue())]
    included = [str(Path(name).resolve()) for name in names]
    if maps is None:
        return document.toprettyxml(indent='  '), included
    maps.append(source_map)
    return text, included


@contextmanager
def _mapping(xacro: Any, wanted: bool, texts: Mapping[str, str] | None) -> Iterator[Any]:
    """Record the source map of the expansion inside, when ``wanted``."""
    if not wanted:
        yield None
        return
    with recording(xacro, texts) as recorder:
        yield recorder


_XML_AT = re.compile(r'line (\d+), column (\d+)')


def _error_place(top: SourceLocation, stack: list[str], message: str) -> SourceLocation:
    """
    Return where xacro's error is: the file it was reading (an include, say).

    An XML error also gets its line and column (xacro gives expat's column, from 0).
    """
    file = top.file
    if stack and top.file is not None and Path(stack[-1]).resolve() != Path(top.file).resolve():
        relative = os.path.relpath(stack[-1])
        file = stack[-1] if relative.startswith('..') else relative
    found = _XML_AT.search(message)
    if found is None:
        return SourceLocation(file)
    return SourceLocation(file, int(found.group(1)), int(found.group(2)) + 1)


def _macro_context(xacro: Any) -> str:
    """Return the macros xacro was instantiating, innermost first, as its CLI names them."""
    try:
        calls = [f'{macro.body.getAttribute("name")} ({macro.history[-1][-1]})'
                 for macro in reversed(xacro.macrostack or [])]
    except (AttributeError, IndexError, TypeError):  # xacro's internals changed
        return ''
    return f'when instantiating macro {", from ".join(calls)}' if calls else ''


_ERRNO_AGAIN = re.compile(r" \[Errno \d+\] [^:]+: '[^']*'$")


def _xacro_warnings(printed: str) -> list[str]:
    """Return xacro's warnings from what it printed, without its file-stack lines."""
    stack = ('when processing file:', 'in file:', 'included from:',
             'when instantiating macro:', 'instantiated from:')
    lines = (' '.join(line.split()) for line in printed.splitlines())
    return [line.removeprefix('warning: ') for line in lines
            if line and not line.startswith(stack)]


def read_xacro(path: str | PathLike[str], mappings: Mapping[str, str] | None = None,
               search_paths: Iterable[str | PathLike[str]] = (),
               packages: Mapping[str, str | PathLike[str]] | None = None,
               cls: type[RobotModel] | None = None) -> RobotModel:
    """Expand the Xacro file ``path`` with ``mappings`` (``name: value``) and read it."""
    said: list[ReadWarning] = []
    maps: list[XacroMap] = []
    text, included = expand_xacro(path, mappings, PackageResolver(search_paths, packages),
                                  said, maps)
    try:
        robot = read_urdf_bytes(text.encode('utf-8'), f'{path} (expanded)', cls)
    except ParseError as error:
        from urdfgenpy_ros.formats.xacro_source import error_in_source
        raise no_robot_in(path, text) or error_in_source(
            error, text, [str(Path(path).resolve()), *included], str(path),
            maps[0]) from None
    robot.source_map = maps[0]
    if not robot.links:  # a macro library with a robot name (franka's fr3.xacro)
        library = no_robot_in(path, text)
        if library is not None:
            raise library
    robot.included_files = [str(Path(path).resolve()), *included]
    said += unknown_arguments(robot.included_files, mappings or {}, str(path))
    robot.read_warnings[:0] = said
    return robot


_MATERIAL = re.compile(r'<material\s[^>]*?\bname\s*=\s*["\']([^"\']+)')
_MACRO = re.compile(r'<xacro:macro\s[^>]*?\bname\s*=\s*["\']([^"\']+)')


def no_robot_in(path: str | PathLike[str], expanded: str) -> ParseError | None:
    """Return the error of a file of macros or materials read as a robot, or None."""
    try:
        source = Path(path).read_text('utf-8', 'replace')
    except OSError:
        return None
    if '<link' in expanded:
        return None
    names, line = _MACRO.findall(source), None
    if names:
        what, call = 'macros', f' and calls <xacro:{names[0]} .../>'
    else:  # a file of materials only (diffbot.materials.xacro)
        names, what, call = _MATERIAL.findall(expanded), 'materials', ''
        if not names:
            return None
        line = next((number for number, text in enumerate(source.splitlines(), start=1)
                     if '<material' in text), None)
    return ParseError(
        f'defines {what} ({", ".join(names[:3])}{", ..." if len(names) > 3 else ""}) and no '
        f'robot: read a robot file that includes it{call}',
        SourceLocation(str(path), line), 'X003')
