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

"""Errors a user can meet, and where in a file they come from."""

from __future__ import annotations

from dataclasses import FrozenInstanceError
from enum import Enum
from typing import NamedTuple


class Fix(NamedTuple):
    """
    How to fix a user's mistake, as data: the library's words and the input they name.

    ``names`` is the input the fix points the user at (``package_paths``): each front end
    says it in its own words (``-p/--package-path``, the node's parameter).
    """

    text: str
    names: str = ''


PACKAGE_FOLDER = Fix('pass its folder in search_paths / --package-path', 'package_paths')
"""The fix of a package not found: give the folder holding it."""
FIXES = (PACKAGE_FOLDER,)
"""Every fix a front end words its own way."""


class UrdfgenpyError(Exception):
    """
    Base class of every error this package raises on purpose.

    ``fixes`` are the fixes its message says in the library's words, as data: a front end
    says each in its own (``report.FrontEnd.worded``).
    """

    fixes: tuple[Fix, ...] = ()

    def __init__(self, *args: object, fixes: tuple[Fix, ...] = ()) -> None:
        super().__init__(*args)
        if fixes:
            self.fixes = fixes


class InputError(UrdfgenpyError):
    """
    An input of the front door refused: ``where`` names it, ``what`` is wrong, ``fix``.

    ``where`` is ``source`` or ``args`` (the parameters of
    :func:`~urdfgenpy_ros.formats.open_description`); ``value`` is what was given. A
    front end says ``where`` in its own words (``--from``, ``parameter 'model'``).
    """

    def __init__(self, where: str, what: str, fix: str = '', value: str = '') -> None:
        self.where, self.what, self.fix, self.value = where, what, fix, value
        super().__init__(self.said(where))

    def said(self, name: str) -> str:
        """Return the message with the input called ``name``."""
        return f'{name}: {self.what}' + (f' ({self.fix})' if self.fix else '')


class ModelError(UrdfgenpyError, ValueError):
    """
    A value the model refuses, raised where it is made (a constructor, a loader, an edit).

    It is a ``ValueError`` too, so ``except ValueError`` keeps working.
    """


class ModelTypeError(UrdfgenpyError, TypeError):
    """An object of the wrong kind handed to the model (``add_link(joint)``)."""


class FrozenValueError(UrdfgenpyError, FrozenInstanceError):
    """
    A value object (an ``Origin``, a shape) changed in place: assign a new one instead.

    It is a ``dataclasses.FrozenInstanceError`` (an ``AttributeError``) too, as before.
    """


class SourceLocation(NamedTuple):
    """
    Where an element was read from: file, line, column and element path.

    ``via`` is, for an element of a Xacro expansion, the places that brought the text
    there (macro call and include sites, innermost first, and the properties an
    expression read), each with ``path`` saying what it is (``<xacro:arm>``).
    """

    file: str | None = None
    line: int | None = None
    column: int | None = None
    path: str | None = None
    via: tuple[SourceLocation, ...] = ()

    def __str__(self) -> str:
        """Return ``file:line:col`` when known, else the element path."""
        if self.line is not None:
            where = self.file or '<string>'
            column = self.column if self.column is not None else 1
            return f'{where}:{self.line}:{column}'
        return self.path or self.file or '<model>'


def _via(location: SourceLocation | None) -> str:
    """Return `` (via WHAT FILE:LINE, ...)``: what brought a Xacro element there, or ''."""
    if location is None or not location.via:
        return ''
    return ' (via ' + ', '.join(f'{place.path} {place}' for place in location.via) + ')'


class ParseError(UrdfgenpyError):
    """A description that cannot be read; the message is one line."""

    def __init__(self, message: str, location: SourceLocation | None = None,
                 code: str = 'P001', fixes: tuple[Fix, ...] = ()) -> None:
        self.location = location
        self.code = code
        self.message = message
        prefix = f'{location}: ' if location is not None else ''
        super().__init__(f'{prefix}error {code} {message}{_via(location)}', fixes=fixes)


class ReadWarning(NamedTuple):
    """Something a reader accepted but a strict parser would not (one line)."""

    location: SourceLocation
    code: str
    message: str

    def __str__(self) -> str:
        """Return ``file:line:col: warning CODE message``."""
        return f'{self.location}: warning {self.code} {self.message}'


class Severity(str, Enum):
    """How bad a finding is: errors break consumers, warnings are likely mistakes."""

    ERROR = 'error'
    WARNING = 'warning'

    def __str__(self) -> str:
        """Return the lower-case name."""
        return self.value


class ValidationError(UrdfgenpyError):
    """
    One finding of ``Robot.validate()``: a stable code, a severity and where it is.

    ``element`` names the element (``joint 'elbow'``), ``location`` gives file and line
    for a model read from a file or the element path for one built in Python, and
    ``hint`` says how to fix it. ``str()`` is one flake8-shaped line.
    """

    def __init__(self, code: str, severity: Severity, element: str,
                 location: SourceLocation, message: str, hint: str) -> None:
        self.code = code
        self.severity = Severity(severity)
        self.element = element
        self.location = location
        self.message = message
        self.hint = hint
        super().__init__(f'{location}: {self.severity} {code} {element}: {message} ({hint})'
                         f'{_via(location)}')

    def as_dict(self) -> dict[str, object]:
        """Return the finding as plain data (for JSON output)."""
        return {'code': self.code, 'severity': str(self.severity), 'element': self.element,
                'file': self.location.file, 'line': self.location.line,
                'column': self.location.column, 'path': self.location.path,
                'via': [{'file': place.file, 'line': place.line, 'column': place.column,
                         'what': place.path} for place in self.location.via],
                'message': self.message, 'hint': self.hint}


class MissingDependencyError(UrdfgenpyError):
    """An optional dependency a feature needs is not installed."""

    def __init__(self, module: str, extra: str, feature: str) -> None:
        super().__init__(
            f'{feature} needs the Python package {module!r}: '
            f"pip install 'urdfgenpy_ros[{extra}]'")
