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
The model layer's robot: links joined into a tree by joints, with materials and extensions.

``RobotModel`` holds the data and the tree and imports nothing above the model;
:class:`urdfgenpy_ros.robot.Robot` adds reading, writing, checking and reshaping, which
call down into ``formats``, ``validation``, ``reshape`` and the rest. Those never import
``Robot`` to run: a reader builds the class it is told (``Robot.from_urdf`` passes
``cls``) or else :func:`robot_class`, which ``robot.py`` sets to ``Robot``; a copy is made
by ``copy.deepcopy`` or ``type(robot)(...)``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from typing import Any, TYPE_CHECKING, TypeVar

from urdfgenpy_ros.model import checks
from urdfgenpy_ros.model.edits import edited
from urdfgenpy_ros.model.errors import ModelError, ModelTypeError, ReadWarning, SourceLocation
from urdfgenpy_ros.model.extensions import Extension
from urdfgenpy_ros.model.joint import Joint
from urdfgenpy_ros.model.link import Link
from urdfgenpy_ros.model.material import Material
from urdfgenpy_ros.model.preserved import SourceDocument

if TYPE_CHECKING:
    from typing_extensions import Self


def _suggest(name: str, known: Any) -> str:
    import difflib  # only when a name is not found: not at every start
    if not isinstance(name, str):  # get_link(None): no name is close to that
        return ''
    close = difflib.get_close_matches(name, list(known), n=1)
    return f' (did you mean {close[0]!r}?)' if close else ''


