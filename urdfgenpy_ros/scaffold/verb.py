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

"""``ros2 pkg scaffold``: the same command as ``urdfgenpy init``, as a ros2pkg verb."""

from __future__ import annotations

import argparse

from urdfgenpy_ros.scaffold.command import add_arguments, run

try:  # the ros2cli base class when ros2cli is installed; the same two methods otherwise
    from ros2cli.verb import VerbExtension
except ImportError:  # pragma: no cover - ros2cli is not on PyPI
    class VerbExtension:  # type: ignore[no-redef]
        """Stand-in for ros2cli's VerbExtension (ros2cli itself is not on PyPI)."""

        def add_arguments(self, parser: argparse.ArgumentParser, cli_name: str) -> None:
            """Declare the verb's arguments."""

        def main(self, *, args: argparse.Namespace) -> int:
            """Run the verb."""
            raise NotImplementedError


class ScaffoldVerb(VerbExtension):
    """Create a ROS 2 description package for a robot (URDF, Xacro, DH table or example)."""

    def add_arguments(self, parser: argparse.ArgumentParser, cli_name: str) -> None:
        """Declare the options (those of ``ros2 pkg create`` where they exist)."""
        add_arguments(parser)

    def main(self, *, args: argparse.Namespace) -> int:
        """Create the package; return the exit code."""
        return run(args, 'ros2 pkg scaffold')
