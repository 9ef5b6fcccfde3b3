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
Inertia: positive mass where it moves, physical tensors, plausible magnitudes.

What the engines the formats are written for accept of an ``<inertial>`` (MuJoCo's
compiler, libsdformat's URDF conversion): the review's ``inertia`` check, and what the
SDF and MJCF rows' ``prepare`` refuse.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from urdfgenpy_ros.formats.sdf_conversion import (
    SdfConversion, sdformat_conversion, SDFORMAT_ZERO_MASS)
from urdfgenpy_ros.formats.sdf_inertia import finite
from urdfgenpy_ros.model.errors import Severity, SourceLocation, ValidationError
from urdfgenpy_ros.model.findings import Findings, link_path
from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, Sphere
from urdfgenpy_ros.model.inertial import (
    box_tensor, capsule_tensor, cylinder_tensor, Inertial, sphere_tensor)
from urdfgenpy_ros.model.joint import JointType
from urdfgenpy_ros.model.link import Link, Shape
from urdfgenpy_ros.model.transforms import symmetric_eigenvalues
from urdfgenpy_ros.reshape.lumping import lumps, WORLD

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

# MuJoCo's mjMINVAL (include/mujoco/mjtype.h): a moving body needs a mass of at least this
# (user_model.cc, CheckBodyMassInertia), as do its moments when all six are zero.
MINIMUM = 1e-15
# MuJoCo's mjEPS (src/user/user_util.h): its URDF reader keeps the six numbers as a full
# tensor (xml_urdf.cc) unless all are zero, and every body's tensor needs eigenvalues of at
# least this, whether the body moves or not (user_util.cc, mjuu_fullInertia: "inertia must
# have positive eigenvalues"; mjCBody::Compile).
EIGENVALUE_MINIMUM = 1e-14
BORDER = 64 * 2.0 ** -52  # closer to a limit than this (relative), rounding decides
IMPLAUSIBLE = 100.0  # a tensor this many times off the geometry's is a unit slip


def non_finite_inertials(robot: RobotModel) -> list[ValidationError]:
    """
    Return an R305 error for each ``<inertial>`` holding NaN or inf, which every engine refuses.

    The review says it as the reader's R305; a target's ``prepare`` runs no review, so
    this is what it refuses such a link for.
    """
    return [ValidationError(
        'R305', Severity.ERROR, f'link {link.name!r}',
        link.inertial.source or SourceLocation(path=link_path(link.name) + '/inertial'),
        'its mass or inertia is not a finite number (NaN or inf)',
        'write finite numbers in its <inertial>')
        for link in robot.links if link.inertial is not None and not finite(link.inertial)]


def check_inertia(robot: RobotModel, findings: Findings) -> None:
    """Check masses, tensors, the root's inertia and links Gazebo would drop."""
    parent_joint = {joint.child: joint for joint in robot.joints}
    roots = {link.name for link in robot.roots}
    below, moving_below = _subtrees(robot)
    conversion = sdformat_conversion(robot)
    lumped_mass = conversion.mass
    _check_kept_root(robot, conversion, findings)
    for link in robot.links:
        joint = parent_joint.get(link.name)
        inertial = link.inertial
        if lumped_mass.get(link.name, 0.0) >= SDFORMAT_ZERO_MASS and (
                inertial is None or not inertial.mass >= MINIMUM):
            continue  # a fixed child lumped into it gives it mass, in Gazebo and MuJoCo
        moves = joint is not None and joint.type is not JointType.FIXED
        where, element = link_path(link.name) + '/inertial', f'link {link.name!r}'
        if inertial is None:
            count = below.get(link.name, 0)
            sensors = _sensor_names(link)
            dropped = "Gazebo's URDF conversion drops it with its joint" + (
                f' and the {count} link(s) below it' if count else '') + (
                f" and its sensor(s) {', '.join(sensors)}" if sensors else '')
            if joint is not None and moves:
                findings.add('I207', link, element, link_path(link.name),
                             f'moves ({joint.type} joint {joint.name!r}) but has no '
                             '<inertial>', f'RViz does not mind; {dropped}, and MuJoCo '
                             'refuses it: give it a mass and inertia (urdfgenpy inertia MESH '
                             '--mass KG prints the <inertial> of its mesh; '
                             'Inertial.from_geometry in Python)')
            elif joint is not None and moving_below.get(link.name, False):
                findings.add('I206', link, element, link_path(link.name),
                             'has no <inertial>', f'{dropped}: give it a mass and inertia')
            continue
        if link.name in roots and inertial.mass > 0.0 and len(robot.links) > 1:
            findings.add('I205', inertial, element, where, 'the root link has an inertia',
                         'KDL ignores it (and warns): add a massless root link, e.g. '
                         'base_footprint, joined by a fixed joint', 'inertial')
        if not inertial.mass >= MINIMUM:
            if moves and joint is not None:
                findings.add('I201', inertial, element, where + '/mass',
                             f'mass is {inertial.mass:g} on a link that moves '
                             f'({joint.type} joint {joint.name!r})',
                             'give it a positive mass (kg): MuJoCo refuses the model, and '
                             "Gazebo's URDF conversion drops the link", 'mass')
            elif inertial.mass < 0.0:  # fixed or the root: still no mass at all
                findings.add('I210', inertial, element, where + '/mass',
                             f'mass is {inertial.mass:g}', 'give it a positive mass (kg), or '
                             "leave out its <inertial>: libsdformat refuses the link's inertia "
                             '(Gazebo loads no model)', 'mass')
            elif joint is not None and moving_below.get(link.name, False):
                count = below.get(link.name, 0)
                findings.add('I206', inertial, element, where + '/mass',
                             f'mass is {inertial.mass:g} above moving links',
                             "Gazebo's URDF conversion drops a massless link with its joint "
                             f'and the {count} link(s) below it: give it a mass and inertia',
                             'mass')
            continue
        if _check_tensor(inertial, element, where, findings, moves):
            _check_plausible(link, inertial, element, where, findings)


