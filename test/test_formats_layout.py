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

"""An edit touches only what it changes, in the layout of the file it came from."""

from __future__ import annotations

import difflib
from pathlib import Path

from helpers import CORPUS, load_yourdfpy
import pytest
from registry_robots import robots as registry_robots

from urdfgenpy_ros import Box, Material, Origin, ParseError, Robot, Visual

FIXTURES = Path(__file__).parent / 'fixtures' / 'io'
LAYOUTS = sorted(FIXTURES.glob('*.urdf'))
ARM = [path for path in LAYOUTS if path.name not in ('one_line.urdf', 'exporter_style.urdf')]


def _changed(before: str, after: str) -> tuple[list[str], list[str]]:
    """Return the removed and the added lines between two texts."""
    diff = list(difflib.ndiff(before.splitlines(), after.splitlines()))
    return ([line[2:] for line in diff if line.startswith('- ')],
            [line[2:] for line in diff if line.startswith('+ ')])


def _source(path: Path) -> str:
    return path.read_bytes().decode()


@pytest.mark.parametrize('path', LAYOUTS, ids=[path.name for path in LAYOUTS])
def test_unedited_file_is_written_back_byte_for_byte(path: Path) -> None:
    """Reading and writing an unedited file gives the file (quotes and line ends too)."""
    assert Robot.from_urdf(path).to_urdf() == _source(path)


def _set_mass(robot: Robot) -> tuple[str, str]:
    robot.get_link('base_link').inertial.mass = 7.25
    return 'mass value', '7.25'


def _set_limit(robot: Robot) -> tuple[str, str]:
    robot.get_joint('shoulder_lift').limit.upper = 1.25
    return 'upper', '1.25'


def _set_visual_origin(robot: Robot) -> tuple[str, str]:
    visual = robot.get_link('shoulder').visuals[1]
    visual.origin = Origin((0.0, 0.0, 0.5))
    visual.origin = Origin((0.0, 0.0, 0.125))
    return 'origin', '0 0 0.125'


def _set_joint_origin(robot: Robot) -> tuple[str, str]:
    robot.get_joint('elbow').origin = Origin((0.0, 0.0, 0.35))
    return 'origin', '0 0 0.35'


def _set_box(robot: Robot) -> tuple[str, str]:
    robot.get_link('base_link').collisions[0].geometry = Box(0.5, 0.32, 0.1)
    return 'box size', '0.5 0.32 0.1'


def _rename_link(robot: Robot) -> tuple[str, str]:
    robot.rename_link('finger', 'digit')
    return 'link name', 'digit'


EDITS = [_set_mass, _set_limit, _set_visual_origin, _set_joint_origin, _set_box]


@pytest.mark.parametrize('edit', EDITS, ids=[edit.__name__[1:] for edit in EDITS])
@pytest.mark.parametrize('path', ARM, ids=[path.name for path in ARM])
def test_a_scalar_edit_changes_one_line(path: Path, edit, tmp_path: Path) -> None:
    """One edited value is one changed line, whatever the indentation."""
    robot = Robot.from_urdf(path)
    needle, value = edit(robot)
    text = robot.to_urdf(tmp_path / 'out.urdf')
    removed, added = _changed(_source(path), text)
    assert len(removed) == len(added) == 1, (removed, added)
    assert needle in added[0] and value in added[0]
    assert added[0].replace(value, '') != removed[0]
    assert added[0].endswith(' />') == removed[0].endswith(' />')  # the file's own style
    load_yourdfpy(tmp_path / 'out.urdf')  # and another reader accepts it


def test_an_edit_in_an_exporter_style_file_touches_only_the_edited_element(
        tmp_path: Path) -> None:
    """Attributes on lines of their own (as CAD exporters write them) stay so elsewhere."""
    path = FIXTURES / 'exporter_style.urdf'
    robot = Robot.from_urdf(path)
    robot.get_link('arm').inertial.mass = 0.75
    text = robot.to_urdf(tmp_path / 'out.urdf')
    removed, added = _changed(_source(path), text)
    assert [line.strip() for line in removed] == ['value="0.5" />']
    assert [line.strip() for line in added] == ['value="0.75" />']  # its ' />' kept
    arm = next(link for link in load_yourdfpy(tmp_path / 'out.urdf').links if link.name == 'arm')
    assert arm.inertial.mass == 0.75


