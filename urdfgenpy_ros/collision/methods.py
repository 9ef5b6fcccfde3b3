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
The ways to make a collision light: hull, decompose, primitive, decimate, and auto.

Each method takes a closed solid (a trimesh mesh in the frame of the scaled source mesh)
and returns the parts that replace it. ``auto`` tries them lightest first and keeps the
first whose intersection over union reaches ``min_iou``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from urdfgenpy_ros.collision.parts import mesh_part, Part
from urdfgenpy_ros.model.errors import MissingDependencyError

METHODS = ('hull', 'decompose', 'primitive', 'decimate', 'auto')
LIGHTEST_FIRST = ('primitive', 'hull', 'decompose', 'decimate')
"""The order ``auto`` tries the methods in: fewest contacts and faces first."""
DEFAULT_MIN_IOU = 0.9  # what auto keeps when no --min-iou is given
_FEWEST_VERTICES = 16  # a convex part of CoACD has at least this many, whatever the budget
_TIE = 0.005  # primitives this close in IoU fit equally: the lighter one is kept


@dataclass(frozen=True)
class Options:
    """What the methods are told: budgets, CoACD's settings, the seed."""

    max_faces: int = 2000  # decimate's budget, and decompose's before CoACD
    max_hulls: int = 16  # decompose: at most this many convex parts
    threshold: float = 0.05  # decompose: CoACD's concavity threshold
    seed: int = 0
    split: bool = False  # primitive: one per convex part of a decomposition
    hulls: bool = False  # the consumer collides with each mesh's hull (MuJoCo): measure so

    def key(self, method: str) -> tuple:
        """Return the options that change ``method``'s result (for the cache)."""
        measured = ('hulls',) if self.hulls else ()
        if method == 'decimate':
            return (self.max_faces, *measured)
        if method == 'decompose':
            return (self.max_faces, self.max_hulls, self.threshold, self.seed, *measured)
        if method == 'primitive' and self.split:
            return (self.max_faces, self.max_hulls, self.threshold, self.seed, True, *measured)
        return measured


def hull(solid: Any, options: Options) -> list[Part]:
    """Return the convex hull of the solid: one part."""
    return [mesh_part(solid.convex_hull)]


def decompose(solid: Any, options: Options) -> list[Part]:
    """
    Return CoACD's convex parts of the solid (decimated first when large; seeded).

    Each part has at most :func:`part_vertices` vertices, so the parts stay light.
    """
    try:
        import coacd
    except ImportError:
        raise MissingDependencyError('coacd', 'collision',
                                     'Convex decomposition (method decompose)') from None
    import trimesh
    coacd.set_log_level('error')
    source = decimated(solid, options.max_faces * 10)
    pieces = coacd.run_coacd(coacd.Mesh(source.vertices, source.faces),
                             threshold=options.threshold, max_convex_hull=options.max_hulls,
                             seed=options.seed, decimate=True,
                             max_ch_vertex=part_vertices(options))
    parts = []
    for vertices, faces in pieces:
        piece = trimesh.Trimesh(vertices, faces).convex_hull  # closed, outward, convex
        if piece.volume > 0:
            parts.append(mesh_part(piece))
    return parts or hull(solid, options)


def part_vertices(options: Options) -> int:
    """
    Return CoACD's vertex limit per convex part: the parts share ``max_faces`` between them.

    A convex hull of V vertices has at most 2V - 4 triangles.
    """
    return max(_FEWEST_VERTICES, options.max_faces // (2 * max(options.max_hulls, 1)) + 2)


AGGRESSION = 3
"""fast-simplification's aggressiveness: its default, 7, moves CAD surfaces 1.5-3x as far
(SO-101's parts at 2,000 faces: 1.0-4.4% of the diagonal against 0.3-2.6%)."""


def decimated(solid: Any, budget: int) -> Any:
    """Return the solid with at most ``budget`` faces (itself when it has no more)."""
    if len(solid.faces) <= budget:
        return solid
    try:
        import fast_simplification
    except ImportError:
        raise MissingDependencyError('fast_simplification', 'collision',
                                     'Decimating meshes (method decimate)') from None
    import trimesh
    reduction = 1.0 - budget / len(solid.faces)
    vertices, faces = fast_simplification.simplify(solid.vertices, solid.faces,
                                                   target_reduction=reduction, agg=AGGRESSION)
    made = trimesh.Trimesh(vertices, faces)
    while budget < len(made.faces) < len(solid.faces):  # it stops a little above at times
        solid, reduction = made, 1.0 - budget / len(made.faces)
        vertices, faces = fast_simplification.simplify(made.vertices, made.faces,
                                                       target_reduction=reduction,
                                                       agg=AGGRESSION)
        made = trimesh.Trimesh(vertices, faces)
    return made


def decimate(solid: Any, options: Options) -> list[Part]:
    """Return the solid decimated to ``max_faces`` triangles: one part."""
    return [mesh_part(decimated(solid, options.max_faces))]


def primitive(solid: Any, options: Options) -> list[Part]:
    """
    Return the enclosing primitive with the highest IoU: one part.

    With ``options.split``, one such primitive for each convex part of the decomposition.
    """
    if options.split:
        return [_best_primitive(piece.solid()) for piece in decompose(solid, options)]
    return [_best_primitive(solid)]


def _best_primitive(solid: Any) -> Part:
    """Return the lightest of the enclosing primitives that fit ``solid`` best."""
    from urdfgenpy_ros.collision.measure import measure
    from urdfgenpy_ros.collision.primitives import candidates
    scored = [(measure(solid, [part]).iou, part) for part in candidates(solid)]
    best = max(iou for iou, _ in scored)
    return next(part for iou, part in scored if iou >= best - _TIE)


RUN: dict[str, Callable[[Any, Options], list[Part]]] = {
    'hull': hull, 'decompose': decompose, 'primitive': primitive, 'decimate': decimate}
