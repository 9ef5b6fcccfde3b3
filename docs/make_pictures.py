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
Make the documentation's pictures with the package's own commands.

``python docs/make_pictures.py [--output DIR]`` (default: docs/images) writes, for the
example pan-tilt unit:

- ``ptu.png``: ``urdfgenpy render`` at pan 0.6, tilt 0.5;
- ``ptu_tree.svg``: ``urdfgenpy graph``;
- ``viewer.png``: ``urdfgenpy view`` in headless Chromium (Debian's ``chromium`` and
  ``chromium-driver``, Selenium from the ``docs`` extra), once the robot is drawn.

Needs the ``view`` and ``docs`` extras. A missing piece is one line naming it, exit 2.
``sarif-xacro.png`` (a SARIF viewer's page) is made apart by ``docs/sarif_picture.py``,
which needs npm.
"""

from __future__ import annotations

import argparse
import io
import os
from pathlib import Path
import shutil
import socket
import subprocess
import sys
import tempfile
import time
from typing import Any

IMAGES = Path(__file__).resolve().parent / 'images'
CHROMIUM_FLAGS = ('--headless', '--no-sandbox', '--disable-gpu', '--no-first-run',
                  '--disable-background-networking', '--disable-component-update',
                  '--disable-sync', '--enable-unsafe-swiftshader', '--window-size=1200,760')


def _urdfgenpy(*arguments: str, cwd: Path) -> None:
    """Run ``urdfgenpy`` (the one beside this Python) and stop on failure."""
    command = [str(Path(sys.executable).parent / 'urdfgenpy'), *arguments]
    if not Path(command[0]).is_file():
        command = [sys.executable, '-m', 'urdfgenpy_ros.cli', *arguments]
    subprocess.run(command, cwd=cwd, check=True, capture_output=True, text=True, timeout=300)


def _free_port() -> int:
    """Return a TCP port nobody listens on now."""
    with socket.socket() as probe:
        probe.bind(('127.0.0.1', 0))
        return int(probe.getsockname()[1])


def _tool(name: str) -> str:
    """Return the path of a command the screenshot needs, or exit naming its package."""
    found = shutil.which(name)
    if found is None:
        sys.exit(f'make_pictures: {name} not found (apt install chromium chromium-driver)')
    return found


def _drawn(png: bytes) -> bool:
    """Return whether a screenshot shows more than a blank canvas."""
    from PIL import Image, ImageStat
    image = Image.open(io.BytesIO(png)).convert('L')
    return max(ImageStat.Stat(image).stddev) > 20.0


def _screenshot(url: str, output: Path, timeout: float = 120.0) -> None:
    """Open ``url`` in headless Chromium and save the page once the robot is drawn."""
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        sys.exit("make_pictures: selenium not installed (pip install -e '.[docs]')")
    options = webdriver.ChromeOptions()
    options.binary_location = _tool('chromium')
    profile = tempfile.mkdtemp(prefix='urdfgenpy-pictures-')
    for flag in (*CHROMIUM_FLAGS, f'--user-data-dir={profile}'):
        options.add_argument(flag)
    driver = webdriver.Chrome(options=options, service=Service(_tool('chromedriver')))
    try:
        driver.get(url)
        deadline = time.monotonic() + timeout
        canvas: Any = None
        while time.monotonic() < deadline:
            canvases = driver.find_elements('css selector', 'canvas')
            sliders = driver.find_elements('css selector', '[role=slider]')
            if canvases and sliders and _drawn(canvases[0].screenshot_as_png):
                canvas = canvases[0]
                break
            time.sleep(0.5)
        if canvas is None:
            raise RuntimeError(f'the viewer at {url} drew nothing in {timeout} s')
        for button in driver.find_elements('css selector', '.mantine-Notification-root button'):
            driver.execute_script('arguments[0].click()', button)  # the WebGL notice
        previous = b''
        while time.monotonic() < deadline:  # the scene fades in: wait until it stops changing
            time.sleep(1.0)
            frame = canvas.screenshot_as_png
            if frame == previous:
                break
            previous = frame
        output.write_bytes(driver.get_screenshot_as_png())
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)


def _view(robot: Path, output: Path) -> None:
    """Serve ``robot`` with ``urdfgenpy view`` and screenshot the page."""
    port = _free_port()
    command = [str(Path(sys.executable).parent / 'urdfgenpy'), 'view', robot.name,
               '--port', str(port)]
    server = subprocess.Popen(command, cwd=robot.parent, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True,
                              env={**os.environ, 'PYTHONUNBUFFERED': '1'})
    try:
        assert server.stdout is not None
        line = server.stdout.readline()
        if 'http://' not in line:
            raise RuntimeError(f'urdfgenpy view did not start: {line}{server.stdout.read()}')
        _screenshot(f'http://127.0.0.1:{port}', output)
    finally:
        server.terminate()
        try:
            server.wait(timeout=20)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()


def make_pictures(output: Path) -> list[Path]:
    """Write every picture of the documentation into ``output``; return their paths."""
    output.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix='urdfgenpy-pictures-') as scratch:
        folder = Path(scratch)
        _urdfgenpy('example', '--output-dir', str(folder), cwd=folder)
        robot = folder / 'ptu.urdf'
        _urdfgenpy('render', str(robot), '-o', str(output / 'ptu.png'),
                   '-j', 'pan_joint=0.6', '-j', 'tilt_joint=0.5', cwd=folder)
        _urdfgenpy('graph', str(robot), '-o', str(output / 'ptu_tree.svg'), cwd=folder)
        _view(robot, output / 'viewer.png')
    return [output / name for name in ('ptu.png', 'ptu_tree.svg', 'viewer.png')]


def main() -> None:
    """Parse the options and make the pictures."""
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--output', type=Path, default=IMAGES,
                        help='folder to write into (default: docs/images)')
    arguments = parser.parse_args()
    try:
        written = make_pictures(arguments.output)
    except subprocess.CalledProcessError as error:
        sys.stderr.write(f'make_pictures: {" ".join(error.cmd)} failed:\n{error.stderr}')
        sys.exit(2)
    for path in written:
        print(f'wrote {path}')


if __name__ == '__main__':
    main()
