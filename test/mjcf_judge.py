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
Judges of an MJCF model against independent readers of its URDF.

MuJoCo compiles the MJCF; yourdfpy reads the URDF's masses and tensors; pinocchio
computes the URDF's forward kinematics (and, when fixed links are fused, the inertia of
each moving body: it appends fixed links to their joint's body itself).
"""

from __future__ import annotations

import math
from pathlib import Path
import re

import numpy

TOLERANCE = 1e-9


def compile_mjcf(path: Path):
    """Return MuJoCo's model of the MJCF file ``path``."""
    import mujoco
    return mujoco.MjModel.from_xml_path(str(path))


def body_tensor(model, index: int) -> numpy.ndarray:
    """Return a body's inertia tensor about its centre of mass, in the body frame."""
    import mujoco
    rotation = numpy.zeros(9)
    mujoco.mju_quat2Mat(rotation, model.body_iquat[index])
    rotation = rotation.reshape(3, 3)
    return rotation @ numpy.diag(model.body_inertia[index]) @ rotation.T


def diverges(model, steps: int = 1000) -> bool:
    """Return whether ``steps`` steps with zero control diverge (MuJoCo resets on it)."""
    import mujoco
    data = mujoco.MjData(model)
    for _ in range(steps):
        mujoco.mj_step(model, data)
    return bool(data.warning[mujoco.mjtWarning.mjWARN_BADQACC].number) or not (
        numpy.all(numpy.isfinite(data.qpos)) and numpy.all(numpy.isfinite(data.qvel)))


def assert_no_contact_at_home(model) -> None:
    """Check that MuJoCo finds no contact at the ``home`` keyframe (the robot alone)."""
    import mujoco
    data = mujoco.MjData(model)
    if model.nkey:
        mujoco.mj_resetDataKeyframe(model, data, model.key('home').id)
    mujoco.mj_forward(model, data)
    assert data.ncon == 0, sorted({(model.body(model.geom_bodyid[c.geom1]).name,
                                    model.body(model.geom_bodyid[c.geom2]).name)
                                   for c in data.contact[:data.ncon]})


def assert_steps_finite(model, steps: int = 1000) -> None:
    """Step ``steps`` times with zero control from the model's initial state; all stays finite."""
    import mujoco
    data = mujoco.MjData(model)
    for _ in range(steps):
        mujoco.mj_step(model, data)
    assert numpy.all(numpy.isfinite(data.qpos)) and numpy.all(numpy.isfinite(data.qvel))
    # MuJoCo resets a diverging simulation itself: count those warnings too
    assert data.warning[mujoco.mjtWarning.mjWARN_BADQACC].number == 0


def assert_inertia_as_urdf(model, urdf_path: Path, links: set[str] | None = None) -> int:
    """Each body's mass, centre of mass and tensor equal yourdfpy's reading of the URDF."""
    import mujoco
    import yourdfpy
    urdf = yourdfpy.URDF.load(str(urdf_path), load_meshes=False, build_scene_graph=False,
                              build_collision_scene_graph=False).robot
    checked = 0
    for link in urdf.links:
        index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, link.name)
        if links is not None and link.name not in links or index < 0:
            continue
        inertial = link.inertial
        if inertial is None or inertial.mass is None:
            assert model.body_mass[index] == 0.0, link.name
            continue
        origin = inertial.origin if inertial.origin is not None else numpy.eye(4)
        tensor = origin[:3, :3] @ numpy.asarray(inertial.inertia) @ origin[:3, :3].T
        assert abs(model.body_mass[index] - inertial.mass) <= TOLERANCE * max(
            1.0, inertial.mass), link.name
        if inertial.mass > 0.0:
            assert numpy.allclose(model.body_ipos[index], origin[:3, 3], rtol=0,
                                  atol=TOLERANCE), link.name
            scale = max(1.0, numpy.abs(tensor).max())
            assert numpy.allclose(body_tensor(model, index), tensor, rtol=0,
                                  atol=TOLERANCE * scale), link.name
        checked += 1
    return checked


def assert_inertia_as_pinocchio(model, urdf_path: Path) -> int:
    """Each moving body's inertia equals pinocchio's (fixed links appended to their joint)."""
    import mujoco
    import pinocchio
    robot = pinocchio.buildModelFromUrdf(str(urdf_path))
    checked = 0
    for joint_id in range(1, robot.njoints):
        name = robot.names[joint_id]
        index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name)
        if index < 0:
            continue
        body = model.jnt_bodyid[index]
        inertia = robot.inertias[joint_id]
        # the joint frame is the child link's frame, the body's frame
        assert abs(model.body_mass[body] - inertia.mass) <= TOLERANCE * max(1, inertia.mass)
        if inertia.mass > 0:
            assert numpy.allclose(model.body_ipos[body], inertia.lever, rtol=0,
                                  atol=TOLERANCE), name
            scale = max(1.0, numpy.abs(inertia.inertia).max())
            assert numpy.allclose(body_tensor(model, body), inertia.inertia, rtol=0,
                                  atol=TOLERANCE * scale), name
        checked += 1
    return checked


