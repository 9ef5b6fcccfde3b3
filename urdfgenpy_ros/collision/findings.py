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
What a run says: one line per collision in ``check``'s format, and a table in JSON.

K911 is each simplified collision's measures; K912 one below ``min_iou``, which refuses
the run; K913 a mesh trimesh repaired before it was measured; K914 a mesh it could not
close, whose collision is left as it was.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from urdfgenpy_ros.collision.measure import Measures
from urdfgenpy_ros.collision.methods import DEFAULT_MIN_IOU
from urdfgenpy_ros.model.errors import ModelError, Severity, SourceLocation, ValidationError

HINTS = {
    'K911': 'a lighter collision loses shape; pick another method if this is too much',
    'K912': 'pick a method that keeps more (decompose, decimate), or lower --min-iou',
    'K913': 'the measures are against the repaired solid; close the mesh to be sure',
    'K914': 'the collision is left as it was',
}


@dataclass
class LinkResult:
    """One collision mesh made light: where it was, by which method, what it lost."""

    link: str
    index: int
    method: str
    measures: Measures
    repairs: list[str]
    location: SourceLocation
    source: str  # the mesh URI as written
    budget: int | None = None  # decimate's face budget

    def line(self) -> str:
        """Return the measures in words."""
        m = self.measures
        shape = (f'IoU {m.iou:.3f}, coverage {m.coverage:.3f}, excess volume {m.excess:.1%}'
                 if m.how != 'none' else 'IoU and coverage not measured (a shape has no '
                 'volume)')
        if m.how == 'sampled':
            shape += ' (sampled with points: a mesh is no valid manifold solid)'
        text = (f'{self.method}: {shape}, faces {m.faces_before} -> {m.faces_after} '
                f"({m.parts} part{'s' if m.parts != 1 else ''})")
        if self.budget is not None and m.faces_after > self.budget:
            text += (f', above the budget of {self.budget} faces (fast-simplification '
                     "stops where the mesh's edges let it collapse no more)")
        if m.inertia_change is not None:
            text += (f'; the inertia came from this mesh and would change by '
                     f'{m.inertia_change:.1%} if computed from the new shape')
        return text


@dataclass
class CollisionReport:
    """Every collision a run made light, and the meshes it could not measure."""

    method: str
    min_iou: float | None = None
    results: list[LinkResult] = field(default_factory=list)
    unclosed: list[tuple[str, SourceLocation, str]] = field(default_factory=list)
    files: list[Path] = field(default_factory=list)

    @property
    def floor(self) -> float | None:
        """Return the IoU floor the run used: ``min_iou``, or auto's default."""
        if self.min_iou is None and self.method == 'auto':
            return DEFAULT_MIN_IOU
        return self.min_iou

    def _short(self, result: LinkResult) -> bool:
        """Return whether auto kept ``result`` although no method reached its floor."""
        floor = self.floor
        return (self.method == 'auto' and floor is not None and result.measures.how != 'none'
                and result.measures.iou < floor)

    def below(self) -> list[LinkResult]:
        """Return the results under ``min_iou``."""
        if self.min_iou is None:
            return []
        return [result for result in self.results
                if result.measures.how != 'none' and result.measures.iou < self.min_iou]

    def findings(self) -> list[ValidationError]:
        """Return one finding per collision, in ``check``'s format."""
        low = {id(result) for result in self.below()}
        found = []
        for result in self.results:
            element = f'link {result.link!r}'
            if id(result) in low:
                found.append(ValidationError(
                    'K912', Severity.ERROR, element, result.location,
                    f'{result.line()}: IoU below --min-iou {self.min_iou}', HINTS['K912']))
            else:
                text = result.line()
                if self._short(result):
                    text = (f'auto: no method reaches IoU {self.floor} (the floor; set it with '
                            f'--min-iou), the best is {text}')
                found.append(ValidationError('K911', Severity.WARNING, element,
                                             result.location, text, HINTS['K911']))
            if result.repairs:
                found.append(ValidationError('K913', Severity.WARNING, element,
                                             result.location, '; '.join(result.repairs),
                                             HINTS['K913']))
        for link, location, message in self.unclosed:
            found.append(ValidationError('K914', Severity.WARNING, f'link {link!r}', location,
                                         message, HINTS['K914']))
        return found

    def lines(self) -> list[str]:
        """Return the findings as text lines."""
        return [str(finding) for finding in self.findings()]

    def table(self) -> list[dict[str, object]]:
        """Return one row per collision: link, method, source, measures (for JSON)."""
        return [{'link': result.link, 'collision': result.index, 'method': result.method,
                 'source': result.source, 'file': result.location.file,
                 'line': result.location.line, **result.measures.as_dict(),
                 'repairs': result.repairs,
                 'below_min_iou': result in self.below()} for result in self.results]

    def refuse_below(self) -> None:
        """Raise, with the numbers, when a collision is under ``min_iou``."""
        low = self.below()
        if low:
            worst = min(low, key=lambda result: result.measures.iou)
            raise CollisionRefusedError(
                f'{len(low)} collision(s) below min_iou {self.min_iou}, e.g. link '
                f'{worst.link!r}: {worst.line()} (pick another method or lower min_iou; '
                'nothing was written)', self)


class CollisionRefusedError(ModelError):
    """A run refused: some collision would lose more than ``min_iou`` allows."""

    def __init__(self, message: str, report: CollisionReport) -> None:
        super().__init__(message)
        self.report = report
