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
Sim-ready collision geometry: each link's collision meshes made light, and measured.

``simplify_collisions(robot, method, links, **options)`` (:mod:`.apply`) runs one of
:data:`METHODS` (:mod:`.methods`) on every chosen collision mesh, measures what it loses
against the original solid (:mod:`.measure`), caches the result by content
(:mod:`.cache`) and replaces the collisions, and only them; :mod:`.findings` says it.
"""

from importlib import import_module
from typing import Any, TYPE_CHECKING

if TYPE_CHECKING:
    from urdfgenpy_ros.collision.apply import plan_collisions, simplify_collisions
    from urdfgenpy_ros.collision.findings import CollisionRefusedError, CollisionReport
    from urdfgenpy_ros.collision.methods import METHODS, Options

_WHERE = {'plan_collisions': 'apply', 'simplify_collisions': 'apply',
          'CollisionRefusedError': 'findings', 'CollisionReport': 'findings',
          'METHODS': 'methods', 'Options': 'methods'}
"""Each public name's module: imported on first use (the command line starts faster)."""


def __getattr__(name: str) -> Any:
    """Return a public name, importing its module on first use."""
    if name in _WHERE:
        return getattr(import_module(f'urdfgenpy_ros.collision.{_WHERE[name]}'), name)
    raise AttributeError(f'module {__name__!r} has no attribute {name!r}')


__all__ = ['CollisionRefusedError', 'CollisionReport', 'METHODS', 'Options',
           'plan_collisions', 'simplify_collisions']
