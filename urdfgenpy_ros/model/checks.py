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
Argument checks run when model elements are built in Python.

Readers turn them off with :class:`unchecked`, so that a faulty file still loads and
``validate()`` can report every problem with its line instead of stopping at the first.
"""

from __future__ import annotations

from collections.abc import Sequence
from contextvars import ContextVar
import math

from urdfgenpy_ros.model.errors import ModelError

_ENABLED: ContextVar[bool] = ContextVar('urdfgenpy_checks', default=True)

Vec3 = tuple[float, float, float]


def enabled() -> bool:
    """Return whether construction checks are active in this context."""
    return _ENABLED.get()


is_on = _ENABLED.get
"""The same as :func:`enabled`, without a Python call (constructors' fast paths use it)."""


class unchecked:  # noqa: N801 - used as a function: ``with checks.unchecked():``
    """Build elements without raising on bad values (readers use this)."""

    __slots__ = ('_token',)

    def __enter__(self) -> None:
        """Turn the checks off in this context."""
        self._token = _ENABLED.set(False)

    def __exit__(self, *exc: object) -> None:
        """Turn them back to what they were."""
        _ENABLED.reset(self._token)


def to_float(owner: str, field: str, value: object) -> float:
    """Coerce ``value`` to float, or raise a ValueError naming the field."""
    try:
        return float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ModelError(f'{owner}: {field} must be a number, got {value!r}') from None


def finite(owner: str, field: str, value: object) -> float:
    """Return ``value`` as a finite float; raise ValueError when checks are on."""
    number = to_float(owner, field, value)
    if number - number != 0.0 and _ENABLED.get():  # only inf and nan fail this
        raise ModelError(f'{owner}: {field} must be finite, got {number!r}')
    return number


def positive(owner: str, field: str, value: object, unit: str = 'm') -> float:
    """Return ``value`` as a float > 0 (a size); raise ValueError when checks are on."""
    number = to_float(owner, field, value)
    if not 0.0 < number < _INF and _ENABLED.get():
        raise ModelError(
            f'{owner}: {field} must be a positive finite number of {unit}, got {number!r}')
    return number


def non_negative(owner: str, field: str, value: object, unit: str) -> float:
    """Return ``value`` as a float >= 0 (a mass, an effort); raise ValueError if checked."""
    number = to_float(owner, field, value)
    if not 0.0 <= number < _INF and _ENABLED.get():
        raise ModelError(
            f'{owner}: {field} must be a finite number >= 0 {unit}, got {number!r}')
    return number


def numbers(owner: str, names: tuple[str, ...], values: tuple,
            minimum: float | None = None, strict: bool = False) -> tuple[float, ...]:
    """
    Return ``values`` as finite floats, each > or >= ``minimum`` when one is given.

    One pass over the values in the common case; the field-by-field check that names the
    culprit in the ValueError runs only when something is wrong and checks are on.
    """
    try:
        result = tuple([float(value) for value in values])
    except (TypeError, ValueError):
        result = tuple(to_float(owner, field, value) for field, value in zip(names, values))
    total = sum(result)
    good = total - total == 0.0
    if good and minimum is not None:
        least = min(result)
        good = least > minimum if strict else least >= minimum
    if not good and _ENABLED.get():
        for field, number in zip(names, result):
            if minimum is None:
                finite(owner, field, number)
            elif strict and minimum == 0.0:
                positive(owner, field, number)
            else:
                non_negative(owner, field, number, '')
    return result


def are_finite_floats(*values: object) -> bool:
    """Return True when every value already is a finite float (the fast path)."""
    for value in values:
        if type(value) is not float or value - value != 0.0:
            return False
    return True


def floats3(value: object) -> Vec3 | None:
    """
    Return ``value`` as a 3-tuple of floats when it is a tuple of 3 finite ints or floats.

    The constructors' fast path: None means "not that simple", and the caller then runs
    :func:`vec3`, which converts what it can and names the field in its error. A vector
    with ints in it (``axis=(0, 0, 1)``, ``xyz=(0, 0, 0.2)``) is converted once and the float
    tuple shared (it is immutable); one with a float zero is not, so that -0.0 stays -0.0.
    """
    if type(value) is not tuple or len(value) != 3:
        return None
    x, y, z = value
    if type(x) is float and type(y) is float and type(z) is float:
        total = x + y + z
        return value if total - total == 0.0 else None
    if type(x) not in _REAL or type(y) not in _REAL or type(z) not in _REAL:
        return None
    exact = (type(x) is int or x) and (type(y) is int or y) and (type(z) is int or z)
    if exact:  # no float zero: equal keys convert to equal floats, sign included
        shared = _MIXED.get(value)
        if shared is not None:
            return shared
    result = x, y, z = (float(x), float(y), float(z))
    total = x + y + z
    if total - total != 0.0:
        return None
    if exact and len(_MIXED) < 1024:
        _MIXED[value] = result
    return result


def vec3(owner: str, field: str, value: Sequence[object]) -> Vec3:
    """Return a 3-vector of finite floats; raise ValueError when malformed."""
    try:
        x, y, z = value
        if type(value) is tuple and type(x) is float and type(y) is float and type(z) is float:
            result = value
        else:
            result = (float(x), float(y), float(z))  # type: ignore[arg-type]
    except (TypeError, ValueError):
        if isinstance(value, Sequence) and len(value) == 3:
            return numbers(owner, (field,) * 3, tuple(value))  # type: ignore[return-value]
        raise ModelError(
            f'{owner}: {field} must have 3 numbers (x, y, z), got {value!r}') from None
    total = result[0] + result[1] + result[2]
    if total - total != 0.0:
        return numbers(owner, (field,) * 3, result)  # type: ignore[return-value]
    return result


def name(owner: str, value: object) -> str:
    """Return a non-empty string name or raise ValueError."""
    if (type(value) is not str or not value or value.isspace()) and _ENABLED.get():
        raise ModelError(f'{owner}: name must be a non-empty string, got {value!r}')
    return value  # type: ignore[return-value]


_INF = math.inf
_REAL = (float, int)
_MIXED: dict[tuple[float, float, float], Vec3] = {}  # vectors with ints, converted
