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
The library review: one call that every front end renders.

``review(robot, options)`` runs the checks of :data:`CHECKS` that ``options`` enable, in
their declared order, moves the findings of a Xacro expansion to their source lines, and
splits them into those that stay and those silenced (by ``options.ignore`` or by the
file's ``urdfgenpy: ignore`` comments), with what ``fix`` can repair. ``urdfgenpy check``,
the publisher node, the viewer, ``convert`` and ``init`` only render a :class:`Review`;
``validate()`` is the list of every finding, unsilenced. A new check is a function and one
row of :data:`CHECKS`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence, Set as AbstractSet
import copy
from dataclasses import dataclass, field
from os import PathLike
from pathlib import Path
import re
from typing import TYPE_CHECKING

from urdfgenpy_ros.formats.inertia_check import check_inertia
from urdfgenpy_ros.formats.xacro_source import in_source
from urdfgenpy_ros.model.codes import CODES, FIXABLE
from urdfgenpy_ros.model.errors import ValidationError
from urdfgenpy_ros.model.findings import Findings
from urdfgenpy_ros.model.review import ENGINES, ReviewRecord, Suppressed
from urdfgenpy_ros.model.topology import check_topology
from urdfgenpy_ros.model.urdf_versions import DEFAULT_TARGET, TARGETS
from urdfgenpy_ros.resources import PackageResolver
from urdfgenpy_ros.validation.joints import check_joints
from urdfgenpy_ros.validation.references import check_references
from urdfgenpy_ros.validation.suppressions import parse_codes, read_suppressions, Suppressions
from urdfgenpy_ros.validation.versions import check_versions

if TYPE_CHECKING:  # the fixer loads when there is something to repair (start-up)
    from urdfgenpy_ros.model import RobotModel
    from urdfgenpy_ros.validation.fix import Repair


@dataclass(frozen=True)
class ReviewOptions:
    """
    What a review checks and silences; every front end builds one from its own options.

    ``search_paths`` resolve ``package://`` meshes (with the ament index and
    ``ROS_PACKAGE_PATH``); ``check_meshes=False`` skips the mesh files. ``target`` is the ROS
    distribution whose urdfdom judges the URDF version (None: the robot's own features).
    ``engines`` pre-flight what ``mujoco`` and ``gazebo`` change when they load the robot.
    ``ignore`` silences finding codes (``--ignore``, the node's ``ignore``);
    ``suppressions=False`` disregards the file's ``urdfgenpy: ignore`` comments.
    ``statics`` judges efforts against gravity (T801, with ``payload`` and
    ``statics_margin``) and other force limits (T802, with ``mjcf``). ``write_sdf`` names
    the links libsdformat would refuse in an SDF (``Review.refused['libsdformat']``).
    ``limit_defaults`` are the values ``fix`` may give a missing or zero ``<limit>``, and
    ``strict`` makes warnings fail the review too. ``checks`` keeps only the named rows of
    :data:`CHECKS` (None: every row the other options enable).
    """

    search_paths: Sequence[str | PathLike[str]] = ()
    check_meshes: bool = True
    target: str | None = DEFAULT_TARGET
    engines: Sequence[str] = ()
    ignore: AbstractSet[str] = frozenset()
    suppressions: bool = True
    statics: bool = False
    payload: Mapping[str, object] | None = None
    statics_margin: float = 1.0
    mjcf: str | PathLike[str] | None = None
    write_sdf: bool = False
    limit_defaults: Mapping[str, float] = field(default_factory=dict)
    strict: bool = False
    checks: Sequence[str] | None = None

    def __post_init__(self) -> None:
        """
        Refuse a code, engine, target or check name that does not exist.

        ``ignore`` and ``engines`` may also be given as one string (``'I205,R307'``).
        """
        search_paths = self.search_paths
        object.__setattr__(self, 'search_paths', (search_paths,) if isinstance(
            search_paths, (str, PathLike)) else tuple(search_paths))
        engines = self.engines
        object.__setattr__(self, 'engines', tuple(
            part for part in re.split(r'[\s,]+', engines) if part)
            if isinstance(engines, str) else tuple(engines))
        ignore = self.ignore
        object.__setattr__(self, 'ignore', parse_codes(
            ignore if isinstance(ignore, str) else ' '.join(ignore)))
        if self.target is not None and self.target not in TARGETS:
            raise ValueError(f'unknown target {self.target!r} (use {", ".join(TARGETS)})')
        unknown = [name for name in self.engines if name not in ENGINES]
        if unknown:
            raise ValueError(f'unknown engine {unknown[0]!r} (use {", ".join(ENGINES)})')
        names = {check.name for check in CHECKS}
        unknown = [name for name in self.checks or () if name not in names]
        if unknown:
            raise ValueError(f'unknown check {unknown[0]!r} (use {", ".join(sorted(names))})')


@dataclass(frozen=True)
class Check:
    """One row of the declared checks: its name, its function and the options it reads."""

    name: str
    run: Callable[[RobotModel, Findings, ReviewOptions], None]
    options: tuple[str, ...] = ()
    """The fields of ``ReviewOptions`` it reads (documentation and ``enabled``)."""
    enabled: Callable[[ReviewOptions], bool] = lambda options: True
    """Whether the options ask for it (statics, engines, SDF output are asked for)."""


@dataclass
class Review(ReviewRecord):
    """
    What ``review()`` found about one robot, with the options it ran with and its repairs.

    The found, silenced and refused findings are :class:`ReviewRecord`'s;
    ``repairable`` are the findings ``fix`` can repair; ``needs`` says what values it still
    lacks for some (J103, J106 without ``limit_defaults``). ``Review(robot, options)``;
    the rest by keyword.
    """

    options: ReviewOptions
    repairable: list[ValidationError] = field(default_factory=list, kw_only=True)
    needs: list[str] = field(default_factory=list, kw_only=True)

    @property
    def failed(self) -> bool:
        """Return whether errors stay (or warnings, with ``options.strict``)."""
        return bool(self.errors or (self.options.strict and self.findings))

    def fix(self) -> list[Repair]:
        """Repair the ``repairable`` findings in ``robot``, in place; return what was done."""
        from urdfgenpy_ros.validation.fix import fix
        return fix(self.robot, self.repairable, dict(self.options.limit_defaults),
                   self.options.search_paths)

    def preview(self) -> list[Repair]:
        """Return what ``fix()`` would do, made on a copy: ``robot`` is left as it is."""
        from urdfgenpy_ros.validation.fix import fix
        return fix(copy.deepcopy(self.robot), self.repairable,
                   dict(self.options.limit_defaults), self.options.search_paths)

    def diff(self, path: str | PathLike[str]) -> str:
        """Return the unified diff ``apply(path)`` would make ('' when it changes nothing)."""
        from urdfgenpy_ros.validation.rewrite import repaired_text, unified_diff
        return unified_diff(Path(path), *repaired_text(self.robot, Path(path)))

    def apply(self, path: str | PathLike[str]) -> Review | None:
        """
        Write ``robot`` (repaired by ``fix()``) over its URDF file ``path``; review it again.

        Only the repaired lines change; the file keeps its permissions. Return the review
        of the file written, or None when the file would not change (nothing written).
        """
        from urdfgenpy_ros.validation.rewrite import read_written, repaired_text, replace_file
        old, new = repaired_text(self.robot, Path(path))
        if new == old:
            return None
        replace_file(Path(path), new)
        return review(read_written(self.robot, Path(path), new), self.options)


# ---- the checks -------------------------------------------------------------------------

def _read_warnings(robot: RobotModel, findings: Findings, options: ReviewOptions) -> None:
    """Add the reader's warnings, as serious as CODES says."""
    for warning in robot.read_warnings:
        findings.items.append(ValidationError(warning.code, CODES[warning.code][0],
                                              f'robot {robot.name!r}', warning.location,
                                              warning.message, 'see the message'))


def _base(robot: RobotModel) -> Path | None:
    """Return the folder relative mesh paths start from: the file's, when read from one."""
    source = robot.source.file if robot.source is not None else None
    return Path(source).parent if source and Path(source).is_file() else None


def _references(robot: RobotModel, findings: Findings, options: ReviewOptions) -> None:
    resolver = PackageResolver(options.search_paths) if options.check_meshes else None
    check_references(robot, findings, resolver, _base(robot))


def _statics(robot: RobotModel, findings: Findings, options: ReviewOptions) -> None:
    from urdfgenpy_ros.validation.statics import check_statics
    check_statics(robot, findings, options.payload, options.statics_margin)


def _efforts(robot: RobotModel, findings: Findings, options: ReviewOptions) -> None:
    from urdfgenpy_ros.validation.efforts import check_efforts
    check_efforts(robot, findings, options.mjcf)


def _gazebo(robot: RobotModel, findings: Findings, options: ReviewOptions) -> None:
    from urdfgenpy_ros.validation.preflight import gazebo_block_findings, sdformat_findings
    if len(robot.roots) == 1:  # S001, S002 say it otherwise; no engine loads such a robot
        sdformat_findings(robot, findings)
        gazebo_block_findings(robot, findings)


def _libsdformat(robot: RobotModel, findings: Findings, options: ReviewOptions) -> None:
    from urdfgenpy_ros.formats.sdf_refusals import check_libsdformat
    check_libsdformat(robot, findings)


def _mujoco(robot: RobotModel, findings: Findings, options: ReviewOptions) -> None:
    from urdfgenpy_ros.validation.mujoco_preflight import mujoco_findings
    if len(robot.roots) == 1:
        mujoco_findings(robot, findings, list(options.search_paths), _base(robot))


CHECKS: tuple[Check, ...] = (
    Check('read', _read_warnings),
    Check('topology', lambda robot, found, _: check_topology(robot, found)),
    Check('joints', lambda robot, found, _: check_joints(robot, found)),
    Check('inertia', lambda robot, found, _: check_inertia(robot, found)),
    Check('versions', lambda robot, found, options: check_versions(robot, found,
                                                                   options.target),
          ('target',)),
    Check('references', _references, ('search_paths', 'check_meshes')),
    Check('statics', _statics, ('statics', 'payload', 'statics_margin'),
          lambda options: options.statics),
    Check('efforts', _efforts, ('statics', 'mjcf'), lambda options: options.statics),
    Check('gazebo', _gazebo, ('engines',), lambda options: 'gazebo' in options.engines),
    Check('mujoco', _mujoco, ('engines', 'search_paths'),
          lambda options: 'mujoco' in options.engines),
    Check('libsdformat', _libsdformat, ('write_sdf',), lambda options: options.write_sdf),
)
"""Every check, in the order a review runs them (and its findings are listed)."""


def run_checks(robot: RobotModel, options: ReviewOptions
               ) -> tuple[list[ValidationError], dict[str, list[ValidationError]]]:
    """Return every finding of the enabled checks (at their source lines) and the refusals."""
    findings = Findings(robot)
    for check in CHECKS:
        chosen = options.checks is None or check.name in options.checks
        if chosen and check.enabled(options):
            check.run(robot, findings, options)
    refused = {consumer: in_source(items, robot) for consumer, items in findings.refused.items()}
    return in_source(findings.items, robot), refused  # Xacro: the source line, or none


def review(robot: RobotModel, options: ReviewOptions | None = None) -> Review:
    """
    Review ``robot``: every finding the ``options`` ask for, silenced ones apart.

    >>> from urdfgenpy_ros import Link, Robot
    >>> result = review(Robot('r').add_link(Link('base_link')), ReviewOptions(ignore={'I209'}))
    >>> [finding.code for finding in result.findings], result.failed
    ([], False)
    """
    options = options or ReviewOptions()
    found, refused = run_checks(robot, options)
    silencing = (read_suppressions(robot, options.ignore) if options.suppressions
                 else Suppressions(ignored=frozenset(options.ignore)))
    result = Review(robot, options, refused=refused,
                    unknown_suppressions=list(silencing.unknown))
    for finding in found:
        reason = silencing.reason(finding)
        if reason is None:
            result.findings.append(finding)
        else:
            result.suppressed.append(Suppressed(finding, reason, silencing.source(finding)))
    result.repairable = [finding for finding in result.findings if finding.code in FIXABLE]
    if result.repairable:  # none: nothing is missing either (needs stays empty)
        from urdfgenpy_ros.validation.fix import missing_defaults
        result.needs = missing_defaults(robot, result.repairable,
                                        dict(options.limit_defaults), options.search_paths)
    return result
