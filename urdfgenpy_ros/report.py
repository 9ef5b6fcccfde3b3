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
The one error boundary of every front end: the CLI, the node, init and ``ros2 pkg scaffold``.

A known error (this package's own, or the operating system refusing a file) is something
the user can fix: it is shown as one line and the program exits with a documented status.
Anything else is a bug in this package and keeps its traceback.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
import sys
import traceback

from urdfgenpy_ros.errors import UrdfgenpyError

EXIT_KNOWN_ERROR = 2
"""Exit status of the command-line tools for a known error (the node exits 1)."""

KNOWN_ERRORS = (UrdfgenpyError, OSError)


def counted(count: int, noun: str) -> str:
    """Return ``1 joint`` or ``2 joints``: a count with its noun in the right number."""
    return f'{count} {noun}' if count == 1 else f'{count} {noun}s'


def one_line(error: BaseException) -> str:
    """Return the line a user sees for a known error."""
    if isinstance(error, OSError) and error.filename is not None:
        return f'{error.filename}: {error.strerror or error}'
    return ' '.join(str(error).split()) or type(error).__name__


def _to_stderr(line: str) -> None:
    print(line, file=sys.stderr)


@contextmanager
def known_errors_as_one_line(prefix: str = '', exit_code: int = EXIT_KNOWN_ERROR,
                             say: Callable[[str], None] = _to_stderr,
                             verbose: Callable[[], bool] = lambda: False) -> Iterator[None]:
    """
    Turn a known error inside the block into one line (via ``say``) and ``SystemExit``.

    When ``verbose()`` is true the traceback is printed too. Other exceptions pass unchanged.
    """
    try:
        yield
    except KNOWN_ERRORS as error:
        if verbose():
            traceback.print_exc()
        say(f'{prefix}{one_line(error)}')
        raise SystemExit(exit_code) from None