def _check_kept_root(robot: RobotModel, conversion: SdfConversion, findings: Findings) -> None:
    """
    Add I209 for a massless root SDFormat's conversion leaves out with the whole robot.

    Said where nothing else says it: every link massless, or the root and the links fixed
    to it all massless. (A bare massless root above moving links, KDL's convention, is
    left to ``--engines gazebo``'s G602.)
    """
    massless = all(conversion.mass.get(link.name, 0.0) < SDFORMAT_ZERO_MASS
                   for link in robot.links)
    for root in robot.roots:
        if root.name == WORLD or root.name not in conversion.cut:
            continue
        fixed = [joint for joint in robot.child_joints(root) if lumps(joint)]
        if not (fixed or massless):
            continue
        what = 'no link of the robot has mass' if massless else \
            'the root has no mass, nor do the links fixed to it'
        findings.add('I209', root, f'link {root.name!r}', link_path(root.name), what,
                     "Gazebo's URDF conversion (libsdformat) leaves the root out with every "
                     'link below it and refuses the robot ("A model must have at least one '
                     'link"): give the root, or a link fixed to it, a mass and inertia (for '
                     'KDL, a massless base_footprint fixed to a base_link with mass)', 'link')


def _sensor_names(link: Link) -> list[str]:
    """Return the names of the sensors on ``link``: built, or in its ``<gazebo>`` blocks."""
    names = [repr(sensor.name) for sensor in link.sensors]
    for block in link.extensions:
        names += [repr(node.get('name', '')) for node in block.element.iter('sensor')]
    return names


def _subtrees(robot: RobotModel) -> tuple[dict[str, int], dict[str, bool]]:
    """Return, per link, how many links hang below it and whether any joint below moves."""
    count: dict[str, int] = {}
    moving: dict[str, bool] = {}
    for root in robot.roots:
        order = list(robot.walk(root))
        for joint, link in reversed(order):  # children before parents
            count.setdefault(link.name, 0)
            moving.setdefault(link.name, False)
            if joint is not None:
                count[joint.parent] = count.get(joint.parent, 0) + count[link.name] + 1
                moving[joint.parent] = (moving.get(joint.parent, False) or moving[link.name]
                                        or joint.type is not JointType.FIXED)
    return count, moving


