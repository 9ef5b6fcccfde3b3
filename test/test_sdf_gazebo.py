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
``<gazebo reference>`` settings in SDF output, judged by libsdformat's own URDF conversion.

libsdformat converts the URDF and prints its SDF; it also reads ours and prints it. Every
setting a ``<gazebo>`` block gives (friction, contact, gravity, self-collision, joint
physics, springs, material scripts, copied elements) is compared element by element, per
link, collision, visual and joint, on every robot the tests read.
"""

from __future__ import annotations

from collections import Counter
import json
from pathlib import Path
import subprocess
import warnings

from click.testing import CliRunner
from helpers import build_sdf_checker, CORPUS, corpus_cases, FIXTURES, parse_xml
import pytest

from urdfgenpy_ros import Robot
from urdfgenpy_ros.cli import main

pytestmark = pytest.mark.engine  # libsdformat's checker

SETTINGS = FIXTURES / 'sdf' / 'gazebo_settings.urdf'
# What a <gazebo> block can put in each SDF element (libsdformat's parser_urdf.cc)
_LINK = ('gravity', 'self_collide', 'velocity_decay')
_LINK_PLAIN = {'pose', 'inertial', 'collision', 'visual', 'must_be_base_link'}
_SHAPE = {'collision': ('surface', 'laser_retro', 'max_contacts'),
          'visual': ('material/script',)}
_JOINT = ('physics', 'axis/dynamics/spring_reference', 'axis/dynamics/spring_stiffness')
# Values libsdformat fills in where an element it requires is absent: the same as none.
_DEFAULTS = {('axis/dynamics/spring_reference', 0.0), ('axis/dynamics/spring_stiffness', 0.0),
             ('physics/ode/limit/cfm', 0.0), ('physics/ode/limit/erp', 0.2)}


@pytest.fixture(scope='module')
def printed(tmp_path_factory: pytest.TempPathFactory):
    """Return a function printing the SDF libsdformat makes of a file (None if it refuses)."""
    binary = build_sdf_checker(tmp_path_factory.mktemp('checker'))

    def run(path: Path) -> str | None:
        result = subprocess.run([str(binary), '--sdf', str(path)], capture_output=True,
                                text=True, timeout=60)
        return result.stdout if result.returncode == 0 else None
    return run


def _value(text: str | None) -> object:
    text = (text or '').strip()
    try:
        return round(float(text), 9)
    except ValueError:
        return text


def _relative(leaf, element) -> str:
    tags = []
    while leaf is not element:
        tags.append(leaf.tag)
        leaf = leaf.getparent()
    return '/'.join(reversed(tags))


def _leaves(element, paths) -> tuple:
    found = [(_relative(leaf, element), _value(leaf.text))
             for path in paths for node in element.findall(path)
             for leaf in node.iter() if len(leaf) == 0 and (leaf.text or '').strip()]
    return tuple(sorted((leaf for leaf in found if leaf not in _DEFAULTS), key=str))


def _tag(element) -> str:
    """Return a tag as written: ``sensor:contact`` (libsdformat prints the prefix alone)."""
    tag = str(element.tag)
    if tag.startswith('{') and element.prefix:
        return f"{element.prefix}:{tag.split('}', 1)[1]}"
    return tag


def gazebo_settings(text: str) -> dict:
    """Return what <gazebo> blocks can set, per link, shape (as a multiset) and joint."""
    model = parse_xml(text.encode()).find('model')  # pr2's <sensor:contact>: a prefix
    found: dict = {'static': _leaves(model, ('static',))}
    for link in model.findall('link'):
        copied = Counter(_tag(child) for child in link if child.tag not in _LINK_PLAIN
                         and child.tag not in _LINK)
        found[f"link {link.get('name')}"] = (_leaves(link, _LINK), sorted(copied.items()))
        for kind, paths in _SHAPE.items():
            found[f"{kind}s {link.get('name')}"] = sorted(
                (_leaves(shape, paths) for shape in link.findall(kind)), key=str)
    for joint in model.findall('joint'):
        found[f"joint {joint.get('name')}"] = _leaves(joint, _JOINT)
    return found


def _ours(robot: Robot, folder: Path) -> Path:
    path = folder / 'ours.sdf'
    for joint in robot.joints:  # SDF 1.9, which Debian's libsdformat 12 reads, has no mimic
        joint.mimic = None
    with warnings.catch_warnings():
        warnings.simplefilter('ignore')
        robot.to_sdf(path, lump_fixed=True)
    return path


def _compare(theirs: dict, ours: dict) -> None:
    common = set(theirs) & set(ours)
    assert {key for key in theirs if key.startswith('link')} <= common
    for key in sorted(common):
        assert ours[key] == theirs[key], key


def test_every_gazebo_setting_goes_where_libsdformat_puts_it(printed, tmp_path: Path) -> None:
    theirs = gazebo_settings(printed(SETTINGS))
    ours = gazebo_settings(printed(_ours(Robot.from_urdf(SETTINGS), tmp_path)))
    _compare(theirs, ours)
    # The blocks do set something: the comparison is not between two empty models.
    wheel = theirs['collisions wheel']
    assert any(('surface/friction/ode/mu', 0.3) in shape for shape in wheel)
    assert ('gravity', 'false') in theirs['link base_link'][0]
    assert any(path.startswith('physics') for path, _ in theirs['joint wheel_joint'])


def test_the_two_link_mu1_file_keeps_its_friction(printed, tmp_path: Path) -> None:
    """The issue's reproduction: a two-link file with mu1 0.3 and a gravity-off link."""
    source = tmp_path / 'two.urdf'
    tensor = '<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>'
    body = (f'<inertial><mass value="1"/>{tensor}</inertial>'
            '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>')
    source.write_text(
        f'<robot name="two"><link name="base_link">{body}</link><link name="arm">{body}</link>'
        '<joint name="j" type="revolute"><parent link="base_link"/><child link="arm"/>'
        '<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        '<gazebo reference="arm"><mu1>0.3</mu1><turnGravityOff>true</turnGravityOff>'
        '</gazebo></robot>')
    result = CliRunner().invoke(main, ['convert', str(source), str(tmp_path / 'two.sdf')])
    assert result.exit_code == 0, result.output
    theirs = gazebo_settings(printed(source))
    ours = gazebo_settings(printed(tmp_path / 'two.sdf'))
    assert ours == theirs
    assert ours['collisions arm'] == [(('surface/friction/ode/mu', 0.3),)]
    assert ours['link arm'][0] == (('gravity', 'false'),)


