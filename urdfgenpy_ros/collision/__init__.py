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

from urdfgenpy_ros.collision.apply import plan_collisions, simplify_collisions
from urdfgenpy_ros.collision.findings import CollisionRefusedError, CollisionReport
from urdfgenpy_ros.collision.methods import METHODS, Options

__all__ = ['CollisionRefusedError', 'CollisionReport', 'METHODS', 'Options',
           'plan_collisions', 'simplify_collisions']
