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

"""Each front end's messages name its own options: init's, the node's parameters."""

from __future__ import annotations

import os
from pathlib import Path
import subprocess
import sys

from helpers import REPO, require_module
import pytest

from urdfgenpy_ros.formats import open_description
from urdfgenpy_ros.model.errors import PACKAGE_FOLDER, UrdfgenpyError
from urdfgenpy_ros.publisher import NODE_WORDS
from urdfgenpy_ros.scaffold.command import main as init

XACRO = """<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base_link"><visual><geometry>
    <mesh filename="$(find no_such_description)/meshes/base.stl"/></geometry></visual></link>
</robot>
"""


@pytest.mark.parametrize('options, said', [
    (['--from', 'missing.urdf'], '--from: missing.urdf does not exist'),
    (['--from', 'robot.urdf.xacro', '--xacro-args', 'oops'], "--xacro-args: 'oops'"),
    (['--from', 'robot.urdf.xacro'], 'search_paths / --package-path'),
])
def test_init_names_its_own_options(options: list[str], said: str, tmp_path: Path,
                                    monkeypatch: pytest.MonkeyPatch,
                                    capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / 'robot.urdf.xacro').write_text(XACRO)
    assert init(['r_description', *options]) == 2
    err = capsys.readouterr().err
    assert said in err and 'parameter' not in err


def test_the_node_names_its_parameter_for_package_folders(tmp_path: Path) -> None:
    (tmp_path / 'robot.urdf.xacro').write_text(XACRO)
    with pytest.raises(UrdfgenpyError) as raised:
        open_description(str(tmp_path / 'robot.urdf.xacro'))
    said = NODE_WORDS.said(raised.value)  # as the node says it
    assert "parameter 'package_paths'" in said and '--package-path' not in said
    assert raised.value.fixes == (PACKAGE_FOLDER,)  # the fix, as data
    assert PACKAGE_FOLDER.text in str(raised.value)  # in the library's own words


def test_init_from_a_module_in_the_current_folder(tmp_path: Path) -> None:
    """The console script's own folder is on its path, not the user's: still found."""
    (tmp_path / 'cwd_bot_maker.py').write_text(
        'from urdfgenpy_ros import Link, Robot\n\n\n'
        'def build():\n    return Robot("cwd_bot").add_link(Link("base_link"))\n')
    script = Path(sys.executable).with_name('urdfgenpy')
    env = dict(os.environ, PYTHONPATH=str(REPO))
    result = subprocess.run([str(script), 'init', 'cwd_bot_description', '--from',
                             'cwd_bot_maker:build'], cwd=tmp_path, capture_output=True,
                            text=True, timeout=120, env=env)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / 'cwd_bot_description' / 'urdf' / 'cwd_bot.urdf.xacro').is_file()


def test_init_refuses_a_package_path_that_does_not_exist_as_check_does(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from click.testing import CliRunner
    from urdfgenpy_ros.cli import main
    missing = str(tmp_path / 'nowhere')
    checked = CliRunner().invoke(main, ['check', '--package-path', missing, str(tmp_path)])
    assert checked.exit_code == 2 and 'does not exist' in checked.stderr
    assert init(['r_description', '--package-path', missing, '--destination-directory',
                 str(tmp_path)]) == 2
    assert f'--package-path {missing}: no such folder' in capsys.readouterr().err
    assert not (tmp_path / 'r_description').exists()


def test_one_fix_as_data_each_front_end_in_its_own_words(tmp_path: Path) -> None:
    from urdfgenpy_ros.cli.words import CLI_WORDS
    from urdfgenpy_ros.report import LIBRARY
    from urdfgenpy_ros.resources import PackageResolver, ResourceError
    with pytest.raises(ResourceError) as raised:
        PackageResolver([tmp_path]).resolve('package://no_such_description/a.stl')
    error = raised.value
    assert error.fixes == (PACKAGE_FOLDER,) and PACKAGE_FOLDER.names == 'package_paths'
    assert LIBRARY.said(error) == str(error)  # Python callers: the library's words
    assert CLI_WORDS.said(error).endswith('or pass its folder with -p/--package-path)')
    assert NODE_WORDS.said(error).endswith(
        "or pass its folder in search_paths / parameter 'package_paths')")
    assert CLI_WORDS.line(error) == f'urdfgenpy: {CLI_WORDS.said(error)}'


def test_the_front_door_refuses_an_input_naming_it_in_each_front_ends_words() -> None:
    from urdfgenpy_ros.model.errors import InputError
    from urdfgenpy_ros.report import FrontEnd
    from urdfgenpy_ros.scaffold import INIT_INPUTS
    with pytest.raises(InputError) as raised:
        open_description('robot.urdf', ['use_sim=true'])
    assert (raised.value.where, raised.value.value) == ('source', 'robot.urdf')
    arm = REPO / 'test' / 'fixtures' / 'packages' / 'fixture_description' / 'urdf'
    with pytest.raises(InputError) as raised:
        open_description(str(arm / 'arm.urdf.xacro'), ['oops'])
    error = raised.value
    assert (error.where, error.value, str(error)) == (
        'args', 'oops', "args: 'oops' is not name:=value")
    assert NODE_WORDS.said(error) == "parameter 'xacro_args': 'oops' is not name:=value"
    assert FrontEnd('urdfgenpy init', inputs=INIT_INPUTS).line(error) == (
        "urdfgenpy init: --xacro-args: 'oops' is not name:=value")


def test_the_viewer_of_urdfgenpy_view_says_the_fix_as_the_command_line(tmp_path: Path) -> None:
    require_module('viser')
    from browser import free_port
    from urdfgenpy_ros.cli.words import CLI_WORDS
    from urdfgenpy_ros.viewer.web import RobotViewer
    path = tmp_path / 'robot.urdf'
    path.write_text('<robot name="r"><link name="base_link"><visual><geometry><mesh '
                    'filename="package://no_such_description/a.stl"/></geometry></visual>'
                    '</link></robot>')
    viewer = RobotViewer(lambda: open_description(path), port=free_port(),
                         words=CLI_WORDS.worded)
    try:
        missing = next(finding for finding in viewer.findings if finding.code == 'R303')
        assert PACKAGE_FOLDER.text in missing.hint  # the review's own words
        viewer.select(missing)
        assert 'pass its folder with -p/--package-path' in viewer._selection.content
        path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                        '<xacro:include filename="$(find no_such_description)/a.xacro"/>'
                        '<link name="base_link"/></robot>')  # a reload that fails
        assert viewer.reload() is False
        assert viewer.status.endswith('or pass its folder with -p/--package-path)')
    finally:
        viewer.close()