def test_edited_values_stay_on_their_own_lines_in_the_sources_quotes(tmp_path: Path) -> None:
    """Each edited value is one changed line; a new attribute puts the tag on one line."""
    source = ("<robot name='r'>\n  <link name='a'>\n    <inertial>\n      <mass\n"
              "        value='1' />\n      <inertia\n        ixx='1' ixy='0' ixz='0'\n"
              "        iyy='1' iyz='0' izz='1'\n        note='&#x41;&amp;b' />\n"
              "    </inertial>\n  </link>\n  <link name='b' />\n"
              "  <joint name='j' type='revolute'>\n    <parent link='a' />\n"
              "    <child link='b' />\n    <limit\n      effort='10'\n"
              "      upper='1'\n      velocity='2' />\n  </joint>\n</robot>\n")
    robot = Robot.from_urdf_string(source)
    robot.get_link('a').inertial.mass = 2.5
    robot.get_link('a').inertial.iyy = 0.5
    robot.get_joint('j').limit.effort = 20.0
    text = robot.to_urdf(tmp_path / 'out.urdf')
    assert _changed(source, text) == (
        ["        value='1' />", "        iyy='1' iyz='0' izz='1'", "      effort='10'"],
        ["        value='2.5' />", "        iyy='0.5' iyz='0' izz='1'", "      effort='20'"])
    model = load_yourdfpy(tmp_path / 'out.urdf')
    link, joint = model.links[0], model.joints[0]
    assert (link.inertial.mass, link.inertial.inertia[1][1]) == (2.5, 0.5)
    assert joint.limit.effort == 20.0
    robot.get_joint('j').limit.lower = -0.5  # an attribute the tag did not have
    removed, added = _changed(source, robot.to_urdf(tmp_path / 'out.urdf'))
    assert added[-1].strip() == \
        "<limit effort='20' upper='1' velocity='2' lower='-0.5' />"
    assert load_yourdfpy(tmp_path / 'out.urdf').joints[0].limit.lower == -0.5


def test_renaming_a_link_changes_only_the_lines_naming_it(tmp_path: Path) -> None:
    """The link's own line and the joint end that names it, nothing else."""
    path = FIXTURES / 'four_space.urdf'
    robot = Robot.from_urdf(path)
    _rename_link(robot)
    removed, added = _changed(_source(path), robot.to_urdf())
    assert removed == ['    <link name="finger">', '        <child link="finger"/>']
    assert added == ['    <link name="digit">', '        <child link="digit"/>']


@pytest.mark.parametrize('edit', [_set_mass, _set_visual_origin, _set_joint_origin])
def test_a_scalar_edit_changes_one_line_of_a_one_line_file(edit, tmp_path: Path) -> None:
    """In a file of one-line elements, the edited element stays on its line."""
    path = FIXTURES / 'one_line.urdf'
    robot = Robot.from_urdf(path)
    if edit is _set_mass:
        robot.get_link('chassis').inertial.mass = 7.25
        value = "value='7.25'"
    elif edit is _set_visual_origin:
        robot.get_link('lidar').visuals[0].origin = Origin((0.0, 0.0, 0.5))
        robot.get_link('lidar').visuals[0].origin = Origin((0.0, 0.0, 0.125))
        value = "xyz='0 0 0.125'"
    else:
        robot.get_joint('lidar_joint').origin = Origin((0.25, 0.0, 0.2))
        value = "xyz='0.25 0 0.2'"
    text = robot.to_urdf(tmp_path / 'out.urdf')
    removed, added = _changed(_source(path), text)
    assert len(removed) == len(added) == 1, (removed, added)
    assert value in added[0]
    load_yourdfpy(tmp_path / 'out.urdf')


def test_added_visual_takes_the_file_layout() -> None:
    """A visual built in Python is indented like its neighbours (tabs here)."""
    path = FIXTURES / 'tab.urdf'
    robot = Robot.from_urdf(path)
    robot.get_link('tool').add_visual(Visual(Box(0.1, 0.1, 0.1)))
    removed, added = _changed(_source(path), robot.to_urdf())
    assert removed == ['\t<link name="tool"/>']
    assert added == ['\t<link name="tool">', '\t\t<visual>', '\t\t\t<geometry>',
                     '\t\t\t\t<box size="0.1 0.1 0.1"/>', '\t\t\t</geometry>', '\t\t</visual>',
                     '\t</link>']