def _check_tensor(inertial: Inertial, element: str, where: str, findings: Findings,
                  moves: bool) -> bool:
    """
    Check the principal moments as the engines do; return whether the tensor is usable.

    MuJoCo refuses a body whose tensor has an eigenvalue below 1e-14 (I202), or whose
    principal moments break the triangle inequality (I203), whether it moves or not. The
    one exception is a tensor of zeros, which MuJoCo does not read as a tensor: on a link
    that does not move (a point mass or a frame) Gazebo's converter and MuJoCo accept it
    (I208, a warning); on a moving link MuJoCo refuses it (I202).
    """
    values = (inertial.ixx, inertial.ixy, inertial.ixz, inertial.iyy, inertial.iyz,
              inertial.izz)
    if not all(math.isfinite(value) for value in values):
        return False  # reported as R305
    small, middle, large = moments = symmetric_eigenvalues(inertial.tensor)
    listed = ', '.join(f'{m:.4g}' for m in moments)
    minimum = EIGENVALUE_MINIMUM if any(values) else MINIMUM
    below, uneven = small < minimum, small + middle < large  # as MuJoCo adds them
    if any(values[index] for index in (1, 2, 4)) and (
            abs(small - minimum) <= BORDER * large or abs(small + middle - large)
            <= BORDER * large):
        below, uneven = _mujoco_verdict(values, (below, uneven))
    if below:
        problem = f'principal moments {listed} are not all at least {minimum:g}'
    elif uneven:
        problem = f'principal moments {small:.4g} + {middle:.4g} < {large:.4g}'
    else:
        return True
    if not moves and not any(values):
        findings.add('I208', inertial, element, where + '/inertia', problem,
                     'a point mass on a link that does not move: Gazebo and MuJoCo accept '
                     'it; compute the tensor from the geometry (Inertial.from_geometry) if '
                     'the link will ever move', 'inertia')
    elif small < minimum:
        findings.add('I202', inertial, element, where + '/inertia', problem,
                     'MuJoCo refuses the model (it needs every moment of at least 1e-14; only '
                     'a link that does not move may have six zeros): compute the tensor from '
                     'the geometry (Inertial.from_geometry) or from CAD',
                     'inertia')
    else:
        findings.add('I203', inertial, element, where + '/inertia', problem,
                     'no rigid body has that: check the tensor (MuJoCo refuses it, even on '
                     'a link that does not move)', 'inertia')
    return False


def _mujoco_verdict(values: tuple[float, ...], ours: tuple[bool, bool]) -> tuple[bool, bool]:
    """
    Return MuJoCo's (eigenvalue too small, triangle broken) for a turned tensor at a limit.

    Within rounding of a limit, a tensor with products of inertia passes or fails by how
    MuJoCo's own eigenvalue routine rounds: a one-link URDF asks it, when it is installed.
    """
    try:
        import mujoco
    except ImportError:
        return ours
    names = ('ixx', 'ixy', 'ixz', 'iyy', 'iyz', 'izz')
    tensor = ' '.join(f'{name}="{value!r}"' for name, value in zip(names, values))
    try:
        mujoco.MjModel.from_xml_string(
            f'<robot name="tensor"><link name="body"><inertial><mass value="1"/>'
            f'<inertia {tensor}/></inertial></link></robot>')
    except ValueError as error:
        said = str(error)
        return 'eigenvalues' in said, 'A + B >= C' in said
    return False, False


def _check_plausible(link: Link, inertial: Inertial, element: str, where: str,
                     findings: Findings) -> None:
    # One primitive is the whole body: with several shapes (a foot's contact spheres) or
    # a mesh, one of them says nothing of the link's tensor.
    items: tuple[Shape, ...] = tuple(link.collisions) or tuple(link.visuals)
    if len(items) != 1 or not isinstance(items[0].geometry, (Box, Cylinder, Sphere, Capsule)):
        return
    shape = items[0].geometry
    if isinstance(shape, Box):
        expected = box_tensor(inertial.mass, *shape.size)
    elif isinstance(shape, Cylinder):
        expected = cylinder_tensor(inertial.mass, shape.radius, shape.length)
    elif isinstance(shape, Capsule):
        expected = capsule_tensor(inertial.mass, shape.radius, shape.length)
    else:
        expected = sphere_tensor(inertial.mass, shape.radius)
    trace = inertial.ixx + inertial.iyy + inertial.izz
    expected_trace = expected[0] + expected[3] + expected[5]
    if not expected_trace > 0.0:
        return  # a zero-size shape (R304) has no tensor to compare with
    ratio = trace / expected_trace
    if ratio > IMPLAUSIBLE or ratio < 1.0 / IMPLAUSIBLE:
        findings.add('I204', inertial, element, where + '/inertia',
                     f'inertia is {ratio:.3g} times that of its {type(shape).__name__.lower()}'
                     f' of mass {inertial.mass:g}',
                     'millimetres for metres, or grams for kilograms? '
                     'Inertial.from_geometry gives the solid value', 'inertia')
