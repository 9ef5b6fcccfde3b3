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
The one error boundary of every front end: the CLI, ``init``, the node and the viewer.

``ros2 pkg scaffold`` is ``init``'s command. A user's mistake (this package's own errors,
the operating system refusing one of their files, a front end's usage errors such as
click's) is something the user can fix: it is shown as one line, ``prog: file:line:
element: message (fix)``, and the program exits with its documented status (2; the node
1). Anything else is a bug in this package and keeps its traceback. The library says a
fix in its own words, declared as data (:class:`~urdfgenpy_ros.model.errors.Fix`); each front
end words it with its own option (``-p/--package-path``, the node's parameter).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field
import sys

from urdfgenpy_ros.model.errors import Fix, FIXES, InputError, UrdfgenpyError

EXIT_KNOWN_ERROR = 2
"""Exit status of the command-line tools for a user's mistake (the node exits 1)."""

KNOWN_ERRORS: tuple[type[BaseException], ...] = (UrdfgenpyError, OSError)
"""The user's mistakes every front end knows: this package's errors, and OSError."""


def _to_stderr(line: str) -> None:
    print(line, file=sys.stderr)


@dataclass(frozen=True)
class FrontEnd:
    """
    How one front end says a user's mistake: ``prog: line`` through ``say``, then exit.

    ``prog`` leads the line (None: the logger names the program already); ``usage_errors``
    are the front end's own user-error types (click's UsageError); ``package_paths`` is how
    it names the folders ``$(find pkg)`` and ``package://`` resolve through (in the fix
    ``pass its folder ...``); ``verbose()`` true prints the traceback too. ``inputs`` are
    its names for the inputs of the front door (``source``, ``args``: its options or
    parameters). A fix is found in a line by its library words, so a message that wraps
    another's (an assembly's part, a Xacro include) is worded too.
    """

    prog: str | None
    exit_code: int = EXIT_KNOWN_ERROR
    say: Callable[[str], None] = _to_stderr
    package_paths: str = 'in search_paths / --package-path'
    verbose: Callable[[], bool] = lambda: False
    usage_errors: tuple[type[BaseException], ...] = ()
    inputs: Mapping[str, str] = field(default_factory=dict, hash=False)

    def line(self, error: BaseException) -> str:
        """Return the one line saying ``error``."""
        said = self.said(error)
        return f'{self.prog}: {said}' if self.prog else said

    def said(self, error: BaseException) -> str:
        """Return ``error``'s message in this front end's words, on one line."""
        if isinstance(error, InputError) and error.where in self.inputs:
            return self.worded(' '.join(error.said(self.inputs[error.where]).split()))
        return self.worded(one_line(error))

    def worded(self, text: str) -> str:
        """Return ``text`` (a message, a finding, a report) with each fix in its words."""
        for fix in FIXES:
            if fix.text in text:
                text = text.replace(fix.text, self.fix(fix))
        return text

    def fix(self, fix: Fix) -> str:
        """Return ``fix`` in this front end's words."""
        if fix.names == 'package_paths':
            return f'pass its folder {self.package_paths}'
        return fix.text


LIBRARY = FrontEnd(None)
"""Python callers: no boundary, the library's own words."""


def counted(count: int, noun: str) -> str:
    """Return ``1 joint`` or ``2 joints``: a count with its noun in the right number."""
    return f'{count} {noun}' if count == 1 else f'{count} {noun}s'


def one_line(error: BaseException) -> str:
    """Return the line a user sees for a known error."""
    if isinstance(error, OSError) and error.filename is not None:
        return f'{error.filename}: {error.strerror or error}'
    said = getattr(error, 'format_message', None)  # click's, with the option it names
    text = said() if callable(said) else str(error)
    return ' '.join(text.split()) or type(error).__name__


@contextmanager
def boundary(front_end: FrontEnd) -> Iterator[None]:
    """
    Say a user's mistake inside the block in one line and raise ``SystemExit``.

    The lines an error carries in ``lines`` (the findings behind a refusal) come first.
    Any other exception, a bug, passes unchanged with its traceback.
    """
    try:
        yield
    except (*KNOWN_ERRORS, *front_end.usage_errors) as error:
        if front_end.verbose():
            import traceback  # only with --verbose (start-up)
            traceback.print_exc()
        for line in getattr(error, 'lines', ()):
            front_end.say(front_end.worded(str(line)))
        front_end.say(front_end.line(error))
        raise SystemExit(front_end.exit_code) from None


def exit_status(front_end: FrontEnd, body: Callable[[], int | None]) -> int:
    """Run ``body`` inside the boundary; return its status, or the front end's on a mistake."""
    try:
        with boundary(front_end):
            return body() or 0
    except SystemExit as stop:  # the boundary's, or argparse's (--help: 0)
        return 0 if stop.code is None else stop.code if isinstance(stop.code, int) \
            else front_end.exit_code
