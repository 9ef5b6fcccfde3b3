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
A format's writer options, each declared once.

An :class:`Option` names the writer's Python keyword and ``urdfgenpy convert``'s flag:
``formats.save`` checks keywords against the Python side, and the CLI makes its click
options from the flag side, so neither repeats the other. Only ``cli/`` turns an option
into click's (the library does not import click).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, TYPE_CHECKING

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel


@dataclass(frozen=True)
class Option:
    """
    One writer option: its Python keyword, its ``convert`` flag and how the flag is given.

    ``keyword`` is None for a flag of ``convert`` only, ``flag`` None for a keyword of
    Python only; ``help_text`` is the flag's help. ``choices``, ``is_flag``, ``multiple``,
    ``file`` (an existing file), ``metavar`` and ``default`` say how the flag is written;
    ``parse`` turns its words into the value (a ``ModelError`` refuses them). ``rank``
    orders ``convert --help`` (its own options rank 50). ``also`` names other formats
    whose output takes the flag too, and a ``transform`` is applied by ``convert`` to the
    robot before writing (the changes it returns are said) instead of being passed to
    the writer.
    """

    keyword: str | None
    flag: str | None = None
    help_text: str = ''
    choices: tuple[str, ...] = ()
    is_flag: bool = False
    multiple: bool = False
    file: bool = False
    metavar: str | None = None
    default: Any = None
    parse: Callable[[tuple[str, ...]], Any] | None = None
    rank: int = 100
    also: tuple[str, ...] = ()
    transform: Callable[[RobotModel, Any], tuple[RobotModel, list[Any]]] | None = None

    @property
    def name(self) -> str:
        """Return the name of the flag's value (``--sdf-version``: ``sdf_version``)."""
        if self.flag is None:
            return self.keyword or ''
        return self.flag.lstrip('-').replace('-', '_')

    def given(self, value: Any) -> bool:
        """Return whether ``value`` of the flag asks for something (not its default)."""
        return value != self.default and value not in (None, False, ())


def keywords(options: tuple[Option, ...]) -> tuple[str, ...]:
    """Return the Python keywords of ``options``, in their declared order."""
    return tuple(option.keyword for option in options if option.keyword is not None)
