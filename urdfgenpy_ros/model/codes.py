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
Every finding code, its severity and title, in one table. Codes never change meaning.

P and X codes are the readers' (errors raise ParseError; warnings come with the robot).
"""

from __future__ import annotations

from urdfgenpy_ros.model.errors import Severity

E, W = Severity.ERROR, Severity.WARNING

CODES: dict[str, tuple[Severity, str]] = {
    # reading (see formats/_parse.py and formats/urdf_read.py)
    'P101': (W, '<robot> wrapped in another root element'),
    'P102': (W, 'malformed or misplaced XML declaration'),
    'P103': (W, 'NUL bytes after the document'),
    'P104': (W, 'default namespace on <robot>'),
    'P105': (W, 'undeclared namespace prefix, kept as written'),
    'P106': (W, '<inertial> without <inertia> (urdfdom drops it, MuJoCo refuses it)'),
    'P107': (W, 'visual material with a malformed colour (urdfdom ignores it, MuJoCo refuses '
                'it)'),
    'X002': (E, 'Xacro file given to the URDF reader'),
    'X003': (E, 'Xacro file of macros only read as a robot'),
    'X101': (W, 'Xacro in a .urdf file, expanded with xacro'),
    'X102': (W, 'xacro warned while expanding the file'),
    'X103': (W, 'Xacro argument given that no file declares (xacro ignores it)'),
    'X104': (W, "a .urdf file's mesh filename uses $(...): read as URDF, needs xacro to "
                'resolve'),
    # structure
    'S001': (E, 'no root link'),
    'S002': (E, 'more than one root link'),
    'S003': (E, 'kinematic loop'),
    'S004': (E, 'joint names a parent link that does not exist'),
    'S005': (E, 'joint names a child link that does not exist'),
    'S006': (E, 'joint connects a link to itself'),
    'S007': (E, 'link has more than one parent joint'),
    'S008': (E, 'empty name'),
    'S009': (W, 'name is not a valid ROS frame name'),
    # joints
    'J101': (E, 'zero axis on a movable joint'),
    'J102': (W, 'axis is not a unit vector'),
    'J103': (E, 'revolute or prismatic joint without <limit>'),
    'J104': (E, 'lower limit above upper limit'),
    'J105': (E, 'negative effort or velocity limit'),
    'J106': (W, 'zero effort or velocity limit on a movable joint'),
    'J107': (E, 'mimic names a joint that does not exist'),
    'J108': (E, 'mimic follows a joint that cannot move'),
    'J109': (E, 'mimic cycle'),
    'J110': (W, 'safety controller soft limits outside the hard limits'),
    'J111': (W, 'mimic on a fixed joint has no effect'),
    # inertia
    'I201': (E, 'moving link without positive mass'),
    'I202': (E, 'inertia tensor not positive-definite'),
    'I203': (E, 'inertia violates the triangle inequality'),
    'I204': (W, 'inertia implausible for the link geometry'),
    'I205': (W, 'inertia on the root link'),
    'I206': (W, 'link without inertial (or massless) above moving links'),
    'I207': (W, 'moving link without inertial (fine for RViz, not for simulation)'),
    'I208': (W, 'a point mass (zero tensor) on a link that does not move'),
    'I209': (W, 'massless root (and links fixed to it): libsdformat keeps no link'),
    'I210': (E, 'negative mass on a link that does not move'),
    # references and values
    'R301': (W, 'material not defined'),
    'R302': (E, 'collision mesh file not found'),
    'R303': (W, 'mesh package not found, file not checked'),
    'R304': (E, 'non-positive size or zero scale'),
    'R305': (E, 'not a finite number'),
    'R306': (W, 'visual mesh file not found'),
    'R307': (W, 'zero size or zero scale on a visual (it draws nothing)'),
    'R308': (W, 'relative path written as a file:// URI (not portable)'),
    'R309': (W, 'mesh named by a bare absolute path (not portable)'),
    # URDF versions (validation/versions.py, urdf_versions.py)
    'V701': (E, 'URDF version the target ROS cannot read'),
    'V702': (W, 'URDF 1.1/1.2 feature in a file whose version lacks it (urdfdom 6 ignores it)'),
    'V703': (E, 'malformed URDF version (urdfdom refuses the file)'),
    'V704': (W, 'quaternion is not of unit length'),
    'V705': (W, 'quaternion of zero length (read as no rotation, as urdfdom 6 does)'),
    'V706': (W, 'written as URDF 1.0: a capsule became a cylinder and two spheres'),
    'V707': (W, 'written as URDF 1.0: a URDF 1.2 limit was dropped'),
    # statics (validation/statics.py, validation/efforts.py; check --statics)
    'T801': (E, 'effort cannot hold the robot against gravity somewhere in the range'),
    'T802': (W, 'force limits of a joint disagree (<limit>, ros2_control, Gazebo)'),
    # collision geometry made light (urdfgenpy collision; urdfgenpy_ros.collision)
    'K911': (W, 'collision made light: what it loses, measured'),
    'K912': (E, 'collision made light below --min-iou'),
    'K913': (W, 'open or non-manifold collision mesh repaired before measuring'),
    'K914': (W, 'collision mesh open and not repairable: left as it was'),
    # conventions
    'C401': (W, "no link called 'base_link'"),
    # engine pre-flight (validation/preflight.py): what a consumer silently changes
    'M501': (W, 'MuJoCo fuses the link into its parent body (fixed joint, or a fixed base)'),
    'M502': (W, 'MuJoCo uses another mass or inertia than the URDF gives'),
    'M503': (W, 'MuJoCo changes the joint range'),
    'M504': (W, 'MuJoCo collides with the convex hull of a non-convex mesh'),
    'M505': (W, 'MuJoCo refuses the model'),
    'M506': (W, 'MuJoCo cannot read the mesh'),
    'M507': (W, 'MuJoCo warns while compiling the model'),
    'M508': (W, "MuJoCo's URDF import makes no actuator of a <ros2_control> command interface"),
    'M509': (W, "MuJoCo's URDF import ignores <gazebo> friction (mu1, mu2)"),
    'M510': (W, 'collision mesh wound inside out (negative volume)'),
    # MJCF export (formats/mjcf/losses.py): what the MJCF cannot carry
    'M801': (W, 'MJCF has no joint velocity limit'),
    'M802': (W, 'MJCF has no safety controller'),
    'M803': (W, 'MJCF has no joint calibration'),
    'M804': (W, 'joint written as a stand-in of several MJCF joints'),
    'M805': (W, 'transmission or ros2_control part that maps to no actuator'),
    'M806': (W, 'Gazebo element not carried into MJCF'),
    'M807': (W, 'element or attribute with no MJCF counterpart'),
    'M808': (W, "<mujoco> block attribute MuJoCo's schema refuses"),
    'M809': (W, 'geometry not written to MJCF (mesh not found or unreadable, size zero)'),
    # MoveIt SRDF against its robot (moveit/srdf_check.py; check --srdf)
    'K901': (E, 'SRDF names a link, joint or group the robot does not have'),
    'K902': (E, 'SRDF chain group whose base is not above its tip'),
    'K903': (E, 'SRDF group state value outside the joint limits'),
    'K904': (W, 'SRDF pair disabled as never colliding collides in random states'),
    'K905': (W, 'SRDF disabled pair names a link without collision geometry'),
    'G601': (W, "SDFormat's URDF conversion lumps the link into its parent (fixed joint)"),
    'G602': (W, "SDFormat's URDF conversion drops the link (and everything below it)"),
    'G603': (W, "SDFormat's URDF conversion drops a <gazebo> setting (nothing takes it)"),
    'G604': (W, 'Gazebo Sim renders no Gazebo-classic material script'),
}

# Engine pre-flight codes: what to do about each (the SARIF rules' help).
PREFLIGHT_HINTS: dict[str, str] = {
    'M501': 'expected for fixed joints; to keep the bodies, add <mujoco><compiler '
            'fusestatic="false"/></mujoco> to the URDF (a mobile base needs a free joint '
            'in MJCF)',
    'M502': 'give the link an <inertial> with a mass and a tensor MuJoCo accepts as they are',
    'M503': 'give lower < upper in <limit>: MuJoCo reads equal bounds as no range at all',
    'M504': 'split the collision mesh into convex parts, or use primitive shapes',
    'M505': 'MuJoCo says why in the message; fix what it names',
    'M507': 'MuJoCo ignores or changes what it names: check the simulation does not need it',
    'M506': 'MuJoCo reads STL, OBJ and MSH meshes: convert it (urdfgenpy convert ROBOT '
            'robot.xml converts DAE, GLB, GLTF and PLY meshes for the MJCF it writes)',
    'M508': 'urdfgenpy convert ROBOT robot.xml writes it as an actuator (docs/mujoco.md)',
    'M509': "urdfgenpy convert ROBOT robot.xml gives the link's collision geoms that friction",
    'M510': 'flip its triangles (trimesh: mesh.invert(); MeshLab: Filters > Normals > Invert '
            'Faces Orientation) and export it again',
    'G601': '<gazebo reference="JOINT"><preserveFixedJoint>true</preserveFixedJoint></gazebo> '
            'keeps the link (and its frame) in Gazebo',
    'G602': 'give the link a mass and inertia (Inertial.from_geometry): Gazebo drops it',
    'G603': 'a <gazebo> element acts only in the block of what it sets: move it there, or '
            'drop it',
    'G604': 'give the visual a <material> with a colour (URDF <color rgba>), which Gazebo '
            'Sim renders',
}

FIXABLE = frozenset(('J102', 'J103', 'J104', 'J106', 'I202', 'I203', 'I205'))
"""The codes ``validation.fix`` can repair (J103 and J106 only with defaults)."""


def severity_of(code: str) -> Severity:
    """Return the severity of ``code``."""
    return CODES[code][0]