def test_what_libsdformat_drops_is_one_line_each(tmp_path: Path) -> None:
    result = CliRunner().invoke(main, ['convert', '--lump-fixed', str(SETTINGS),
                                       str(tmp_path / 'out.sdf')])
    assert result.exit_code == 0, result.output
    lines = [line for line in result.stderr.splitlines() if '<gazebo' in line]
    said = {(line.split('> <', 1)[0].split('<gazebo', 1)[1], line.split('> <')[1].split('>')[0])
            for line in lines}
    assert said == {
        (" reference='base_link'", 'static'),  # only a block without reference sets it
        (" reference='wheel'", 'stopCfm'),  # a joint setting in a link's block
        (" reference='wheel'", 'material'),  # kept, but Gazebo Sim renders no script
        (" reference='wheel_joint'", 'mu1'),  # a collision setting in a joint's block
        (" reference='no_such_link'", 'mu1'),
        ('', 'mu2'),  # no reference: no collision takes it
        (" reference='bumper_joint'", 'provideFeedback'),  # that joint is merged away
    }
    assert all(line.startswith(f'{SETTINGS}:') for line in lines)
    assert len(lines) == len(said)


def _every_urdf() -> list:
    from registry_robots import robot_id, robots
    fixtures = sorted(FIXTURES.rglob('*.urdf'))
    corpus = sorted(CORPUS.rglob('*.urdf')) if CORPUS.is_dir() else []
    return [*[pytest.param(path, id=str(path.relative_to(FIXTURES))) for path in fixtures],
            *[pytest.param(path, id=robot_id(path)) for path in robots()],
            *corpus_cases(corpus, [str(path.relative_to(CORPUS)) for path in corpus])]


@pytest.mark.parametrize('path', _every_urdf())
def test_gazebo_settings_match_libsdformat_on_every_robot(
        path: Path, printed, tmp_path: Path) -> None:
    from test_sdf import readable_robot
    reference = printed(path)  # libsdformat's own URDF conversion
    if reference is None:
        pytest.skip('libsdformat does not convert the original')
    robot = readable_robot(path)
    try:
        ours = printed(_ours(robot, tmp_path))
    except ValueError as error:  # planar joints: SDF has none
        pytest.skip(str(error))
    assert ours is not None
    _compare(gazebo_settings(reference), gazebo_settings(ours))


def test_check_engines_gazebo_names_what_the_conversion_drops(printed) -> None:
    """G603 for each dropped element, G604 for a script: and libsdformat has none of them."""
    result = CliRunner().invoke(main, ['check', '--engines', 'gazebo', '--format', 'json',
                                       str(SETTINGS)])
    findings = [f for f in json.loads(result.output)['files'][0]['findings']
                if f['code'] in ('G603', 'G604')]
    said = {(f['code'], f['element']) for f in findings}
    assert said == {
        ('G603', "<gazebo reference='base_link'> <static>"),
        ('G603', "<gazebo reference='wheel'> <stopCfm>"),
        ('G603', "<gazebo reference='wheel_joint'> <mu1>"),
        ('G603', "<gazebo reference='no_such_link'> <mu1>"),
        ('G603', '<gazebo> <mu2>'),
        ('G603', "<gazebo reference='bumper_joint'> <provideFeedback>"),
        ('G604', "<gazebo reference='wheel'> <material>"),
    }
    # The values the dropped elements carry appear nowhere in libsdformat's conversion.
    theirs = printed(SETTINGS)
    for dropped in ('<mu2>0.7</mu2>', '<mu>0.2</mu>', '<mu>0.5</mu>', '<static>true'):
        assert dropped not in theirs
    assert '<name>Gazebo/Black</name>' in theirs  # the script is kept, for no renderer


def test_gazebo_settings_match_libsdformat_on_xacro_robots(printed, tmp_path: Path) -> None:
    """Husky's wheels (mu1, mu2, kp, kd, fdir1 ...): xacro expands, libsdformat converts."""
    from helpers import ament_index, corpus_file, environment, xacro_expand
    path = corpus_file('husky/husky_description/urdf/husky.urdf.xacro')
    with environment(ament_index(tmp_path / 'index')):
        expanded = tmp_path / 'husky.urdf'
        expanded.write_text(xacro_expand(path))  # the real xacro
        robot = Robot.from_xacro(path)
    theirs = gazebo_settings(printed(expanded))
    _compare(theirs, gazebo_settings(printed(_ours(robot, tmp_path))))
    assert any('surface/friction/ode/mu' in str(shapes) for key, shapes in theirs.items()
               if key.startswith('collisions'))  # the comparison is not of empty models
