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


"""Warnings that point at the user's line, however deep in the package they are raised."""

from __future__ import annotations

from pathlib import Path
import sys
from types import FrameType
import warnings

PACKAGE = str(Path(__file__).resolve().parent)


def warn_caller(message: str) -> None:
    """Issue ``message`` as a ``UserWarning`` at the first caller outside this package."""
    level = 2  # the frame that called this function
    frame: FrameType | None = sys._getframe(1)
    while frame is not None and str(Path(frame.f_code.co_filename).resolve()).startswith(
            PACKAGE):
        level, frame = level + 1, frame.f_back
    warnings.warn(message, stacklevel=level)