def test_attribute_less_elements_survive(tmp_path: Path) -> None:
    """``<texture/>`` stays as written: yourdfpy sees no file name, not ''."""
    source = FIXTURES / 'two_space.urdf'
    robot = Robot.from_urdf(source)
    assert '<texture/>' in robot.to_urdf()
    robot.rename_material('decal', 'sticker')  # an edited material keeps it too
    text = robot.to_urdf(tmp_path / 'out.urdf')
    removed, added = _changed(_source(source), text)
    assert removed == ['  <material name="decal">', '      <material name="decal"/>']
    assert added == ['  <material name="sticker">', '      <material name="sticker"/>']
    theirs = {material.name: material for material in load_yourdfpy(tmp_path / 'out.urdf')
              .materials}
    assert theirs['sticker'].texture.filename is None


def test_texture_built_in_python_without_a_file(tmp_path: Path) -> None:
    """A material whose texture is '' is written ``<texture/>`` too."""
    robot = Robot('bare')
    robot.add_material(Material('plain', texture=''))
    assert '<texture/>' in robot.to_urdf()


def test_an_edited_block_of_a_copied_robot_is_written(tmp_path: Path) -> None:
    """Blocks edited in place count, also in a deep copy of a read robot."""
    import copy
    robot = copy.deepcopy(Robot.from_urdf(FIXTURES / 'two_space.urdf'))
    robot.extensions[0].element.set('name', 'wrist_transmission')
    removed, added = _changed(_source(FIXTURES / 'two_space.urdf'), robot.to_urdf())
    assert removed == ['  <transmission name="pan_transmission">']
    assert added == ['  <transmission name="wrist_transmission">']


_END_TAGS = """<?xml version="1.0"?>
<robot name="end_tags">
  <link name="world"></link>
  <link name="base">
    <visual>
      <geometry><box size="0.1 0.2 0.3"></box></geometry>
    </visual>
  </link>
  <joint name="fixed_base" type="fixed">
    <parent link="world"></parent>
    <child link="base"/>
    <origin xyz="0 0 0.5"></origin>
  </joint>
  <gazebo reference="base">
    <self_collide>true</self_collide>
    <sensor_hint></sensor_hint>
  </gazebo>
</robot>
"""


def test_empty_elements_written_with_end_tags_survive(tmp_path: Path) -> None:
    """``<link></link>`` comes back as written (lxml alone writes ``<link/>``); edits too."""
    robot = Robot.from_urdf_string(_END_TAGS)
    assert robot.to_urdf() == _END_TAGS
    robot.get_joint('fixed_base').origin = Origin((0.0, 0.0, 0.75))
    text = robot.to_urdf(tmp_path / 'out.urdf')
    removed, added = _changed(_END_TAGS, text)
    assert removed == ['    <origin xyz="0 0 0.5"></origin>']
    assert added == ['    <origin xyz="0 0 0.75"></origin>']
    theirs = load_yourdfpy(tmp_path / 'out.urdf')
    assert [link.name for link in theirs.links] == ['world', 'base']
    assert theirs.joints[0].origin[2][3] == 0.75


def test_an_empty_block_element_given_children_is_written_open() -> None:
    """An element read as ``<x></x>`` that gets a child is written with it, as valid XML."""
    from lxml import etree
    robot = Robot.from_urdf_string(_END_TAGS)
    hint = robot.get_link('base').extensions[0].element.find('sensor_hint')
    etree.SubElement(hint, 'rate').text = '10'
    written = etree.fromstring(robot.to_urdf().encode())
    assert written.find('gazebo/sensor_hint/rate').text == '10'
    assert written.find('link').get('name') == 'world'


@pytest.mark.parametrize('gap, end', [('\n\n', '\n\n'), ('\n', ''), ('\n\n\n', '\n  \n'),
                                      (' ', '')])
def test_white_space_around_the_root_is_kept(gap: str, end: str, tmp_path: Path) -> None:
    source = (f'<?xml version="1.0"?>{gap}<robot name="r">\n  <link name="a">\n'
              f'    <inertial>\n      <mass value="1"/>\n'
              '      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>\n'
              f'    </inertial>\n  </link>\n</robot>{end}')
    robot = Robot.from_urdf_string(source)
    assert robot.to_urdf() == source
    robot.links[0].inertial.mass = 2.0
    edited = robot.to_urdf()
    assert _changed(source, edited) == (['      <mass value="1"/>'], ['      <mass value="2"/>'])
    assert edited.endswith(f'</robot>{end}') and f'?>{gap}<robot' in edited
    path = tmp_path / 'edited.urdf'
    path.write_bytes(edited.encode())
    assert load_yourdfpy(path).links[0].inertial.mass == 2.0


