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
What a target format refuses, found before anything is written: the rows' ``prepare``.

Each returns a :class:`~urdfgenpy_ros.validation.checklist.Review` whose ``lines`` a
front end says before writing and whose ``refusal``, when set, is why nothing is written.
SDF and MJCF need one tree; SDF also what libsdformat refuses (an inertia) and says the
masses it keeps or leaves out; MJCF what MuJoCo refuses (a mass, a tensor).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TYPE_CHECKING

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.validation.checklist import Review


def tree_review(robot: RobotModel) -> Review:
    """Return the review of the robot's tree alone; a robot not one tree is refused."""
    from urdfgenpy_ros.validation.checklist import review, ReviewOptions
    found = review(robot, ReviewOptions(check_meshes=False, suppressions=False,
                                        checks=('topology',)))
    if found.errors:
        found.refusal = f'{found.errors[0]}'
    return found


def prepare_sdf(robot: RobotModel, options: Mapping[str, Any]) -> Review:
    """Return what libsdformat refuses in the SDF of ``robot`` (with the writer's options)."""
    found = tree_review(robot)
    if found.refusal is not None:
        return found
    from urdfgenpy_ros.formats.sdf_frames import merge_for_sdf
    from urdfgenpy_ros.formats.sdf_mass import default_mass_notes, mass_only_notes
    from urdfgenpy_ros.validation.checklist import review, ReviewOptions
    from urdfgenpy_ros.validation.sdf_refusals import lumped_into
    merged = merge_for_sdf(robot, bool(options.get('lump_fixed')))[0]  # the links it has
    found = review(merged, ReviewOptions(check_meshes=False, write_sdf=True,
                                         suppressions=False, checks=('inertia', 'libsdformat')))
    refused = [(finding, lumped_into(merged, finding))
               for finding in found.refused['libsdformat']]
    for finding, parent in refused:
        fix = (f"pass --lump-fixed (it merges the link into {parent!r}, as libsdformat's "
               'conversion does) or --fix (a tensor from its shape)'
               if parent is not None else 'pass --fix (a tensor from its shape)')
        found.lines.append(f'{finding.location}: error {finding.code} {finding.element}: '
                           f'{finding.message}, which libsdformat refuses: {fix}')
    if refused:
        lumpable = all(parent is not None for _, parent in refused)
        found.refusal = (f'libsdformat would refuse the inertia of {len(refused)} link(s) '
                         '(above): ' + ('pass --lump-fixed' if lumpable
                                        else 'pass --fix, or fix them and convert again'))
    else:  # a mass-only inertial kept as libsdformat keeps it
        found.lines += [*mass_only_notes(robot), *default_mass_notes(merged)]
    return found


def prepare_mjcf(robot: RobotModel, options: Mapping[str, Any]) -> Review:
    """Return what MuJoCo refuses in the MJCF of ``robot`` (with the writer's options)."""
    found = tree_review(robot)
    if found.refusal is not None:
        return found
    from urdfgenpy_ros.formats.mjcf.prepare import MjcfRefusedError, prepare, raise_refused
    try:
        raise_refused(prepare(robot, options), bool(options.get('fuse_fixed')))
    except MjcfRefusedError as error:
        found.lines += [str(finding) for finding in error.findings]
        found.refusal = str(error)
    return found
