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
What makes the written model simulate: the integrator, and a floating base on the floor.

MuJoCo's default Euler integrator blows up a velocity servo on a light joint (kv=1 on a
wheel of 3e-5 kg m^2 at dt=0.002); ``implicitfast`` integrates the damping implicitly and
stays stable. A floating base placed at the origin may start inside the scene's floor:
it is raised so that its lowest collision geom touches the floor (z=0) at the keyframe.
"""

from __future__ import annotations

import copy
import importlib.util
import math
from typing import Any

from lxml import etree

from urdfgenpy_ros.model.floats import fmt_vec

INTEGRATOR = 'implicitfast'


def choose_integrator(document: Any, kinds: set[str], servo_damping: bool) -> str | None:
    """
    Write ``<option integrator="implicitfast"/>`` when a damping servo needs it.

    Velocity actuators, or position actuators given a ``kv``, need it, unless the
    document (the URDF's ``<mujoco>`` block, an overlay) already names an integrator.
    Return the note saying what was chosen, or None.
    """
    if 'velocity' not in kinds and not ('position' in kinds and servo_damping):
        return None
    option = document.find('option')
    if option is not None and option.get('integrator') is not None:
        return None
    if option is None:
        from urdfgenpy_ros.formats.mjcf.blocks import insert_section
        option = etree.Element('option')
        insert_section(document, option)
    option.set('integrator', INTEGRATOR)
    return (f'integrator: {INTEGRATOR} (servo damping under the default Euler blows up on '
            'light joints; set <option integrator=...> in the <mujoco> block or an overlay '
            'to choose another)')


def _lowest(model: Any, data: Any) -> float | None:
    """Return the lowest z of the collision geoms (None when there is none)."""
    import numpy
    lowest = None
    for geom in range(model.ngeom):
        if not (model.geom_contype[geom] or model.geom_conaffinity[geom]) \
                or model.geom_bodyid[geom] == 0:
            continue
        kind, size = int(model.geom_type[geom]), model.geom_size[geom]
        rotation = data.geom_xmat[geom].reshape(3, 3)
        z = float(data.geom_xpos[geom][2])
        up = rotation[2]  # the world z of each geom axis
        if kind == 2:  # sphere
            depth = size[0]
        elif kind == 3:  # capsule
            depth = abs(up[2]) * size[1] + size[0]
        elif kind == 4:  # ellipsoid
            depth = math.sqrt(sum((up[i] * size[i]) ** 2 for i in range(3)))
        elif kind == 5:  # cylinder
            depth = abs(up[2]) * size[1] + size[0] * math.sqrt(max(0.0, 1 - up[2] ** 2))
        elif kind == 6:  # box
            depth = sum(abs(up[i]) * size[i] for i in range(3))
        elif kind == 7:  # mesh
            mesh = model.geom_dataid[geom]
            start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
            depth = -float(numpy.min(model.mesh_vert[start:start + count] @ up))
        else:
            continue
        bottom = z - float(depth)
        lowest = bottom if lowest is None else min(lowest, bottom)
    return lowest


def rest_on_floor(document: Any, root: str, files: dict[str, bytes],
                  meshdir: str | None) -> str:
    """
    Raise the floating body ``root`` so its lowest collision geom touches z=0.

    The body's ``pos`` and the free joint's place in each keyframe are moved; return the
    note saying how far (or why it was not placed).
    """
    if importlib.util.find_spec('mujoco') is None:
        return ('floating base left at the origin: MuJoCo places it on the floor when '
                "installed (pip install 'urdfgenpy_ros[engines]')")
    import mujoco
    assets = {f'{meshdir}/{name}' if meshdir else name: data for name, data in files.items()}
    try:
        model = mujoco.MjModel.from_xml_string(
            etree.tostring(copy.deepcopy(document), encoding='unicode'), assets)
    except ValueError as error:
        return f'floating base left at the origin: MuJoCo does not compile it ({error})'
    data = mujoco.MjData(model)
    if model.nkey:
        mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    lowest = _lowest(model, data)
    if lowest is None:
        return 'floating base left at the origin: it has no collision geom'
    rise = -lowest
    body = next(node for node in document.iter('body') if node.get('name') == root)
    position = [float(value) for value in body.get('pos', '0 0 0').split()]
    position[2] += rise
    body.set('pos', fmt_vec(position))
    for key in document.iter('key'):
        qpos = key.get('qpos')
        if qpos is not None:
            values = [float(value) for value in qpos.split()]
            values[2] += rise
            key.set('qpos', fmt_vec(values))
    return f'floating base raised to z={position[2]:.6g}: its lowest collision geom ' \
        'rests on the floor (z=0)'
