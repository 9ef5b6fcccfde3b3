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
Every registry and corpus robot that check_urdf accepts, converted to MJCF and judged.

MuJoCo compiles it and steps it 1000 times with zero control without diverging (a robot
whose own masses and collisions make MuJoCo diverge must diverge in MuJoCo's own import
too); per body the mass, centre of mass and inertia equal yourdfpy's reading of the URDF
(pinocchio's lumped inertia when fixed links are fused); every link's pose equals
pinocchio's forward kinematics at 20 random configurations; each joint's range, damping,
friction and effort limit equal the URDF's (1e-9). A robot whose mass or inertia MuJoCo
refuses is refused before anything is written, and MuJoCo's own URDF import (keeping
every body) refuses it too.
"""

from __future__ import annotations

from pathlib import Path

from helpers import (
    check_urdf_verdict, CORPUS, corpus_cases, CORPUS_PACKAGES, require_module, xacro_expand)
import mjcf_judge
import pytest
import registry_robots

from urdfgenpy_ros.formats import load
from urdfgenpy_ros.formats.mjcf import MjcfRefusedError, write_mjcf

pytestmark = pytest.mark.engine  # MuJoCo compiles and runs every real robot

# more than a few seconds each (large meshes to convert and to hull)
SLOW = {'cookie.urdf', 'panda.urdf', 'fr3.urdf', 'dual_fr3.urdf', 'upkie.urdf',
        'upkie_camera.urdf', 'kinova_robotiq.urdf'}


def _registry() -> list:
    return [pytest.param(path, registry_robots.search_paths(), fuse,
                         id=f'{registry_robots.robot_id(path)}-{"fused" if fuse else "bodies"}',
                         marks=[pytest.mark.slow] if path.name in SLOW or fuse else [])
            for path in registry_robots.robots() for fuse in (False, True)]


def _corpus() -> list:
    files = sorted(CORPUS.rglob('*.urdf')) if CORPUS.is_dir() else []
    folders = sorted({(CORPUS / folder).parent for folder in CORPUS_PACKAGES.values()})
    cases = [(path, folders, fuse) for path in files for fuse in (False, True)]
    return corpus_cases(cases or [(None, [], False)],  # without a corpus: one skip
                        [f'{path.relative_to(CORPUS)}-{"fused" if fuse else "bodies"}'
                         for path in files for fuse in (False, True)])


def _example_robot_data() -> list:
    """Return example-robot-data's URDF files (pip's example-robot-data), all slow."""
    from importlib import metadata
    try:
        share = Path(str(metadata.distribution('example-robot-data').locate_file(
            'cmeel.prefix/share/example-robot-data/robots')))
    except metadata.PackageNotFoundError:
        share = Path('/nonexistent')
    files = sorted(share.glob('*/robots/*.urdf')) + sorted(share.glob('*/urdf/*.urdf'))
    if not files:
        return [pytest.param(None, [], False, id='not-installed', marks=pytest.mark.skip(
            'example-robot-data not installed'))]
    return [pytest.param(path, [share], False, id=str(path.relative_to(share)),
                         marks=pytest.mark.slow) for path in files]


def _urdf_for_judges(path: Path, robot, folder: Path) -> Path:
    """Return the URDF the judges read: the file, or real xacro's expansion of it."""
    if not any(warning.code == 'X101' for warning in robot.read_warnings):
        return path
    expanded = folder / path.name
    expanded.write_text(xacro_expand(path))
    return expanded


def _mujoco_import(robot, source: Path | None = None):
    """
    Return MuJoCo's own URDF import of the robot, every body kept.

    Without ``source`` it has no geometry; with it, the collisions MuJoCo can read (STL and
    OBJ files found from ``source``'s folder or the registry packages) stay.
    """
    import mujoco
    from lxml import etree
    text = robot.to_urdf()
    if source is not None:
        text = registry_robots.absolute_meshes(text, source.parent)
    root = etree.fromstring(text.encode())
    for shape in [*root.iter('visual'), *root.iter('collision')]:
        mesh = shape.find('geometry/mesh')
        readable = mesh is not None and Path(mesh.get('filename', '')).is_file() and \
            mesh.get('filename', '').lower().endswith(('.stl', '.obj'))
        if source is None or shape.tag == 'visual' or (mesh is not None and not readable):
            shape.getparent().remove(shape)
    root.append(etree.fromstring('<mujoco><compiler fusestatic="false"/></mujoco>'))
    return mujoco.MjModel.from_xml_string(etree.tostring(root, encoding='unicode'))


def _mujoco_import_refuses(robot) -> bool:
    """Return whether MuJoCo's own URDF import, keeping every body, refuses the robot."""
    try:
        _mujoco_import(robot)
    except ValueError:
        return True
    return False


def _judge(path: Path, search_paths: list, fuse: bool, tmp_path: Path) -> None:
    require_module('mujoco')
    require_module('pinocchio')
    require_module('yourdfpy')
    if not check_urdf_verdict(path):
        pytest.skip('check_urdf refuses it')
    robot = load(path, {}, search_paths)
    target = tmp_path / 'robot.xml'
    try:
        write_mjcf(robot, target, fuse_fixed=fuse, search_paths=search_paths)
    except MjcfRefusedError as refused:
        assert {finding.code for finding in refused.findings} <= {'I201', 'I202', 'I203',
                                                                  'I207'}
        assert not target.exists() and _mujoco_import_refuses(robot)
        return
    model = mjcf_judge.compile_mjcf(target)
    mjcf_judge.assert_no_contact_at_home(model)  # self-collisions excluded as MuJoCo finds
    if mjcf_judge.diverges(model):  # the robot's own physics: MuJoCo's import diverges too
        assert mjcf_judge.diverges(_mujoco_import(robot, path))
    urdf = _urdf_for_judges(path, robot, tmp_path)
    lumping = 'preserveFixedJoint' in urdf.read_text() or \
        'disableFixedJointLumping' in urdf.read_text()
    if not fuse:
        mjcf_judge.assert_inertia_as_urdf(model, urdf)
    elif not lumping:  # pinocchio lumps every fixed joint; these blocks keep some
        mjcf_judge.assert_inertia_as_pinocchio(model, urdf)
    mjcf_judge.assert_total_mass_as_urdf(model, urdf)
    assert mjcf_judge.assert_fk_as_pinocchio(model, urdf) > 0 or len(robot.links) == 1
    mjcf_judge.assert_joints_as_urdf(model, robot)


@pytest.mark.parametrize(('path', 'search_paths', 'fuse'), _registry())
def test_registry_robot_in_mujoco(path: Path, search_paths: list, fuse: bool,
                                  tmp_path: Path) -> None:
    _judge(path, search_paths, fuse, tmp_path)


@pytest.mark.parametrize(('path', 'search_paths', 'fuse'), _corpus())
def test_corpus_robot_in_mujoco(path: Path, search_paths: list, fuse: bool,
                                tmp_path: Path) -> None:
    _judge(path, search_paths, fuse, tmp_path)


@pytest.mark.parametrize(('path', 'search_paths', 'fuse'), _example_robot_data())
def test_example_robot_data_in_mujoco(path: Path, search_paths: list, fuse: bool,
                                      tmp_path: Path) -> None:
    _judge(path, search_paths, fuse, tmp_path)
