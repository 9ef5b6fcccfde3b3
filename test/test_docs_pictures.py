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
docs/make_pictures.py makes every picture of the site again, and none is blank.

The PNGs must show the example's amber material (the render and the viewer drew the
robot, not an empty scene); the tree's boxes are the links yourdfpy reads from the file.
"""

from __future__ import annotations

from pathlib import Path
import subprocess
import sys

from helpers import load_yourdfpy, REPO, require_module, require_tool
from lxml import etree
import pytest

from urdfgenpy_ros.examples import pan_tilt_unit

AMBER = (255, 140, 0)  # the example's rgba (1.0, 0.55, 0.0), shaded by the light


def _amber_share(path: Path) -> float:
    """Return the share of pixels whose hue is the example's amber (red > green > blue)."""
    numpy = require_module('numpy')
    from PIL import Image
    pixels = numpy.asarray(Image.open(path).convert('RGB')).astype(int)
    red, green, blue = pixels[..., 0], pixels[..., 1], pixels[..., 2]
    amber = (red > 120) & (green > 0.35 * red) & (green < 0.8 * red) & (blue < 0.35 * red)
    return float(amber.mean())


def _not_blank(path: Path) -> None:
    numpy = require_module('numpy')
    from PIL import Image
    pixels = numpy.asarray(Image.open(path).convert('L')).astype(float)
    assert pixels.shape[0] >= 300 and pixels.shape[1] >= 300, pixels.shape
    assert pixels.std() > 20, f'{path.name} is nearly one colour'


@pytest.mark.slow
def test_make_pictures_draws_every_picture(tmp_path: Path) -> None:
    for module in ('vtk', 'viser', 'graphviz', 'selenium', 'PIL'):
        require_module(module)
    require_tool('chromium', 'chromium chromium-driver')
    require_tool('dot', 'graphviz')
    result = subprocess.run([sys.executable, str(REPO / 'docs' / 'make_pictures.py'),
                             '--output', str(tmp_path)], capture_output=True, text=True,
                            timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    for name in ('ptu.png', 'viewer.png'):
        _not_blank(tmp_path / name)
        assert _amber_share(tmp_path / name) > 0.01, f'{name}: no amber tilt link drawn'
    robot = pan_tilt_unit()
    robot.save(tmp_path / 'ptu.urdf')
    links = {link.name for link in load_yourdfpy(tmp_path / 'ptu.urdf').links}
    svg = etree.parse(str(tmp_path / 'ptu_tree.svg'))
    labels = {''.join(group.find('{*}text').itertext())
              for group in svg.iter('{*}g') if group.get('class') == 'node'}
    assert labels == links
    edges = [group for group in svg.iter('{*}g') if group.get('class') == 'edge']
    assert len(edges) == len(robot.joints)


def test_the_committed_pictures_are_those_the_pages_show() -> None:
    """Every image a page shows is in docs/images, and every image there is shown."""
    import re
    shown = set()
    for page in [REPO / 'README.md', *(REPO / 'docs').glob('*.md')]:
        shown |= {Path(name).name for name in
                  re.findall(r'!\[[^\]]*\]\(([^)\s]+)', page.read_text(encoding='utf-8'))}
    committed = {path.name for path in (REPO / 'docs' / 'images').iterdir()}
    assert shown == committed
