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

from urdfgenpy_ros.errors import ReadWarning, SourceLocation

_DECLARED = re.compile(r'<[\w.-]+:arg\s[^>]*?\bname\s*=\s*["\']([^"\']+)')
_USED = re.compile(r'\$\(\s*arg\s+([^\s)]+)')


def unknown_arguments(files: Iterable[str], mappings: Mapping[str, str],
                      top: str) -> list[ReadWarning]:
    """Return an X103 warning per argument in ``mappings`` no file declares or uses."""
    declared: list[str] = []
    used: set[str] = set()
    for name in files:
        try:
            text = Path(name).read_text(encoding='utf-8', errors='replace')
        except OSError:
            return []  # cannot tell: say nothing rather than something wrong
        declared += [found for found in _DECLARED.findall(text) if found not in declared]
        used.update(_USED.findall(text))
    warnings = []
    for argument in mappings:
        if argument in declared or argument in used:
            continue
        close = difflib.get_close_matches(argument, declared, n=1)
        guess = f': did you mean {close[0]!r}?' if close else ''
        known = ', '.join(declared) if declared else 'none'
        warnings.append(ReadWarning(
            SourceLocation(top), 'X103',
            f'xacro argument {argument!r} is not declared, so xacro ignores it{guess} '
            f'(the files declare: {known})'))
    return warnings
