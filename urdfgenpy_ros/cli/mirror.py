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

"""``urdfgenpy mirror``: add the mirror image of a limb."""

from __future__ import annotations

from pathlib import Path
import re
import warnings

import click

from urdfgenpy_ros.cli._options import input_options, read_robot
from urdfgenpy_ros.formats import format_of
from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.report import counted
from urdfgenpy_ros.reshape.mirror import mirror_subtree, PLANES
from urdfgenpy_ros.resources import rebase_meshes


def _renames(pairs: tuple[str, ...]) -> dict[str, str]:
    renames = {}
    for pair in pairs:
        old, separator, new = pair.partition(':')
        if not separator or not (old or new):
            raise click.BadParameter(f'{pair!r} is not OLD:NEW (e.g. left_:right_, or :m_ '
                                     'for a prefix)', param_hint='--rename')
        renames[old] = new
    return renames


def _in_option_words(text: str) -> str:
    """Return a library message with its fix said in this command's options."""
    text = re.sub(r'pass rename= that ([a-z ]+); it was \{.*?\}',
                  r'pass --rename OLD:NEW that \1', text)
    return text.replace('mesh_folder=', '--mesh-folder').replace('rename=', '--rename')


@click.command()
@click.argument('source', type=click.Path(exists=True, dir_okay=False, path_type=Path))
@click.argument('arguments', nargs=-1, metavar='[NAME:=VALUE]...')
@click.option('--root', required=True, help='The first link of the limb to mirror.')
@click.option('--plane', type=click.Choice(sorted(PLANES)), default='xz', show_default=True,
              help='The mirror plane, in the axes of --frame.')
@click.option('--frame', default=None,
              help="The link whose plane it is (default: the robot's root link).")
@click.option('--rename', 'renames', multiple=True, metavar='OLD:NEW',
              help='Rename the copy: OLD becomes NEW wherever it is a word of a name, '
                   'except a later OLD that tells parts of the limb apart; :NEW puts NEW '
                   'before every name (repeatable; default left_:right_).')
@click.option('--mesh-folder', type=click.Path(file_okay=False, path_type=Path), default=None,
              help='Write the mirrored meshes here (default: beside the originals).')
@click.option('--output', '-o', required=True, type=click.Path(dir_okay=False, path_type=Path),
              help='The robot with both limbs: .urdf, .urdf.xacro or .sdf.')
@click.option('--force', '-f', is_flag=True, help='Overwrite OUTPUT if it exists.')
@input_options
def mirror(source: Path, arguments: tuple[str, ...], root: str, plane: str,
           frame: str | None, renames: tuple[str, ...], mesh_folder: Path | None,
           output: Path, force: bool, package_paths: tuple[Path, ...]) -> None:
    """Add to SOURCE the mirror image of the limb below --root; write OUTPUT."""
    format_of(output)
    if output.exists() and not force:
        raise UrdfgenpyError(f'{output} exists: pass --force to overwrite it')
    robot = read_robot(source, arguments, package_paths)
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter('always')
            rules = mirror_subtree(robot, root, plane, frame, _renames(renames) or None,
                                   mesh_folder=mesh_folder, search_paths=package_paths)
    except UrdfgenpyError as error:  # its fix in the words of this command's options
        raise UrdfgenpyError(_in_option_words(str(error))) from None
    for warning in caught:  # ours; others' (deprecations of the mesh readers) are noise here
        if str(warning.message).startswith('mirror:'):
            click.echo(f'warning: {_in_option_words(str(warning.message))}', err=True)
    for rule in rules:
        click.echo(str(rule))
    rebase_meshes(robot, source.parent, output.parent)  # relative meshes still found
    robot.save(output)
    click.echo(f'wrote {output}: {counted(len(robot.links), "link")}, '
               f'{counted(len(robot.joints), "joint")}')
