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

"""Named colours and textures that visuals refer to."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, KW_ONLY
import math

from urdfgenpy_ros.model import checks
from urdfgenpy_ros.model.errors import ModelError, SourceLocation
from urdfgenpy_ros.model.preserved import Preserved

Rgba = tuple[float, float, float, float]


def _rgba(name: str, value: Sequence[object]) -> Rgba:
    owner = f'material {name!r}'
    if len(value) != 4:
        raise ModelError(f'{owner}: rgba must have 4 numbers (red, green, blue, alpha), '
                         f'got {tuple(value)!r}')
    rgba = tuple(checks.to_float(owner, 'rgba', v) for v in value)
    if checks.enabled() and not all(math.isfinite(v) and 0.0 <= v <= 1.0 for v in rgba):
        raise ModelError(f'{owner}: rgba components run from 0 to 1, got {rgba!r} '
                         '(divide 0-255 values by 255)')
    return rgba  # type: ignore[return-value]


@dataclass(slots=True, frozen=True)
class Material:
    """
    A material: a name with a colour (``rgba``, each 0..1), a texture, or both.

    A material with neither refers to a robot-level material of the same name.
    """

    name: str
    rgba: Rgba | None = None
    texture: str | None = None
    _: KW_ONLY
    source: SourceLocation | None = field(default=None, compare=False, repr=False)
    extras: Preserved | None = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        """Check the name and coerce the colour."""
        checks.name('material', self.name)
        if self.rgba is not None:
            object.__setattr__(self, 'rgba', _rgba(self.name, self.rgba))

    @property
    def is_reference(self) -> bool:
        """Return whether this only names a material defined elsewhere."""
        return self.rgba is None and self.texture is None
