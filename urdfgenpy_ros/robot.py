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

"""The robot: links joined into a tree by joints, read, written, checked and reshaped."""

from __future__ import annotations

from collections.abc import Mapping
from os import PathLike
from pathlib import Path
from typing import Any, cast

from urdfgenpy_ros.formats.table import save, write_as
from urdfgenpy_ros.model import checks
from urdfgenpy_ros.model import RobotModel, set_robot_class
from urdfgenpy_ros.model.errors import ModelError, ValidationError
from urdfgenpy_ros.model.geometry import Origin
from urdfgenpy_ros.model.joint import Joint
from urdfgenpy_ros.model.link import Link


class Robot(RobotModel):
    """
    A robot description: build it, navigate it, edit it, export it.

    Links, joints and materials keep the order they were added in, which is the order
    they are written in. Names are unique within each kind. Building, access, navigation
    and most editing come from :class:`urdfgenpy_ros.model.RobotModel`; the methods here
    call down into the operations (``formats``, ``validation``, ``assembly``, ``reshape``,
    ``dynamics``, ``tree``).
    """

    # ---- renaming (references in blocks and mimics follow: urdfgenpy_ros.reshape.assembly) ----

    def rename_link(self, old: str, new: str) -> Link:
        """Rename a link and every joint end and reference that names it."""
        from urdfgenpy_ros.reshape.assembly import rename
        link = self.get_link(old)
        if new in self._links and new != old:
            raise ModelError(f'cannot rename link {old!r} to {new!r}: that name is taken')
        rename(self, links={old: checks.name('link', new)})
        return link

    def rename_joint(self, old: str, new: str) -> Joint:
        """Rename a joint and every mimic and reference that names it."""
        from urdfgenpy_ros.reshape.assembly import rename
        joint = self.get_joint(old)
        if new in self._joints and new != old:
            raise ModelError(f'cannot rename joint {old!r} to {new!r}: that name is taken')
        rename(self, joints={old: checks.name('joint', new)})
        return joint

    # ---- checking ------------------------------------------------------------------

    def validate(self, strict: bool = False, **options: object) -> list[ValidationError]:
        """
        Return the findings of every check (``urdfgenpy_ros.validation.validate``).

        With ``strict=True``, raise the first error instead. ``search_paths`` and
        ``check_meshes`` go to the mesh check.
        """
        from urdfgenpy_ros.validation import validate
        return validate(self, strict, **options)  # type: ignore[arg-type]

    # ---- input ---------------------------------------------------------------------

    @classmethod
    def from_urdf(cls, path: str | PathLike[str]) -> Robot:
        """
        Read a URDF file, keeping whatever the model does not hold for writing back.

        :raises ParseError: when the file is not a readable URDF (one line, located).
        """
        from urdfgenpy_ros.formats.detect import refuse_xacro
        from urdfgenpy_ros.formats.urdf_read import read_urdf_bytes
        data = Path(path).read_bytes()
        weak = refuse_xacro(data, str(path))  # one line naming Robot.from_xacro (X002)
        robot = cast(Robot, read_urdf_bytes(data, str(path), cls))  # a cls, as told
        if weak is not None:  # only a $(...) in a mesh filename: urdfdom reads it too
            robot.read_warnings.insert(0, weak)
        return robot

    @classmethod
    def from_urdf_string(cls, xml: str | bytes, file: str | None = None) -> Robot:
        """Read URDF text (bytes, or a string in the encoding it declares); ``file`` names it."""
        from urdfgenpy_ros.formats._xml import xml_bytes
        from urdfgenpy_ros.formats.urdf_read import read_urdf_bytes
        data = xml_bytes(xml, 'surrogateescape') if isinstance(xml, str) else xml
        return cast(Robot, read_urdf_bytes(data, file, cls))

    @classmethod
    def from_xacro(cls, path: str | PathLike[str], mappings: dict[str, str] | None = None,
                   *, search_paths: list[str | PathLike[str]] | tuple = (),
                   packages: dict[str, str | PathLike[str]] | None = None) -> Robot:
        """
        Expand a Xacro file with the real ``xacro`` and read the result.

        ``mappings`` are xacro arguments (``{'dof': '7'}``); ``$(find pkg)`` resolves
        through ``packages`` (name to folder), ``search_paths``, the ament index and
        ``ROS_PACKAGE_PATH``.
        """
        from urdfgenpy_ros.formats.xacro_read import read_xacro
        return cast(Robot, read_xacro(path, mappings, search_paths, packages, cls))

    # ---- output --------------------------------------------------------------------

    def to_urdf(self, path: str | PathLike[str] | None = None, *,
                version: str | None = None) -> str:
        """
        Return the URDF text; also write it to ``path`` when given.

        With ``version`` ('1.0', '1.1' or '1.2'), write what that URDF version holds:
        for 1.0 (what ROS 2 Jazzy reads), quaternions become rpy and capsules a cylinder
        and two spheres. Each change that is not exact is a ``UserWarning`` naming its
        place (``urdfgenpy convert --urdf-version`` prints them as findings).
        """
        return write_as(self, 'urdf', path, version=version)

    def to_xacro(self, path: str | PathLike[str] | None = None, *, macro: bool = False) -> str:
        """
        Return idiomatic Xacro text; also write it to ``path`` when given.

        With ``macro``, the robot becomes ``<xacro:macro name=... params="prefix parent
        *origin">`` in ``<name>.macro.xacro`` beside ``path``, and ``path`` the file that
        instantiates it (see :func:`urdfgenpy_ros.formats.xacro.write_macro_xacro`).
        """
        return write_as(self, 'xacro', path, macro=macro)

    def to_sdf(self, path: str | PathLike[str] | None = None, lump_fixed: bool = False,
               version: str | None = None) -> str:
        """
        Return an SDF model; also write it to ``path`` when given.

        With ``lump_fixed``, links joined by fixed joints are merged (combined inertia), as
        SDFormat's own URDF conversion does. ``version`` is ``'1.9'`` or ``'1.11'`` (the
        default when a joint mimics another: 1.11 holds mimic joints).
        """
        return write_as(self, 'sdf', path, lump_fixed=lump_fixed, version=version)

    def save(self, path: str | PathLike[str], **options: Any) -> None:
        """
        Write the robot in the format its suffix names (.urdf, .xacro, .sdf, .xml, .mjcf).

        ``options`` go to that format's writer (``fuse_fixed=True`` for MJCF, say).
        """
        save(self, path, **options)

    def tree_string(self) -> str:
        """Return the kinematic tree as plain text."""
        from urdfgenpy_ros.tree import tree_string
        return tree_string(self)

    def print_tree(self) -> None:
        """Print the kinematic tree, coloured when stdout is a terminal."""
        from urdfgenpy_ros.tree import print_tree
        print_tree(self)

    def save_tree(self, path: str | PathLike[str]) -> None:
        """Write the plain-text kinematic tree to ``path``."""
        from urdfgenpy_ros.tree import save_tree
        save_tree(self, path)

    # ---- assembling ----------------------------------------------------------------

    def prefixed(self, prefix: str, *, materials: bool = False) -> Robot:
        """
        Return a copy with ``prefix`` before every link and joint name.

        Every reference follows: joint ends, mimic targets, ``<gazebo reference>``,
        transmission and ``<ros2_control>`` joints, sensor frames and the joint and link
        names in plugin parameters. Transmission, actuator, ``<ros2_control>`` and sensor
        names (and sensors' relative topics) get the prefix too. Robot-level materials keep
        their names unless ``materials`` is true.
        """
        from urdfgenpy_ros.reshape.assembly import prefixed
        return prefixed(self, prefix, materials=materials)

    def attach(self, part: Robot, at: str, origin: Origin | None = None, prefix: str = '',
               joint_name: str | None = None, joint_type: str = 'fixed',
               **joint_options: Any) -> Robot:
        """
        Join a copy of ``part``, its names prefixed, to the link ``at``; return this robot.

        The joint (``joint_name``, default ``<at>_to_<part root>``) is fixed unless
        ``joint_type`` says otherwise (``axis=``, ``limit=`` ... then go to the Joint).
        Names that clash are refused, all listed in one line, and nothing changes.
        Materials that equal one of this robot's are shared; same-named ones of another
        colour are renamed with the prefix. ``part`` itself is not changed.
        """
        from urdfgenpy_ros.reshape.assembly import attach
        return attach(self, part, at, origin, prefix, joint_name, joint_type, **joint_options)

    @classmethod
    def from_assembly(cls, path: str | PathLike[str],
                      search_paths: list[str | PathLike[str]] | tuple = ()) -> Robot:
        """
        Build the robot an assembly file (YAML) describes: parts, where each attaches.

        ``included_files`` lists the assembly file and every part's files.

        :raises ParseError: one line with the file, line, key and the fix.
        """
        from urdfgenpy_ros.formats import load
        from urdfgenpy_ros.formats.assembly_file import read_assembly
        return cast(Robot, read_assembly(path, search_paths, load=load))  # robot_class()

    # ---- reshaping -----------------------------------------------------------------

    def mirror(self, root: str, plane: str = 'xz', frame: str | None = None,
               rename: Mapping[str, str] | None = None, *,
               mesh_folder: str | PathLike[str] | None = None,
               search_paths: list[str | PathLike[str]] | tuple = ()) -> Robot:
        """
        Add the mirror image of the subtree below ``root``'s parent joint; return the robot.

        The reflection is through ``plane`` ('xz', 'yz' or 'xy') of link ``frame`` (the
        robot's root link by default); names change by ``rename`` (default
        ``{'left_': 'right_'}``: a name starting with a key gets the value as its prefix
        instead, a key only further in a name is replaced wherever it is; every reference
        follows). Mirrored meshes are written beside the originals, or in ``mesh_folder``
        (``package://`` URIs resolve through ``search_paths`` too); nothing is written
        unless the whole mirror succeeds.
        :func:`urdfgenpy_ros.reshape.mirror.mirror_subtree` also returns each joint's rule
        (positions kept or negated).
        """
        from urdfgenpy_ros.reshape.mirror import mirror_subtree
        mirror_subtree(self, root, plane, frame, rename, mesh_folder=mesh_folder,
                       search_paths=tuple(search_paths))
        return self

    def merge_fixed(self, keep: str | tuple[str, ...] | list[str] = (), *,
                    drop_frames: bool = False) -> Robot:
        """
        Return a copy with fixed-joint children merged into their parents.

        Inertia is lumped exactly as the SDF writer (and SDFormat) lumps it; visuals and
        collisions move with their poses. Each merged link stays as a massless frame on
        its fixed joint unless ``drop_frames``; links in ``keep`` (a name or several) are
        never merged.
        """
        from urdfgenpy_ros.reshape.merge import merge_fixed
        return merge_fixed(self, keep, drop_frames=drop_frames)

    def apply_dh(self, table: Any, base: str, tip: str) -> list[str]:
        """
        Give the chain from ``base`` to ``tip`` the kinematics of a DH ``table``.

        Only joint origins change (one line each in a lossless write); return the names of
        the joints whose origin changed. See :mod:`urdfgenpy_ros.reshape.dh_apply`.
        """
        from urdfgenpy_ros.reshape.dh_apply import apply_dh
        return apply_dh(self, table, base, tip)

    def simplify_collisions(self, method: str = 'hull', links: Any = None,
                            **options: Any) -> Any:
        """
        Make the collision meshes of ``links`` (a name or several; default all) light.

        ``method``: 'hull', 'decompose' (CoACD), 'primitive', 'decimate' or 'auto' (the
        lightest within ``min_iou``). Options: ``max_faces``, ``max_hulls``, ``seed``,
        ``split`` (a primitive per convex part), ``min_iou`` (refuse below it),
        ``mesh_folder``, ``search_paths``, ``capsules``.
        Only collisions change; new meshes are written beside the originals (or in
        ``mesh_folder``). Returns a :class:`urdfgenpy_ros.collision.CollisionReport`
        (``lines()``, ``table()``); see docs/collision.md.
        """
        from urdfgenpy_ros.collision import simplify_collisions
        return simplify_collisions(self, method, links, **options)

    # ---- kinematics and statics (urdfgenpy_ros.dynamics, numpy) ---------------------

    @property
    def movable_joints(self) -> list[str]:
        """Return the joints ``q`` gives values for: movable, not mimic, in joint order."""
        from urdfgenpy_ros.dynamics import movable_joints
        return movable_joints(self)

    def fk(self, q: Any = None, base: Any = None, strict: bool = False) -> Any:
        """
        Return every link's pose in the root frame, e.g. a 4x4 ``poses['tool0']``.

        ``q``: a mapping of joint names (missing ones 0), an array over
        :attr:`movable_joints`, or an (N, dof) array, which gives N x 4 x 4 poses. Mimic
        joints follow their leaders: a mapping may name them (a JointState's names and
        positions), and a value that disagrees is a warning (a ModelError with ``strict``);
        naming a fixed joint is a ModelError. ``base``: a 4x4 pose for the root.
        """
        from urdfgenpy_ros.dynamics import fk
        return fk(self, q, base, strict)

    def jacobian(self, link: str, q: Any = None, frame: str = 'world', base: Any = None,
                 strict: bool = False) -> Any:
        """
        Return the geometric Jacobian of ``link`` (6 x dof; N x 6 x dof for N configs).

        Rows: linear velocity of the link's origin, then angular velocity, in the root's
        axes (``frame='world'``) or the link's (``'local'``). Columns:
        :attr:`movable_joints`; a mimic joint counts in its leader's column. ``q`` and
        ``strict`` as for :meth:`fk`.
        """
        from urdfgenpy_ros.dynamics import jacobian
        return jacobian(self, link, q, frame, base, strict)

    def gravity_torques(self, q: Any = None, gravity: tuple[float, float, float] = (
            0.0, 0.0, -9.81), payload: dict[str, Any] | None = None, strict: bool = False
            ) -> Any:
        """
        Return the torque (N m) or force (N) each movable joint needs to hold still at ``q``.

        ``payload``: ``{'link': 'tool0', 'mass': 2.0, 'com': (0, 0, 0.05)}`` (com in the
        link's frame). A floating root is held where it is. ``q`` and ``strict`` as for
        :meth:`fk`.
        """
        from urdfgenpy_ros.dynamics import gravity_torques
        return gravity_torques(self, q, gravity, payload, strict)

    # ---- MoveIt (urdfgenpy_ros.moveit; coal, the moveit extra) -----------------------

    def to_srdf(self, path: str | PathLike[str] | None = None, **options: Any) -> str:
        """
        Return MoveIt's SRDF, its collision matrix computed as the Setup Assistant does.

        Options: ``samples`` (10000), ``seed`` (0), ``groups`` (``{'arm': (base, tip)}``),
        ``default_state`` (a group state's name), ``virtual_joint``, ``search_paths``
        (see :func:`urdfgenpy_ros.moveit.srdf.build_srdf`). Also written to ``path``.
        """
        from urdfgenpy_ros.moveit.srdf import write_srdf
        return write_srdf(self, path, **options).text

    # ---- MuJoCo --------------------------------------------------------------------

    def to_mjcf(self, path: str | PathLike[str] | None = None, **options: Any) -> str:
        """
        Return MuJoCo MJCF; with ``path``, also write it and its meshes beside it.

        Options: ``fuse_fixed``, ``base`` ('fixed' or 'floating'), ``actuators``
        ('position', 'velocity', 'motor'), ``kp``, ``kv``, ``scene``, ``overlay``,
        ``meshdir``, ``search_paths``, ``strict`` (see
        :func:`urdfgenpy_ros.formats.mjcf.write_mjcf`).
        Each thing the MJCF cannot carry is a ``UserWarning`` in ``check``'s format, as is
        what asks you to act (no actuator written, a servo that needs damping).
        """
        return write_as(self, 'mjcf', path, **options)


set_robot_class(Robot)