def assert_fk_as_pinocchio(model, urdf_path: Path, configurations: int = 20,
                           seed: int = 0) -> int:
    """Every link's pose (body or site) equals pinocchio's FK at random configurations."""
    import mujoco
    import pinocchio
    robot = pinocchio.buildModelFromUrdf(str(urdf_path))
    frames = pinocchio.Model.createData(robot)
    data = mujoco.MjData(model)
    random = numpy.random.default_rng(seed)
    links = [frame.name for frame in robot.frames if frame.type == pinocchio.FrameType.BODY]
    compared = 0
    for _ in range(configurations):
        q = pinocchio.neutral(robot)
        qpos = model.qpos0.copy()
        for joint_id in range(1, robot.njoints):
            joint = robot.joints[joint_id]
            index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, robot.names[joint_id])
            if joint.nq == 1:
                low = robot.lowerPositionLimit[joint.idx_q]
                high = robot.upperPositionLimit[joint.idx_q]
                low, high = (low, high) if math.isfinite(low) and math.isfinite(high) \
                    and low < high else (-math.pi, math.pi)
                value = random.uniform(low, high)
                q[joint.idx_q] = value
            elif joint.nq == 2 and joint.nv == 1:  # continuous: cos, sin
                value = random.uniform(-math.pi, math.pi)
                q[joint.idx_q:joint.idx_q + 2] = (math.cos(value), math.sin(value))
            else:
                continue
            if index >= 0:
                qpos[model.jnt_qposadr[index]] = value
        data.qpos[:] = qpos
        mujoco.mj_kinematics(model, data)
        pinocchio.framesForwardKinematics(robot, frames, q)
        for name in links:
            if name == 'world' or name == 'universe':
                continue
            expected = frames.oMf[robot.getFrameId(name, pinocchio.FrameType.BODY)]
            body = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_BODY, name)
            if body >= 0:
                position, rotation = data.xpos[body], data.xmat[body].reshape(3, 3)
            else:
                site = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, name)
                assert site >= 0, f'link {name} is neither a body nor a site'
                position, rotation = data.site_xpos[site], data.site_xmat[site].reshape(3, 3)
            assert numpy.allclose(position, expected.translation, rtol=0, atol=TOLERANCE), name
            assert numpy.allclose(rotation, expected.rotation, rtol=0, atol=TOLERANCE), name
            compared += 1
    return compared


def assert_joints_as_urdf(model, robot) -> int:
    """Range, damping, friction and effort of every one-axis joint equal the URDF's."""
    import mujoco
    checked = 0
    for joint in robot.joints:
        if joint.type.value not in ('revolute', 'continuous', 'prismatic'):
            continue
        index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, joint.name)
        assert index >= 0, joint.name
        dof = model.jnt_dofadr[index]
        limit, dynamics = joint.limit, joint.dynamics
        if joint.type.value != 'continuous' and limit is not None \
                and limit.lower < limit.upper:
            assert model.jnt_limited[index] and tuple(model.jnt_range[index]) == (
                limit.lower, limit.upper), joint.name
        else:
            assert not model.jnt_limited[index], joint.name
        assert model.dof_damping[dof] == (dynamics.damping if dynamics else 0.0)
        assert model.dof_frictionloss[dof] == (dynamics.friction if dynamics else 0.0)
        if limit is not None and limit.effort > 0:
            assert model.jnt_actfrclimited[index]
            assert tuple(model.jnt_actfrcrange[index]) == (-limit.effort, limit.effort)
        checked += 1
    return checked


def assert_total_mass_as_urdf(model, urdf_path: Path) -> None:
    """Check that the bodies' masses add up to the URDF's (as yourdfpy reads them)."""
    import yourdfpy
    urdf = yourdfpy.URDF.load(str(urdf_path), load_meshes=False, build_scene_graph=False,
                              build_collision_scene_graph=False).robot
    total = sum(link.inertial.mass for link in urdf.links
                if link.inertial is not None and link.inertial.mass is not None)
    assert abs(float(model.body_mass.sum()) - total) <= TOLERANCE * max(1.0, total)


def marked_losses(path: Path) -> set[tuple[int, str]]:
    """Return the (line, code) pairs a fixture marks with ``<!-- Mxxx -->`` comments."""
    found = set()
    for number, line in enumerate(path.read_text().splitlines(), start=1):
        for comment in re.findall(r'<!--((?: M\d{3})+) -->', line):
            found |= {(number, code) for code in comment.split()}
    return found