@pytest.mark.parametrize('before', [
    '<!-- c1 -->\n\n', '\n<!-- c1 -->\n<?pi x?>\n\n\n<!-- c2 -->  ', ''])
def test_comments_before_the_root_keep_their_blank_lines(before: str) -> None:
    for declaration in ('<?xml version="1.0"?>\n', ''):
        source = f'{declaration}{before}<robot name="r">\n  <link name="a"/>\n</robot>\n'
        robot = Robot.from_urdf_string(source)
        assert robot.to_urdf() == source
        robot.get_link('a').name = 'b'
        assert _changed(source, robot.to_urdf()) == (['  <link name="a"/>'],
                                                     ['  <link name="b"/>'])


def test_a_line_break_inside_a_value_does_not_decide_the_files_line_ends() -> None:
    """An exporter's CRLF inside an attribute of an LF file (Unitree's hand files)."""
    text = ('<robot name="r">\n  <link name="a">\n    <inertial>\n      <mass value="1" />\n'
            '      <inertia ixx="0.1" ixy="0" ixz="0.0\r\n" iyy="0.1" iyz="0" izz="0.1" />\n'
            '    </inertial>\n  </link>\n</robot>\n')
    robot = Robot.from_urdf_string(text)
    assert robot.to_urdf() == text
    robot.get_link('a').inertial.mass = 2.0
    removed, added = _changed(text, robot.to_urdf())
    assert removed == ['      <mass value="1" />'] and added == ['      <mass value="2" />']


_ATTRIBUTES_ON_LINES = """<?xml version="1.0"?>
<robot name="lines">
  <link
    name="base"/>
  <link name="arm"></link>
  <joint name="j" type="fixed"><parent link="base"/><child link="arm"/></joint>
  <gazebo
    reference="arm">
    <material>Gazebo/Red</material>
  </gazebo>
</robot>
"""


def test_a_block_edited_before_the_first_write_is_written_edited() -> None:
    """A source node changed in place before anything was written keeps its change."""
    from lxml import etree
    robot = Robot.from_urdf_string(_ATTRIBUTES_ON_LINES)
    block = robot.get_link('arm').extensions[0]
    block.element.set('reference', 'arm')  # the same value, set again
    block.element.set('name', 'tip')
    etree.SubElement(block.element, 'self_collide').text = 'true'
    written = etree.fromstring(robot.to_urdf().encode())
    assert [dict(node.attrib) for node in written.iter('gazebo')] == [
        {'reference': 'arm', 'name': 'tip'}]
    assert written.find('gazebo/self_collide').text == 'true'
    text = Robot.from_urdf_string(_ATTRIBUTES_ON_LINES).to_urdf()
    assert text == _ATTRIBUTES_ON_LINES


@pytest.mark.parametrize('wrapper', ['<urdf>', '<urdf xmlns:foo="http://foo">'])
def test_a_wrapped_robot_is_written_without_its_wrapper(wrapper: str) -> None:
    """The inner ``<robot>`` as it was written; a namespace the wrapper declared comes along."""
    from lxml import etree
    inner = ('  <robot name="r">\n    <link name="a"><foo:bar/></link>\n  </robot>'
             if 'foo' in wrapper else '  <robot name="r">\n    <link name="a"/>\n  </robot>')
    source = f'<?xml version="1.0"?>\n{wrapper}\n{inner}\n</urdf>\n'
    text = Robot.from_urdf_string(source).to_urdf()
    written = etree.fromstring(text.encode())
    assert written.tag == 'robot' and [link.get('name') for link in written] == ['a']
    if 'foo' in wrapper:
        assert written[0][0].tag == '{http://foo}bar'
    else:
        assert text == f'<?xml version="1.0"?>\n{inner[2:]}\n'


def test_an_element_added_before_the_first_write_moves_no_tag_onto_another() -> None:
    """Start tags are found by place in the file: a tree changed since keeps its names."""
    from lxml import etree
    source = ('<robot name="r">\n  <link name="a"/>\n  <gazebo reference="a">\n'
              '    <p k="1"/>\n    <q\n      k="1"/>\n  </gazebo>\n</robot>\n')
    robot = Robot.from_urdf_string(source)
    block = robot.get_link('a').extensions[0].element
    block.insert(0, etree.Element('new'))
    written = etree.fromstring(robot.to_urdf().encode())
    assert [(node.tag, dict(node.attrib)) for node in written.find('gazebo')] == [
        ('new', {}), ('p', {'k': '1'}), ('q', {'k': '1'})]


