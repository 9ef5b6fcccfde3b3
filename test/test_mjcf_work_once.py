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
The MJCF export's work done once (issue 41), each result judged by MuJoCo.

A lidar of many rays is placed in one pass (its sites before the body's child bodies, in
ray order, reading what MuJoCo's rangefinders read); the contact model is compiled with
only the mesh files its collision geoms read; a converted mesh's verdict is asked once.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from helpers import require_module
from lxml import etree
from mesh_judge import write_y_up_dae
import pytest

from urdfgenpy_ros import Box, Inertial, Joint, JointLimit, Link, Origin, Robot
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.formats.mjcf import write_mjcf


@pytest.fixture(autouse=True)
def _mujoco() -> None:
    require_module('mujoco')


def _scanning_head(samples: int) -> Robot:
    """Return a head with a lidar of ``samples`` rays, a child link, and a wall 2 m ahead."""
    from urdfgenpy_ros.model.link import Collision
    from urdfgenpy_ros.model.sensors import Lidar
    box = Inertial.from_box(1.0, 0.1, 0.1, 0.1)
    robot = Robot('scanner').add_link(Link('base_link', inertial=box)).add_link(
        Link('head', inertial=box)).add_link(Link('ear', inertial=box)).add_link(
        Link('wall', collisions=[Collision(Box(0.1, 4, 4))]))
    robot.add_joint(Joint('neck', 'revolute', 'base_link', 'head', axis=(0, 0, 1),
                          origin=Origin((0, 0, 1)), limit=JointLimit(-1, 1, effort=1, velocity=1)))
    robot.add_joint(Joint('ear_joint', 'fixed', 'head', 'ear', origin=Origin((0, 0.2, 0))))
    robot.add_joint(Joint('wall_joint', 'fixed', 'base_link', 'wall',
                          origin=Origin((2.05, 0, 1))))
    robot.get_link('head').add_sensor(Lidar('scan', samples=samples, min_angle=-1.2,
                                            max_angle=1.2, range_max=30.0))
    return robot


def test_a_lidars_sites_come_before_the_child_bodies_in_ray_order() -> None:
    import mujoco
    import numpy
    samples = 301
    text = write_mjcf(_scanning_head(samples)).text
    head = etree.fromstring(text.encode()).find('.//body[@name="head"]')
    tags = [child.tag for child in head if isinstance(child.tag, str)]
    assert tags.count('site') == samples and 'body' in tags
    assert tags.index('body') > max(i for i, tag in enumerate(tags) if tag == 'site')
    model = mujoco.MjModel.from_xml_string(text)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    sites = [model.site(f'scan_ray{index:03d}') for index in range(samples)]
    assert [site.id for site in sites] == sorted(site.id for site in sites)
    assert {int(site.bodyid[0]) for site in sites} == {model.body('head').id}
    for index, angle in enumerate(numpy.linspace(-1.2, 1.2, samples)):
        sensor = model.sensor(f'scan_ray{index:03d}')
        expected = 2.0 / math.cos(angle) if abs(2.0 * math.tan(angle)) < 2.0 else -1.0
        assert abs(data.sensordata[sensor.adr[0]] - expected) < 1e-9, index


def _box_stl(path: Path, low: tuple[float, ...], high: tuple[float, ...]) -> None:
    import trimesh
    box = trimesh.creation.box(bounds=(low, high))
    path.write_bytes(box.export(file_type='stl'))


def _touching_fingers(folder: Path) -> Path:
    """Write two fingers whose collision STLs touch at zero, and a visual-only STL shell."""
    _box_stl(folder / 'left.stl', (0.0, 0.0, 0.0), (0.02, 0.02, 0.1))
    _box_stl(folder / 'right.stl', (0.0, 0.0, 0.0), (0.02, 0.02, 0.1))
    _box_stl(folder / 'shell.stl', (-0.1, -0.1, -0.1), (0.1, 0.1, 0.1))
    inertial = ('<inertial><mass value="0.1"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" '
                'ixy="0" ixz="0" iyz="0"/></inertial>')

    def finger(name: str, side: float) -> str:
        return (f'<link name="{name}">{inertial}<visual><geometry><mesh filename="{name}.stl"/>'
                f'</geometry></visual><collision><geometry><mesh filename="{name}.stl"/>'
                f'</geometry></collision></link><joint name="{name}_joint" type="prismatic">'
                f'<parent link="palm"/><child link="{name}"/><origin xyz="{side} 0 0"/>'
                '<axis xyz="1 0 0"/><limit lower="-0.05" upper="0.05" effort="10" '
                'velocity="1"/></joint>')
    source = folder / 'hand.urdf'
    source.write_text(
        f'<robot name="hand"><link name="world"/><link name="palm">{inertial}<visual><geometry>'
        '<mesh filename="shell.stl"/></geometry></visual></link><joint name="mount" '
        'type="fixed"><parent link="world"/><child link="palm"/><origin xyz="0 0 1"/></joint>'
        f'{finger("left", -0.01)}{finger("right", 0.0)}</robot>')
    return source


def test_the_contact_model_is_given_only_the_files_its_collisions_read(
        tmp_path: Path, monkeypatch: Any) -> None:
    import mujoco
    compile_text = mujoco.MjModel.from_xml_string
    given: list[set[str]] = []

    def spy(text: str, assets: Any = None) -> Any:
        if '<worldbody' in text:  # the contact model, not a mesh file's verdict
            given.append(set(assets or {}))
        return compile_text(text, assets) if assets is not None else compile_text(text)
    monkeypatch.setattr(mujoco.MjModel, 'from_xml_string', staticmethod(spy))
    target = tmp_path / 'out' / 'hand.xml'
    write_mjcf(load(_touching_fingers(tmp_path)), target)
    monkeypatch.undo()
    assert given == [{'assets/left.stl', 'assets/right.stl'}]  # not the visual-only shell
    model = mujoco.MjModel.from_xml_path(str(target))  # MuJoCo judges the pairs excluded
    excluded = {frozenset((model.body(int(pair & 0xFFFF)).name,
                           model.body(int(pair >> 16)).name)) for pair in model.exclude_signature}
    tree = etree.parse(str(target))
    for exclude in tree.iter('exclude'):
        exclude.getparent().remove(exclude)
    tree.write(str(target))
    bare = mujoco.MjModel.from_xml_path(str(target))
    data = mujoco.MjData(bare)
    mujoco.mj_forward(bare, data)
    touching = {frozenset((bare.body(int(bare.geom_bodyid[contact.geom1])).name,
                           bare.body(int(bare.geom_bodyid[contact.geom2])).name))
                for contact in data.contact[:data.ncon]}
    assert frozenset(('left', 'right')) in touching and touching <= excluded


def test_a_converted_meshs_verdict_is_asked_once_a_process(tmp_path: Path,
                                                           monkeypatch: Any) -> None:
    import mujoco
    from urdfgenpy_ros.formats.mjcf import mesh_convert
    write_y_up_dae(tmp_path / 'part.dae')
    source = tmp_path / 'part.urdf'
    source.write_text('<robot name="part"><link name="base_link"><visual><geometry><mesh '
                      'filename="part.dae"/></geometry></visual></link></robot>')
    asked: list[int] = []
    verdict = mesh_convert.mujoco_refusal
    monkeypatch.setattr(mesh_convert, '_verdicts', {})  # this process may have asked before
    monkeypatch.setattr(mesh_convert, 'mujoco_refusal',
                        lambda name, data: asked.append(len(data)) or verdict(name, data))
    for number in range(3):
        target = tmp_path / f'out{number}' / 'part.xml'
        write_mjcf(load(source), target)
        model = mujoco.MjModel.from_xml_path(str(target))  # MuJoCo reads every OBJ written
        assert model.nmesh == 2 and model.nmeshface == 24  # its red and its blue part
    assert len(asked) == 2  # one verdict per OBJ, in the first write only