class RobotModel:
    """
    A robot's data and tree: build it, navigate it, edit it (``Robot`` adds the rest).

    Links, joints and materials keep the order they were added in, which is the order
    they are written in. Names are unique within each kind.
    """

    def __init__(self, name: str) -> None:
        self.name = checks.name('robot', name)
        self._links: dict[str, Link] = {}
        self._joints: dict[str, Joint] = {}
        self._materials: dict[str, Material] = {}
        self.extensions: list[Extension] = []
        self.source: SourceLocation | None = None
        self.urdf_version: str | None = None  # the <robot version=...> given (None: 1.0)
        self.extras: SourceDocument | None = None  # the record of the file read, if any
        self.read_warnings: list[ReadWarning] = []
        self.included_files: list[str] = []
        self.source_map: Any = None  # formats.xacro_map.XacroMap: where a Xacro's text came from

    def __repr__(self) -> str:
        """Return a one-line summary."""
        return (f'Robot({self.name!r}, links={len(self._links)}, '
                f'joints={len(self._joints)})')

    def __eq__(self, other: object) -> bool:
        """Compare name, links, joints, materials and extensions (order included)."""
        if not isinstance(other, RobotModel):
            return NotImplemented
        return (self.name == other.name and self.links == other.links
                and self.joints == other.joints and self.materials == other.materials
                and self.extensions == other.extensions)

    __hash__ = None  # type: ignore[assignment]

    # ---- building ------------------------------------------------------------------

    def add_link(self, link: Link) -> Self:
        """Add a link and return the robot; its name must be new."""
        if type(link) is not Link and not isinstance(link, Link):
            raise ModelTypeError(f'robot {self.name!r}: add_link() takes a Link, '
                                 f'got {type(link).__name__}')
        links = self._links
        name = link.name_slot  # the slot: no property call
        if name in links:
            raise ModelError(f'robot {self.name!r}: link {name!r} already exists '
                             '(link names must be unique: rename one)')
        links[name] = link
        link._robot = self
        edited()
        return self

    def add_joint(self, joint: Joint) -> Self:
        """Add a joint between two links already added and return the robot."""
        if type(joint) is not Joint and not isinstance(joint, Joint):
            raise ModelTypeError(f'robot {self.name!r}: add_joint() takes a Joint, '
                                 f'got {type(joint).__name__}')
        joints = self._joints
        name = joint.name_slot
        if name in joints:
            raise ModelError(f'robot {self.name!r}: joint {name!r} already exists '
                             '(joint names must be unique: rename one)')
        links = self._links
        parent, child = joint.parent_slot, joint.child_slot
        if (parent not in links or child not in links or parent == child) and checks.is_on():
            for role, link in (('parent', parent), ('child', child)):
                if link not in links:
                    raise ModelError(
                        f'joint {name!r}: {role} link {link!r} is not in robot '
                        f'{self.name!r}{_suggest(link, links)} '
                        '(add the link before the joint)')
            raise ModelError(f'joint {name!r}: parent and child are both '
                             f'{child!r} (a joint connects two different links)')
        joints[name] = joint
        joint._robot = self
        edited()
        return self

    def add_material(self, material: Material) -> Self:
        """Add a robot-level material and return the robot; its name must be new."""
        if not isinstance(material, Material):
            raise ModelTypeError(f'robot {self.name!r}: add_material() takes a Material, '
                                 f'got {type(material).__name__}')
        if material.name in self._materials:
            raise ModelError(f'robot {self.name!r}: material {material.name!r} already '
                             'exists (material names must be unique: rename one)')
        self._materials[material.name] = material
        return self

    def add_extension(self, extension: Extension) -> Self:
        """Add a robot-level ``<gazebo>``, ``<transmission>`` or ``<ros2_control>``."""
        self.extensions.append(extension)
        return self

    # ---- access --------------------------------------------------------------------

    @property
    def links(self) -> list[Link]:
        """Return the links in order."""
        return list(self._links.values())

    @property
    def joints(self) -> list[Joint]:
        """Return the joints in order."""
        return list(self._joints.values())

    @property
    def materials(self) -> list[Material]:
        """Return the robot-level materials in order."""
        return list(self._materials.values())

    def get_link(self, name: str) -> Link:
        """Return the link called ``name``; raise KeyError naming a close match."""
        try:
            return self._links[name]
        except KeyError:
            raise KeyError(f'robot {self.name!r} has no link {name!r}'
                           f'{_suggest(name, self._links)}') from None

    def get_joint(self, name: str) -> Joint:
        """Return the joint called ``name``; raise KeyError naming a close match."""
        try:
            return self._joints[name]
        except KeyError:
            raise KeyError(f'robot {self.name!r} has no joint {name!r}'
                           f'{_suggest(name, self._joints)}') from None

    def get_material(self, name: str) -> Material:
        """Return the robot-level material called ``name``."""
        try:
            return self._materials[name]
        except KeyError:
            raise KeyError(f'robot {self.name!r} has no material {name!r}'
                           f'{_suggest(name, self._materials)}') from None

    def has_link(self, name: str) -> bool:
        """Return whether a link called ``name`` exists."""
        return name in self._links

    def has_joint(self, name: str) -> bool:
        """Return whether a joint called ``name`` exists."""
        return name in self._joints

    def has_material(self, name: str) -> bool:
        """Return whether a robot-level material called ``name`` exists."""
        return name in self._materials

    # ---- navigation ----------------------------------------------------------------

    def _children_index(self) -> dict[str, list[Joint]]:
        index: dict[str, list[Joint]] = {}
        for joint in self._joints.values():
            index.setdefault(joint.parent, []).append(joint)
        return index

    @property
    def roots(self) -> list[Link]:
        """Return every link that is no joint's child."""
        children = {joint.child for joint in self._joints.values()}
        return [link for name, link in self._links.items() if name not in children]

    @property
    def root(self) -> Link:
        """Return the root link; raise ValueError unless there is exactly one."""
        roots = self.roots
        if len(roots) != 1:
            names = ', '.join(repr(link.name) for link in roots) or 'none (a loop?)'
            raise ModelError(f'robot {self.name!r} must have exactly one root link, '
                             f'found {names} (connect them with joints)')
        return roots[0]

    def parent_joint(self, link: str | Link) -> Joint | None:
        """Return the joint whose child is ``link``, or None for a root."""
        name = link.name if isinstance(link, Link) else link
        for joint in self._joints.values():
            if joint.child == name:
                return joint
        return None

    def parent_link(self, link: str | Link) -> Link | None:
        """Return the parent link of ``link``, or None for a root."""
        joint = self.parent_joint(link)
        return self._links.get(joint.parent) if joint is not None else None

    def child_joints(self, link: str | Link) -> list[Joint]:
        """Return the joints whose parent is ``link``, in order."""
        name = link.name if isinstance(link, Link) else link
        return [joint for joint in self._joints.values() if joint.parent == name]

    def child_links(self, link: str | Link) -> list[Link]:
        """Return the child links of ``link``, in joint order."""
        return [self._links[joint.child] for joint in self.child_joints(link)
                if joint.child in self._links]

    def walk(self, start: str | Link | None = None) -> Iterator[tuple[Joint | None, Link]]:
        """
        Yield ``(parent joint, link)`` depth-first from ``start`` (default: the root).

        Each link is visited once, so a faulty model with a loop still terminates.
        """
        first = self.root if start is None else (
            start if isinstance(start, Link) else self.get_link(start))
        index = self._children_index()
        seen = {first.name}
        stack: list[tuple[Joint | None, Link]] = [(None, first)]
        while stack:
            joint, link = stack.pop()
            yield joint, link
            for child_joint in reversed(index.get(link.name, ())):
                child = self._links.get(child_joint.child)
                if child is not None and child.name not in seen:
                    seen.add(child.name)
                    stack.append((child_joint, child))

    def subtree(self, link: str | Link) -> list[Link]:
        """Return ``link`` and every link below it, depth-first."""
        return [node for _, node in self.walk(link)]

    def chain(self, tip: str | Link, base: str | Link | None = None) -> list[Joint]:
        """Return the joints from ``base`` (default: the root) down to ``tip``."""
        base_name = None if base is None else (base.name if isinstance(base, Link) else base)
        joints: list[Joint] = []
        current = tip.name if isinstance(tip, Link) else self.get_link(tip).name
        while current != base_name:
            joint = self.parent_joint(current)
            if joint is None:
                if base_name is None:
                    break
                raise ModelError(f'link {current!r} is not below {base_name!r}')
            joints.append(joint)
            current = joint.parent
            if len(joints) > len(self._joints):
                raise ModelError(f'robot {self.name!r}: the chain to {tip!r} has a loop')
        return joints[::-1]

    # ---- editing -------------------------------------------------------------------

    def remove_joint(self, name: str) -> Joint:
        """Remove a joint and return it; its child link becomes a root."""
        joint = self.get_joint(name)
        del self._joints[name]
        joint._robot = None
        edited()
        return joint

    def remove_link(self, name: str, *, subtree: bool = False) -> list[Link]:
        """
        Remove a link and its parent joint; return what was removed.

        A link with children is refused unless ``subtree=True``, which removes every
        link and joint below it too.
        """
        link = self.get_link(name)
        below = self.subtree(link)
        if len(below) > 1 and not subtree:
            children = ', '.join(repr(child.name) for child in self.child_links(link))
            raise ModelError(f'link {name!r} has child links {children}: pass '
                             'subtree=True to remove them too, or re-attach them first')
        doomed = {node.name for node in below}
        for joint in list(self._joints.values()):
            if joint.child in doomed or joint.parent in doomed:
                del self._joints[joint.name]
                joint._robot = None
        for node in below:
            del self._links[node.name]
            node._robot = None
        edited()
        return below

    def remove_material(self, name: str) -> Material:
        """Remove a robot-level material and return it."""
        material = self.get_material(name)
        del self._materials[name]
        return material

    def rename_material(self, old: str, new: str) -> Material:
        """Rename a robot-level material and every visual that uses it."""
        self.get_material(old)
        if new in self._materials and new != old:
            raise ModelError(f'cannot rename material {old!r} to {new!r}: name taken')
        self._rename_materials({old: checks.name('material', new)})
        return self.get_material(new)

    def _rename_materials(self, names: Mapping[str, str]) -> None:
        """
        Rename materials, old name to new, robot-level or defined by visuals.

        The robot's list keeps its order; a visual sharing a definition shares the renamed
        one; a visual's own material of a renamed name is renamed (what it read is kept).
        """
        def renamed(material: Material) -> Material:
            return Material(names[material.name], material.rgba, material.texture,
                            source=material.source, extras=material.extras)

        new = {id(material): renamed(material) for material in self._materials.values()
               if material.name in names}
        self._materials = {names.get(name, name): new.get(id(material), material)
                           for name, material in self._materials.items()}
        for link in self._links.values():
            for visual in link.visuals:
                material = visual.material
                if material is not None and material.name in names:
                    visual.material = new.get(id(material)) or renamed(material)

    def _holds(self, kind: str, name: str, element: object) -> bool:
        """Return whether ``element`` is this robot's link (or joint) of that name."""
        held = self._links if kind == 'link' else self._joints
        return held.get(name) is element

    def _map_materials(self, change: Callable[[Material], Material]) -> None:
        """Replace each robot-level material by ``change(material)`` (same name, same place)."""
        self._materials = {name: change(material) for name, material in self._materials.items()}

    def _reindex(self) -> None:
        """Key links and joints by their names again, after they were renamed in place."""
        self._links = {link.name: link for link in self._links.values()}
        self._joints = {joint.name: joint for joint in self._joints.values()}
        edited()


RobotT = TypeVar('RobotT', bound=RobotModel)
"""A robot of some class, given back as that class (``Robot`` stays ``Robot``)."""
_built: list[type[RobotModel]] = []


def robot_class() -> type[RobotModel]:
    """Return the class a reader builds when not told one: ``Robot``, set by ``robot.py``."""
    return _built[-1]


def set_robot_class(cls: type[RobotModel]) -> None:
    """Make readers not told a class build ``cls`` (``robot.py`` gives ``Robot``)."""
    _built[:] = [cls]