def test_an_edit_after_a_write_is_written() -> None:
    """A write leaves nothing behind that a later write of an edited robot would reuse."""
    robot = Robot.from_urdf_string(_ATTRIBUTES_ON_LINES)
    assert robot.to_urdf() == _ATTRIBUTES_ON_LINES
    robot.get_link('arm').extensions[0].element.set('name', 'tip')
    assert '<gazebo reference="arm" name="tip">' in robot.to_urdf()


_REAL_URDFS = [*(path for path in sorted((FIXTURES.parent).rglob('*.urdf'))
                 if path.parent.name != 'broken'),
               *registry_robots(),
               *(sorted(CORPUS.rglob('*.urdf')) if CORPUS.is_dir() else [])]


def _plain_subtree(node) -> bool:
    """Return whether no tag or attribute below ``node`` has a namespace."""
    from lxml import etree
    return all(isinstance(item.tag, str) and '{' not in item.tag and ':' not in item.tag
               and not any('{' in key or ':' in key for key in item.attrib)
               for item in node.iter(etree.Element))


def test_every_node_of_a_real_file_has_the_span_lxml_reads_back() -> None:
    """The scanner's span of each element, parsed by lxml on its own, is that element."""
    from lxml import etree

    from urdfgenpy_ros.formats.source_record import Spans

    compared = 0
    for path in _REAL_URDFS:
        try:
            robot = Robot.from_urdf(path)
        except (ParseError, OSError):
            continue
        document = robot.extras
        top = document.node.getroottree().getroot()
        spans = Spans(document.text, top)
        nodes = [*top.itersiblings(preceding=True), *top.iter(), *top.itersiblings()]
        assert all(spans.get(node) is not None for node in nodes), path
        assert not spans.loose, path
        for node in top.iter(etree.Element):
            if not _plain_subtree(node):
                continue
            span = spans.get(node)
            alone = etree.fromstring(document.text[span.start:span.end].encode())
            copy = etree.fromstring(etree.tostring(node, with_tail=False))
            assert etree.tostring(alone, method='c14n', exclusive=True) == \
                etree.tostring(copy, method='c14n', exclusive=True), (path, node.sourceline)
            compared += 1
    assert compared > 1000


def test_many_unusual_start_tags_are_all_kept() -> None:
    """A file whose every tag is unusual (spaces, single quotes) is written as read; edits too."""
    links = ''.join(f"  <link  name='l{index}'>\n    <visual>\n      <geometry><box size='1 1 1'"
                    f'/></geometry>\n    </visual>\n  </link>\n' for index in range(40))
    source = "<robot  name='r'>\n" + links + '</robot>\n'
    robot = Robot.from_urdf_string(source)
    assert robot.to_urdf() == source
    robot.get_link('l7').visuals[0].geometry = Box(1.0, 1.0, 2.0)
    assert _changed(source, robot.to_urdf()) == (
        ["      <geometry><box size='1 1 1'/></geometry>"],
        ["      <geometry><box size='1 1 2'/></geometry>"])


def test_an_unedited_file_keeps_its_own_spelling_of_characters() -> None:
    """Character references and ``<x />`` tags come back as written, not as lxml writes them."""
    source = ('<?xml version="1.0"?>\n<robot name="r">\n  <link name="a" />\n'
              '  <gazebo reference="a">\n    <plugin>x &quot;&#x41;&quot; &gt; y</plugin>\n'
              '  </gazebo>\n</robot>\n')
    robot = Robot.from_urdf_string(source)
    assert robot.to_urdf() == source
    assert robot.to_urdf() == source  # and again
    robot.get_link('a').extensions[0].element[0].text = 'z'
    assert '<plugin>z</plugin>' in robot.to_urdf()  # an edit since is written


