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
One collision mesh made light: loaded, closed, simplified and measured, through the cache.

``auto`` tries the methods lightest first (:data:`methods.LIGHTEST_FIRST`) and keeps the
first whose intersection over union reaches ``min_iou`` (when decompose does, decimate is
tried too and the one with fewer faces kept); when none does, the one that comes closest,
which the caller says or refuses with its numbers.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.collision import cache
from urdfgenpy_ros.collision.measure import closed_solid, measure, Measures
from urdfgenpy_ros.collision.methods import DEFAULT_MIN_IOU, LIGHTEST_FIRST, Options, RUN
from urdfgenpy_ros.collision.parts import Part
from urdfgenpy_ros.model.errors import ModelError

if TYPE_CHECKING:
    from urdfgenpy_ros.model.inertial import Inertial


@dataclass(frozen=True)
class Simplified:
    """The parts that replace one collision mesh, by which method, and what they lose."""

    method: str
    parts: list[Part]
    measures: Measures
    repairs: list[str]


def load_solid(path: Path, scale: tuple[float, float, float]) -> Any:
    """Return the mesh file at ``path`` as one trimesh mesh, scaled."""
    import numpy
    import trimesh
    try:
        loaded = trimesh.load(str(path), force='mesh')
    except Exception as error:  # noqa: BLE001 (each reader raises its own kind)
        raise ModelError(f'{path}: trimesh cannot read it ({error}); convert it to STL or '
                         'OBJ') from None
    if not hasattr(loaded, 'faces') or len(loaded.faces) == 0:
        raise ModelError(f'{path}: no triangles in it (an empty or point mesh): give the '
                         'link a mesh with faces, or a primitive collision')
    if scale != (1.0, 1.0, 1.0):
        loaded.apply_transform(numpy.diag([*scale, 1.0]))
    return loaded


def simplify(path: Path, scale: tuple[float, float, float], method: str, options: Options,
             inertial: Inertial | None = None, min_iou: float | None = None) -> Simplified:
    """Return ``method``'s result for the mesh file at ``path`` (from the cache if there)."""
    data = path.read_bytes()
    tensor = () if inertial is None else (inertial.mass, inertial.ixx, inertial.ixy,
                                          inertial.ixz, inertial.iyy, inertial.iyz,
                                          inertial.izz)
    solid: list[Any] = []  # loaded once, and only when something is not cached

    def run(name: str) -> Simplified:
        entry = cache.key(data, scale, name, options.key(name), (path.suffix.lower(), tensor))
        found = cache.load(entry)
        if found is not None:
            return Simplified(name, *found)
        if not solid:
            solid.extend(closed_solid(load_solid(path, scale), str(path)))
        parts = RUN[name](solid[0], options)
        measures = measure(solid[0], parts, inertial, options.hulls)
        result = Simplified(name, parts, measures, list(solid[1]))
        cache.store(entry, result.parts, result.measures, result.repairs)
        return result

    if method != 'auto':
        return run(method)
    floor = DEFAULT_MIN_IOU if min_iou is None else min_iou
    tried = []
    for name in LIGHTEST_FIRST:
        tried.append(run(name))
        if tried[-1].measures.iou >= floor and name != 'decompose':
            break  # decompose can be heavier than decimate: both are weighed
    reaching = [result for result in tried if result.measures.iou >= floor]
    if reaching:
        return min(reaching, key=lambda result: result.measures.faces_after)
    return max(tried, key=lambda result: result.measures.iou)
