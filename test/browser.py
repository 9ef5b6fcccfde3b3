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


"""A real headless browser for the viewer's tests: Debian's chromium driven by Selenium."""

from __future__ import annotations

from collections.abc import Callable
import shutil
import socket
import tempfile
import time
from typing import Any

from helpers import require_module, require_tool

try:
    from selenium.common.exceptions import StaleElementReferenceException
except ImportError:  # the tests that need it skip
    StaleElementReferenceException = KeyError  # type: ignore

FLAGS = ('--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync',
         '--enable-unsafe-swiftshader', '--window-size=1200,800')


def free_port() -> int:
    """Return a TCP port nobody listens on now."""
    with socket.socket() as probe:
        probe.bind(('127.0.0.1', 0))
        return probe.getsockname()[1]


class Browser:
    """One headless Chromium with a fresh profile; ``close`` ends it."""

    def __init__(self) -> None:
        webdriver = require_module('selenium.webdriver')
        from selenium.webdriver.chrome.service import Service
        options = webdriver.ChromeOptions()
        options.binary_location = require_tool('chromium', 'chromium chromium-driver')
        self.profile = tempfile.mkdtemp(prefix='urdfgenpy-chromium-')
        for flag in (*FLAGS, f'--user-data-dir={self.profile}'):
            options.add_argument(flag)
        self.driver = webdriver.Chrome(options=options,
                                       service=Service(require_tool(
                                           'chromedriver', 'chromium chromium-driver')))

    def load(self, url: str) -> None:
        """Load ``url`` and wait until the viewer's controls are there."""
        self.driver.get(url)
        self.wait_for(lambda: self.sliders() or self.text_shown('no movable joints'), 60)
        for button in self.driver.find_elements('css selector',
                                                '.mantine-Notification-root button'):
            self.driver.execute_script('arguments[0].click()', button)  # the WebGL notice

    def wait_for(self, condition: Callable[[], Any], timeout: float = 20.0) -> Any:
        """Poll ``condition`` until it is true; fail after ``timeout`` seconds."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            try:
                result = condition()
            except (KeyError, StaleElementReferenceException):  # the page is rebuilding
                result = None
            if result is not None and result is not False and (
                    hasattr(result, 'shape') or bool(result)):  # an image counts as found
                return result
            time.sleep(0.1)
        raise AssertionError(f'timed out after {timeout} s waiting for {condition}')

    def text_shown(self, text: str) -> bool:
        """Return whether the page shows ``text``."""
        return text in self.driver.find_element('tag name', 'body').text

    def sliders(self) -> dict[str, Any]:
        """Return each labelled slider's thumb element, by its label."""
        found = {}
        for thumb in self.driver.find_elements('css selector', '[role=slider]'):
            for row in thumb.find_elements('xpath', './ancestor::div')[::-1]:
                first = row.text.split('\n')[0].strip()
                try:
                    float(first)
                except ValueError:
                    found[first] = thumb
                    break
        return found

    def canvas(self) -> Any:
        """Return the 3D view's pixels (rows x columns x RGB), the control panel blanked."""
        import io
        numpy = require_module('numpy')
        from PIL import Image
        element = self.driver.find_element('css selector', 'canvas')
        data = element.screenshot_as_png
        pixels = numpy.asarray(Image.open(io.BytesIO(data)).convert('RGB')).astype(int)
        panel = self.driver.execute_script(
            "const show = document.evaluate(\"//*[text()='Show']\", document, null, "
            'XPathResult.FIRST_ORDERED_NODE_TYPE, null).singleNodeValue;'
            'return show ? show.getBoundingClientRect().left : null;')
        if panel is not None:
            scale = pixels.shape[1] / element.size['width']
            pixels[:, max(int((panel - 40 - element.location['x']) * scale), 0):] = 255
        return pixels

    def close(self) -> None:
        """Quit the browser and remove its profile."""
        self.driver.quit()
        shutil.rmtree(self.profile, ignore_errors=True)
