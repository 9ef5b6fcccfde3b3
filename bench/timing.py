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

"""Timing shared by the benchmarks."""

from __future__ import annotations

from collections.abc import Callable
import gc
import statistics
import time
from typing import Any


def median_seconds(function: Callable[[], Any], repeat: int,
                   clock: Callable[[], float] = time.perf_counter) -> float:
    """
    Return the median time of ``repeat`` calls of ``function`` (GC run before each).

    ``clock`` is wall time; ``time.process_time`` gives the CPU time of this process (time
    spent waiting for a core is not counted).
    """
    times = []
    for _ in range(repeat):
        gc.collect()
        start = clock()
        function()
        times.append(clock() - start)
    return statistics.median(times)


def p90(values: list[float]) -> float:
    """Return the 90th percentile of ``values`` (the nearest rank, no interpolation)."""
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(0.9 * (len(ordered) - 1)))]
