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
``urdfgenpy collision``: make a robot's collision meshes light, and say what each loses.

One line per collision in ``check``'s format on stderr (``--json``: the table on stdout);
``--min-iou`` refuses a collision below it with its numbers, and then nothing is written.
"""

from __future__ import annotations

import json
from pathlib import Path
import tempfile

import click

from urdfgenpy_ros.cli._options import input_options, read_robot
from urdfgenpy_ros.collision.methods import METHODS, Options
from urdfgenpy_ros.formats import format_of
from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.resources import rebase_meshes
from urdfgenpy_ros.robot import Robot

_DEFAULTS = Options()


@click.command()
@click.argument('source', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@click.option('--output', '-o', required=True, type=click.Path(dir_okay=False, path_type=Path),
              help='The robot with the new collisions: .urdf, .urdf.xacro or .sdf.')
@click.option('--method', type=click.Choice(METHODS), default='hull', show_default=True,
              help='hull: one convex hull per mesh; decompose: convex parts (CoACD); '
                   'primitive: the best-fitting box, cylinder, capsule or sphere; decimate: '
                   'at most --max-faces triangles; auto: the lightest within --min-iou.')
@click.option('--link', 'links', multiple=True, metavar='NAME',
              help='Only this link (repeatable; default: every link).')
@click.option('--max-faces', type=click.IntRange(min=4), default=_DEFAULTS.max_faces,
              show_default=True, help='decimate: the face budget of each mesh.')
@click.option('--max-hulls', type=click.IntRange(min=1), default=_DEFAULTS.max_hulls,
              show_default=True, help='decompose: at most this many convex parts per mesh.')
@click.option('--min-iou', type=click.FloatRange(0.0, 1.0), default=None,
              help='Refuse a collision whose IoU with the original is below this (auto: '
                   'the lightest method that reaches it; default 0.9 there).')
@click.option('--split', is_flag=True,
              help='primitive: fit one primitive to each convex part of a decomposition '
                   '(CoACD) instead of one to the whole mesh.')
@click.option('--seed', type=int, default=_DEFAULTS.seed, show_default=True,
              help="decompose: CoACD's random seed.")
@click.option('--mesh-folder', type=click.Path(file_okay=False, path_type=Path), default=None,
              help='Write the new meshes here (default: beside each source mesh).')
@click.option('--json', 'as_json', is_flag=True,
              help='Print the table of measures as JSON on stdout.')
@click.option('--force', '-f', is_flag=True, help='Overwrite OUTPUT if it exists.')
@input_options
def collision(source: Path, arguments: tuple[str, ...], output: Path, method: str,
              links: tuple[str, ...], max_faces: int, max_hulls: int, min_iou: float | None,
              split: bool, seed: int, mesh_folder: Path | None, as_json: bool, force: bool,
              package_paths: tuple[Path, ...]) -> None:
    """Make the collision meshes of SOURCE light; write OUTPUT; say what each loses."""
    from urdfgenpy_ros.collision.apply import apply_plan, plan_collisions
    format_of(output)
    if output.exists() and not force:
        raise UrdfgenpyError(f'{output} exists: pass --force to overwrite it')
    robot = read_robot(source, arguments, package_paths)
    options = Options(max_faces=max_faces, max_hulls=max_hulls, seed=seed, split=split)
    plan = plan_collisions(robot, method, links, mesh_folder=mesh_folder,
                           search_paths=package_paths, min_iou=min_iou, options=options)
    report = plan.report
    for line in report.lines():
        click.echo(line, err=True)
    below = report.below()
    if below:
        raise UrdfgenpyError(f'{output} not written: {len(below)} collision(s) below '
                             f'--min-iou {min_iou} (above; pick another --method or lower '
                             '--min-iou)')
    written = apply_plan(robot, plan, '--mesh-folder')
    try:
        rebase_meshes(robot, source.parent, output.parent)  # relative meshes still found
        robot.save(output)
    except BaseException:
        for path in written:  # nothing is written unless the whole run succeeds
            path.unlink(missing_ok=True)
        raise
    if as_json:  # only once written: a table of files that are not there would mislead
        click.echo(json.dumps({'method': method, 'min_iou': report.floor,
                               'collisions': report.table()}, indent=2))
    none = '' if report.results or report.unclosed else (
        ' (no chosen link has a mesh collision: primitives are light already)')
    heavier = [result.link for result in report.results
               if result.measures.faces_after > result.measures.faces_before]
    more = (f' and {len(heavier)} replaced by more faces than its source had (convex parts: '
            f"link {', '.join(heavier)})") if heavier else ''
    click.echo(f'wrote {output}: {len(report.results) - len(heavier)} collision mesh(es) made '
               f'light by {method}{more}, {len(written)} new mesh file(s){none}', err=True)


def mjcf_collisions(robot: Robot, method: str | None, search_paths: tuple[Path, ...]
                    ) -> tempfile.TemporaryDirectory[str] | None:
    """
    Make ``robot``'s collision meshes light for ``convert --collision`` (MJCF output).

    The new meshes go to a scratch folder that lives as long as the returned object (the
    MJCF writer copies them to its assets); capsules stay capsules. Each collision's line
    goes to stderr. Each mesh is measured as its convex hull, the shape MuJoCo collides
    with, and ``auto`` chooses on that.
    """
    if method is None:
        return None
    from urdfgenpy_ros.collision.apply import apply_plan, plan_collisions
    scratch = tempfile.TemporaryDirectory(prefix='urdfgenpy-collision-')
    plan = plan_collisions(robot, method, None, mesh_folder=Path(scratch.name),
                           search_paths=search_paths, capsules=True, absolute=True,
                           options=Options(hulls=True))  # MuJoCo collides with hulls
    for line in plan.report.lines():
        click.echo(line, err=True)
    apply_plan(robot, plan)
    return scratch
