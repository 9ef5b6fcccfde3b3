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
Picture ``check --format sarif`` on a Xacro robot, as a SARIF viewer shows it.

``python docs/sarif_picture.py --viewer DIR [--output FILE]`` (default:
docs/images/sarif-xacro.png). DIR is a folder, outside the repository, where
``npm install @microsoft/sarif-web-component@0.6.0-29 react@16.14.0 react-dom@16.14.0``
was run: Microsoft's SARIF viewer, loaded from its own UMD build on a local page. Optional
(npm is not part of the build or the tests); the committed PNG is what the docs show.

A two-file Xacro robot (a macro making a link and its joint, called twice, one call with
the axis ``0 0 2``) is checked; the SARIF gets a ``versionControlProvenance`` with a
made-up GitHub address, as code scanning knows the repository, so that the viewer turns
locations into ``blob/<commit>/FILE#LINE`` links. Chromium resolves no host but 127.0.0.1.
Needs the ``docs`` extra and Debian's ``chromium`` and ``chromium-driver``.
"""

from __future__ import annotations

import argparse
import functools
import http.server
import json
from pathlib import Path
import shutil
import sys
import tempfile
import threading
import time

from make_pictures import _free_port, _tool, _urdfgenpy, CHROMIUM_FLAGS, IMAGES

VIEWER = '@microsoft/sarif-web-component'
REPOSITORY = 'https://github.com/example/arm_description'
ROBOT = {
    'arm_macros.xacro': """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="segment" params="parent name length axis">
    <link name="${name}">
      <visual>
        <geometry><cylinder radius="0.03" length="${length}"/></geometry>
      </visual>
      <inertial>
        <mass value="0.5"/>
        <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.0002"/>
      </inertial>
    </link>
    <joint name="${name}_joint" type="revolute">
      <parent link="${parent}"/>
      <child link="${name}"/>
      <origin xyz="0 0 ${length}"/>
      <axis xyz="${axis}"/>
      <limit lower="-1.57" upper="1.57" effort="10" velocity="1"/>
    </joint>
  </xacro:macro>
</robot>
""",
    'arm.urdf.xacro': """<?xml version="1.0"?>
<robot name="arm" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="arm_macros.xacro"/>
  <link name="base_link">
    <inertial>
      <mass value="1.0"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>
    </inertial>
  </link>
  <xacro:segment parent="base_link" name="upper_arm" length="0.3" axis="0 1 0"/>
  <xacro:segment parent="upper_arm" name="forearm" length="0.25" axis="0 0 2"/>
</robot>
""",
}
PAGE = """<!DOCTYPE html>
<html><head><meta http-equiv="content-type" content="text/html; charset=utf-8">
<title>urdfgenpy SARIF</title>
<style>body{margin:0;font-family:sans-serif}
#links{margin:8px 32px;padding:10px 16px;font-size:13px;background:#fff;
box-shadow:0 1px 3px rgba(0,0,0,.2)}#links ul{margin:6px 0 0}</style>
</head><body><div id="root"></div><div id="links"></div>
<script src="node_modules/react/umd/react.production.min.js"></script>
<script src="node_modules/react-dom/umd/react-dom.production.min.js"></script>
<script src="node_modules/@microsoft/sarif-web-component/dist/index.js"></script>
<script>
window.caption = () => {
  const box = document.getElementById('links');
  box.innerHTML = '<b>The links @VIEWER@ made of the results</b> (read from its page; ' +
    'the repository is the SARIF\\'s <code>versionControlProvenance</code>):';
  const list = document.createElement('ul');
  for (const a of document.querySelectorAll('#root a[href]')) {
    const item = document.createElement('li');
    item.innerHTML = '<span></span> &rarr; <code></code>';
    item.firstChild.textContent = a.textContent;
    item.lastChild.textContent = a.href.replace(/blob\\/[0-9a-f]{40}/, 'blob/<commit>');
    list.appendChild(item);
  }
  box.appendChild(list);
};
fetch('arm.sarif').then(r => r.json()).then(log => ReactDOM.render(
  React.createElement(window.Viewer, {logs: [log], hideBaseline: true}),
  document.getElementById('root')));
