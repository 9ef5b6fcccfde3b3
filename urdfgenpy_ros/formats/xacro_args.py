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
A Xacro argument given that no file declares or uses: a misspelling xacro ignores silently.

``usesim:=true`` for ``<xacro:arg name="use_sim"/>`` expands with the default; the reader
warns (X103), naming the arguments the files declare and the closest one.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
import difflib
from pathlib import Path
import re

from urdfgenpy_ros.model.errors import ReadWarning, SourceLocation

_DECLARED = re.compile(r'<[\w.-]+:arg\s[^>]*?\bname\s*=\s*["\']([^"\']+)')
_USED = re.compile(r'\$\(\s*arg\s+([^\s)]+)')


def unknown_arguments(files: Iterable[str], mappings: Mapping[str, str],
                      top: str) -> list[ReadWarning]:
    """Return an X103 warning per argument in ``mappings`` no file declares or uses."""
    return [ReadWarning(SourceLocation(top), 'X103',
                        f'xacro argument {argument!r} is not declared, so xacro ignores it'
                        f'{f": did you mean {close!r}?" if close else ""} '
                        f'(the files declare: {", ".join(declared) or "none"})')
            for argument, close, declared in _undeclared(files, mappings)]


def misspelt_arguments(files: Iterable[str], mappings: Mapping[str, str]) -> str:
    """
    Return what to add to a failed expansion's line about misspelt arguments, or ''.

    It names each given argument no file read declares and the declared one it is close
    to: a misspelling the failure may come from.
    """
    readable = [name for name in files if Path(name).is_file()]  # not the one it missed
    said = [f'{argument!r} is not declared by the files read: did you mean {close!r}?'
            for argument, close, _ in _undeclared(readable, mappings) if close]
    return f' (xacro argument {"; ".join(said)})' if said else ''


def _undeclared(files: Iterable[str], mappings: Mapping[str, str]
                ) -> list[tuple[str, str, list[str]]]:
    """Return each argument no file declares or uses, its closest declared one, all declared."""
    declared: list[str] = []
    used: set[str] = set()
    for name in files:
        try:
            text = Path(name).read_text(encoding='utf-8', errors='replace')
        except OSError:
            return []  # cannot tell: say nothing rather than something wrong
        declared += [found for found in _DECLARED.findall(text) if found not in declared]
        used.update(_USED.findall(text))
    found = []
    for argument in mappings:
        if argument not in declared and argument not in used:
            close = difflib.get_close_matches(argument, declared, n=1)
            found.append((argument, close[0] if close else '', declared))
    return found