def test_a_file_in_another_encoding_keeps_its_characters(tmp_path: Path) -> None:
    """A Latin-1 file comes back in Latin-1; a character it cannot hold makes it UTF-8."""
    from lxml import etree
    source = ('<?xml version="1.0" encoding="ISO-8859-1"?>\n<robot name="r">\n'
              '  <!-- pi\xe8ce \xe0 main -->\n  <link name="a" />\n</robot>\n').encode('latin-1')
    path = tmp_path / 'latin.urdf'
    path.write_bytes(source)
    robot = Robot.from_urdf(path)
    text = robot.to_urdf(tmp_path / 'out.urdf')
    assert '\ufffd' not in text and 'pi\xe8ce \xe0 main' in text
    assert (tmp_path / 'out.urdf').read_bytes() == source
    assert Robot.from_urdf_string(text).to_urdf() == text  # a string read as it declares
    robot.rename_link('a', 'b\u20ac')
    robot.to_urdf(tmp_path / 'euro.urdf')
    written = etree.parse(str(tmp_path / 'euro.urdf')).getroot()
    assert written[0].text == ' pi\xe8ce \xe0 main ' and written[1].get('name') == 'b\u20ac'
    assert Robot.from_urdf(tmp_path / 'euro.urdf').links[0].name == 'b\u20ac'


def test_text_spelled_with_references_stays_so_when_something_else_is_edited() -> None:
    """A block's ``&quot;`` (Kinova's ros2_control params) is no changed line of an edit."""
    from lxml import etree
    source = ('<robot name="r">\r\n  <link name="a">\r\n    <inertial>\r\n'
              '      <mass value="1"/>\r\n      <inertia ixx="1" ixy="0" ixz="0" iyy="1" '
              'iyz="0" izz="1"/>\r\n    </inertial>\r\n  </link>\r\n'
              '  <ros2_control name="c" type="system">\r\n    <hardware>\r\n'
              '      <param name="prefix">&quot;&quot;</param>\r\n'
              '      <param name="ip">&#x31;0.0.0.&#49;</param>\r\n'
              "      <param name='q'>it&apos;s &gt; &amp;\r\n two lines</param>\r\n"
              '      <param name="plain">a &gt; b</param>\r\n'
              '    </hardware>\r\n  </ros2_control>\r\n</robot>\r\n')
    robot = Robot.from_urdf_string(source)
    robot.get_link('a').inertial.mass = 2.0
    written = robot.to_urdf()
    assert _changed(source, written) == (['      <mass value="1"/>'], ['      <mass value="2"/>'])
    before = etree.fromstring(source.encode())
    after = etree.fromstring(written.encode())
    assert [node.text for node in after.iter('param')] == \
        [node.text for node in before.iter('param')]  # as lxml reads them: the same
    params = robot.extensions[0].element[0]
    params[1].text = '10.0.0.2'  # a text edited in place is written edited
    params.insert(0, etree.Element('param'))  # and the places of the others move
    written = robot.to_urdf()
    assert '<param name="ip">10.0.0.2</param>' in written
    assert '<param name="prefix">&quot;&quot;</param>' in written
    assert [node.text for node in etree.fromstring(written.encode()).iter('param')] == \
        [None, '""', '10.0.0.2', "it's > &\n two lines", 'a > b']


def test_a_byte_order_mark_is_kept_in_the_file_not_in_the_text(tmp_path: Path) -> None:
    """Windows editors start UTF-8 files with a BOM: it comes back, edited or not."""
    from lxml import etree
    source = b'\xef\xbb\xbf<?xml version="1.0"?>\r\n<robot name="r">\r\n  <link name="a"/>\r\n' \
        b'</robot>\r\n'
    path = tmp_path / 'bom.urdf'
    path.write_bytes(source)
    robot = Robot.from_urdf(path)
    assert robot.to_urdf(tmp_path / 'out.urdf').startswith('<?xml')  # text: no BOM
    assert (tmp_path / 'out.urdf').read_bytes() == source
    robot.rename_link('a', 'b')
    robot.to_urdf(tmp_path / 'out.urdf')
    assert (tmp_path / 'out.urdf').read_bytes() == source.replace(b'"a"', b'"b"')
    assert etree.parse(str(tmp_path / 'out.urdf')).getroot()[0].get('name') == 'b'


def test_a_mended_declaration_changes_only_its_own_line() -> None:
    """A declaration like pybullet's ``version="0.0"`` is mended (P102); what follows stays."""
    source = ('<?xml version="0.0" ?>\n<!-- c -->\n\n<robot name="r">\n  <link name="a"/>\n'
              '</robot>\n')
    robot = Robot.from_urdf_string(source)
    assert [warning.code for warning in robot.read_warnings] == ['P102']
    assert _changed(source, robot.to_urdf()) == (['<?xml version="0.0" ?>'],
                                                 ['<?xml version="1.0"?>'])