</script></body></html>
"""


def _sarif(folder: Path) -> None:
    """Write the robot into ``folder`` and its ``check`` SARIF as ``arm.sarif``."""
    for name, text in ROBOT.items():
        (folder / name).write_text(text)
    _urdfgenpy('check', 'arm.urdf.xacro', '--format', 'sarif', '-o', 'arm.sarif', cwd=folder)
    log = json.loads((folder / 'arm.sarif').read_text())
    log['runs'][0]['versionControlProvenance'] = [{
        'repositoryUri': REPOSITORY, 'revisionId': '0' * 40,
        'mappedTo': {'uriBaseId': '%SRCROOT%'}}]
    (folder / 'arm.sarif').write_text(json.dumps(log, indent=2))


def _shoot(url: str, output: Path) -> None:
    """Open the page in headless Chromium, expand every rule, and save the screenshot."""
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    options.binary_location = _tool('chromium')
    profile = tempfile.mkdtemp(prefix='urdfgenpy-pictures-')
    for flag in (*CHROMIUM_FLAGS, f'--user-data-dir={profile}', '--window-size=1100,720',
                 '--host-resolver-rules=MAP * ~NOTFOUND , EXCLUDE 127.0.0.1'):
        options.add_argument(flag)
    driver = webdriver.Chrome(options=options, service=Service(_tool('chromedriver')))
    try:
        driver.get(url)
        deadline = time.monotonic() + 60
        while not driver.find_elements('css selector', '#root a[href]'):
            if time.monotonic() > deadline:
                raise RuntimeError(f'{VIEWER} showed no result at {url}')
            time.sleep(0.2)
        for row in driver.find_elements('css selector', '[role=row][aria-expanded=false]'):
            driver.execute_script('arguments[0].click()', row)
        time.sleep(1.0)
        driver.execute_script('window.caption()')
        output.write_bytes(driver.get_screenshot_as_png())
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)


def sarif_picture(viewer: Path, output: Path) -> str:
    """Screenshot the robot's SARIF in the viewer installed in ``viewer``; return its version."""
    package = viewer / 'node_modules' / VIEWER / 'package.json'
    if not package.is_file():
        sys.exit(f'sarif_picture: {package} not found (npm install {VIEWER} in {viewer})')
    version = json.loads(package.read_text())['version']
    with tempfile.TemporaryDirectory(prefix='urdfgenpy-sarif-') as scratch:
        folder = Path(scratch)
        _sarif(folder)
        (folder / 'index.html').write_text(PAGE.replace('@VIEWER@', f'{VIEWER} {version}'))
        (folder / 'node_modules').symlink_to((viewer / 'node_modules').resolve())
        handler = functools.partial(_QuietHandler, directory=str(folder))
        server = http.server.ThreadingHTTPServer(('127.0.0.1', _free_port()), handler)
        threading.Thread(target=server.serve_forever, daemon=True).start()
        try:
            _shoot(f'http://127.0.0.1:{server.server_port}/index.html', output)
        finally:
            server.shutdown()
            server.server_close()
    return version


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    """Serve the scratch folder without a log line per request."""

    def log_message(self, format: str, *args: object) -> None:  # noqa: A002
        """Say nothing."""


def main() -> None:
    """Parse the options and make the picture."""
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--viewer', type=Path, required=True,
                        help=f'folder where {VIEWER}, react@16 and react-dom@16 are installed')
    parser.add_argument('--output', type=Path, default=IMAGES / 'sarif-xacro.png',
                        help='PNG to write (default: docs/images/sarif-xacro.png)')
    arguments = parser.parse_args()
    version = sarif_picture(arguments.viewer, arguments.output)
    print(f'wrote {arguments.output} ({VIEWER} {version})')


if __name__ == '__main__':
    main()
