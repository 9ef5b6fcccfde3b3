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

"""How the ``urdfgenpy`` command says a user's mistake and a fix: its options' names."""

from __future__ import annotations

import click

from urdfgenpy_ros.report import FrontEnd

CLI_WORDS = FrontEnd('urdfgenpy', package_paths='with -p/--package-path',
                     usage_errors=(click.UsageError,))
"""The command line as a front end (its group sets ``say`` and ``verbose`` when it runs)."""
