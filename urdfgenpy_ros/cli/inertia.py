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

"""``urdfgenpy inertia``: an ``<inertial>`` block for a mesh, or for MeshLab's figures."""

from __future__ import annotations

from pathlib import Path
import warnings

import click

from urdfgenpy_ros.formats.urdf import UrdfWriter
from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.model.inertial import Inertial
from urdfgenpy_ros.model.link import Link
from urdfgenpy_ros.model.mesh_inertia import ScaleWarning
from urdfgenpy_ros.robot import Robot


# MeshLab's figures are pasted as they are printed: "--tensor 8171479.5 -1091.58 ...". The
# numbers after the first reach the command as extra arguments, negative ones included.
@click.command(context_settings={'ignore_unknown_options': True})
@click.argument('arguments', nargs=-1, type=click.UNPROCESSED, metavar='[MESH]')
@click.option('--mass', type=float, help='Total mass in kg.')
@click.option('--density', type=float, help='Uniform density in kg/m^3 (instead of --mass).')
@click.option('--scale', type=float, default=1.0, show_default=True,
              help='Vertex scale (0.001 for a mesh in millimetres).')
@click.option('--meshlab', is_flag=True,
              help="Convert MeshLab's Compute Geometric Measures output instead of a mesh.")
@click.option('--volume', type=float, help='MeshLab: "Mesh Volume is" (mm^3).')
@click.option('--tensor', help='MeshLab: the 9 numbers of "Inertia Tensor is", row by row '
              '(one quoted argument, or pasted as they are printed).')
def inertia(arguments: tuple[str, ...], mass: float | None, density: float | None,
            scale: float, meshlab: bool, volume: float | None, tensor: str | None) -> None:
    """Print the <inertial> of MESH (STL, OBJ, DAE), or of MeshLab's figures (--meshlab)."""
    if meshlab:
        pasted = ' '.join([tensor or '', *arguments]).replace(',', ' ').split()
        try:
            numbers = [float(value) for value in pasted]
        except ValueError as error:
            raise click.BadParameter(f'{" ".join(pasted)!r}: {error}',
                                     param_hint='--tensor') from None
        if mass is None or volume is None or len(numbers) != 9:
            raise UrdfgenpyError('--meshlab needs --mass, --volume and --tensor with 9 '
                                 'numbers (row by row, as MeshLab prints them)')
        inertial = Inertial.from_meshlab(mass, volume, [numbers[0:3], numbers[3:6],
                                                        numbers[6:9]])
    else:
        if len(arguments) != 1:
            raise UrdfgenpyError('give one MESH file, or --meshlab with its figures')
        mesh = Path(arguments[0])
        if not mesh.is_file():
            raise click.BadParameter(f'{mesh} is not a file', param_hint='MESH')
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter('always')
            inertial = Inertial.from_mesh(str(mesh), density=density, mass=mass,
                                          scale=(scale, scale, scale))
        for warning in caught:  # one line each, in this command's words
            note = warning.message
            click.echo(f'warning: {note.name} spans {note.extent:g} m: if it is in '
                       'millimetres, pass --scale 0.001' if isinstance(note, ScaleWarning)
                       else f'warning: {note}', err=True)
    link = Link('part').set_inertial(inertial)
    click.echo(UrdfWriter(Robot('part')).write_inertial(inertial, '', link))
