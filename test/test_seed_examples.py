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

"""Every snippet of the getting-started page runs as written, but for the import name."""

from __future__ import annotations

import math
import os
from pathlib import Path

from helpers import assert_check_urdf_accepts, load_yourdfpy, pose_matrix, REPO
import pytest

SEED = REPO.parent / 'shared' / 'seeds' / '001_9d70f1c18a520da0.txt'

# (first line, last line) of each code snippet on the page, in page order.
SNIPPETS = [
    ('from urdfgenpy import (', 'robot.print_tree()'),
    ('box = Box(0.2, 0.2, 0.1)', 'origin = Origin.above(sphere)'),
    ('wheel_origin = Origin.wheel(', 'wheel_origin = Origin.wheel('),
    ('# From a specific shape', 'inertial = Inertial.from_geometry(mass=1.0, geometry=box)'),
    ('robot.print_tree() # coloured', 'robot.save_tree("tree.txt")'),
    ('# To string', 'robot.save("output.xacro")'),
]


def _snippets() -> list[str]:
    if not SEED.is_file():
        pytest.skip(f'seed page not found at {SEED}')
    lines = SEED.read_text(encoding='utf-8').splitlines()
    found, position = [], 0
    for first, last in SNIPPETS:
        start = next(i for i in range(position, len(lines)) if lines[i].startswith(first))
        end = next(i for i in range(start, len(lines)) if lines[i].startswith(last))
        found.append('\n'.join(lines[start:end + 1]))
        position = end + 1
    return [code.replace('from urdfgenpy import', 'from urdfgenpy_ros import')
            for code in found]


@pytest.fixture
def page(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> dict:
    """Run every snippet in one namespace inside a scratch directory."""
    namespace: dict = {}
    cwd = os.getcwd()
    os.chdir(tmp_path)
    try:
        minimal, *snippets = _snippets()
        exec(compile(minimal, str(SEED), 'exec'), namespace)
        # The later snippets use names (Sphere) the page never imports: give them all.
        exec('from urdfgenpy_ros import *', namespace)
        for code in snippets:
            exec(compile(code, str(SEED), 'exec'), namespace)
    finally:
        os.chdir(cwd)
    namespace['printed'] = capsys.readouterr().out
    namespace['dir'] = tmp_path
    return namespace


def test_minimal_example_writes_a_urdf_check_urdf_accepts(page: dict) -> None:
    assert_check_urdf_accepts(page['dir'] / 'ptu.urdf')


def test_minimal_example_loads_in_yourdfpy_with_the_same_model(page: dict) -> None:
    ours = page['robot']
    theirs = load_yourdfpy(page['dir'] / 'ptu.urdf')
    assert [link.name for link in theirs.links] == ['base_plate', 'pan_link', 'tilt_link']
    for link in theirs.links:
        mine = ours.get_link(link.name)
        assert link.inertial.mass == mine.inertial.mass
        assert link.inertial.inertia.tolist() == [list(row) for row in mine.inertial.tensor]
        assert (link.visuals[0].origin == pose_matrix(mine.visual.origin)).all()
        assert link.visuals[0].material.name == mine.visual.material.name
    for joint in theirs.joints:
        mine = ours.get_joint(joint.name)
        assert (joint.type, joint.parent, joint.child) == (
            mine.type.value, mine.parent, mine.child)
        assert (joint.origin == pose_matrix(mine.origin)).all()
        assert joint.axis.tolist() == list(mine.axis)
        assert (joint.limit.lower, joint.limit.upper, joint.limit.effort,
                joint.limit.velocity) == (mine.limit.lower, mine.limit.upper,
                                          mine.limit.effort, mine.limit.velocity)
    colours = {material.name: material.color.rgba.tolist() for material in theirs.materials}
    assert colours == {'charcoal': [0.22, 0.22, 0.25, 1.0], 'amber': [1.0, 0.55, 0.0, 1.0]}


def test_origin_above_puts_the_bottom_of_each_geometry_at_zero(page: dict) -> None:
    assert page['box'].height == 0.1 and page['cyl'].length == 0.3
    # The page's comment says 0.05 for the sphere of radius 0.1: the bottom of a sphere
    # lies one radius below its centre, so the geometry wins (README says so).
    lifts = {'box': 0.05, 'cyl': 0.15, 'sphere': 0.1}
    origins = {'box': page['box'], 'cyl': page['cyl'], 'sphere': page['sphere']}
    from urdfgenpy_ros import Origin
    for name, geometry in origins.items():
        assert Origin.above(geometry).xyz == (0.0, 0.0, lifts[name])
    assert page['origin'].xyz == (0.0, 0.0, 0.1)


def test_wheel_origin_turns_a_cylinder_axis_onto_y(page: dict) -> None:
    wheel = page['wheel_origin']
    assert wheel.xyz == (-0.15, 0.0, 0.05)
    assert wheel.rpy == (-math.pi / 2, 0.0, 0.0)
    # The rotated z axis (the cylinder's) must point along +/- y.
    matrix = pose_matrix(wheel)
    assert matrix[:3, 2].round(12).tolist() in ([0.0, 1.0, 0.0], [0.0, -1.0, 0.0])


def test_inertia_snippets_give_the_closed_form_of_the_last_shape(page: dict) -> None:
    inertial = page['inertial']
    assert inertial.mass == 1.0
    assert inertial.ixx == pytest.approx(1.0 / 12 * (0.2 ** 2 + 0.1 ** 2), rel=1e-15)
    assert inertial.izz == pytest.approx(1.0 / 12 * (0.2 ** 2 + 0.2 ** 2), rel=1e-15)


def test_tree_and_export_snippets_write_their_files(page: dict) -> None:
    folder = page['dir']
    tree = (folder / 'tree.txt').read_text(encoding='utf-8')
    assert tree == page['text'] and 'tilt_joint [revolute] → tilt_link' in tree
    assert '\033[' not in page['printed'], 'colour codes printed to a non-terminal'
    assert page['urdf_xml'] == (folder / 'output.urdf').read_text(encoding='utf-8')
    assert page['xacro_xml'] == (folder / 'output.xacro').read_text(encoding='utf-8')
    assert_check_urdf_accepts(folder / 'output.urdf')
