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

Each returns a :class:`~urdfgenpy_ros.model.review.ReviewRecord` whose ``lines`` a front
end says before writing and whose ``refusal``, when set, is why nothing is written.
SDF and MJCF need one tree; SDF also what libsdformat refuses (an inertia) and says the
masses it keeps or leaves out; MJCF what MuJoCo refuses (a mass, a tensor). The checks
are the review's own (``topology``, ``inertia``, ``libsdformat``), run here without it:
nothing is silenced, neither by ``--ignore`` nor by a suppression comment, as a target
refuses what it refuses whatever the file says.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.formats.checked import checked
from urdfgenpy_ros.model.topology import check_topology

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.model.review import ReviewRecord


_TENSORS = ('I202', 'I203')  # what --fix mends: a tensor from the link's shape


def tree_review(robot: RobotModel) -> ReviewRecord:
    """Return the review of the robot's tree alone; a robot not one tree is refused."""
    found = checked(robot, check_topology)
    if found.errors:
        found.refusal = f'{found.errors[0]}'
    return found


def prepare_sdf(robot: RobotModel, options: Mapping[str, Any]) -> ReviewRecord:
    """Return what libsdformat refuses in the SDF of ``robot`` (with the writer's options)."""
    found = tree_review(robot)
    if found.refusal is not None:
        return found
    from urdfgenpy_ros.formats.inertia_check import check_inertia
    from urdfgenpy_ros.formats.sdf_frames import merge_for_sdf
    from urdfgenpy_ros.formats.sdf_mass import default_mass_notes, mass_only_notes
    from urdfgenpy_ros.formats.sdf_refusals import check_libsdformat, lumped_into
    merged = merge_for_sdf(robot, bool(options.get('lump_fixed')))[0]  # the links it has
    found = checked(merged, check_inertia, check_libsdformat)
    refused = [(finding, lumped_into(merged, finding) if finding.code in _TENSORS else None)
               for finding in found.refused['libsdformat']]
    for finding, parent in refused:
        fix = (f"pass --lump-fixed (it merges the link into {parent!r}, as libsdformat's "
               'conversion does) or --fix (a tensor from its shape)'
               if parent is not None else 'pass --fix (a tensor from its shape)')
        if finding.code not in _TENSORS:  # no tensor from a shape mends a mass or a NaN
            fix = finding.hint
        found.lines.append(f'{finding.location}: error {finding.code} {finding.element}: '
                           f'{finding.message}, which libsdformat refuses: {fix}')
    if refused:
        lumpable = all(parent is not None for _, parent in refused)
        tensors = all(finding.code in _TENSORS for finding, _ in refused)
        found.refusal = (f'libsdformat would refuse the inertia of {len(refused)} link(s) '
                         '(above): ' + ('pass --lump-fixed' if lumpable else
                                        'pass --fix, or fix them and convert again' if tensors
                                        else 'fix them and convert again'))
    else:  # a mass-only inertial kept as libsdformat keeps it
        found.lines += [*mass_only_notes(robot), *default_mass_notes(merged)]
    return found


def prepare_mjcf(robot: RobotModel, options: Mapping[str, Any]) -> ReviewRecord:
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
