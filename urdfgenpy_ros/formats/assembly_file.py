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
Assembly files: a YAML list of parts, each a description file or a builder function.

::

    name: rover_with_arm                 # optional; default: the first part's name
    parts:
      - file: rover.urdf                 # the first part is the base
      - file: arm.urdf.xacro             # .urdf, .xacro, a DH table, another assembly
        args: {dof: 4}                   # Xacro arguments
        at: base_link                    # a link of what is assembled so far
        prefix: arm_
        origin: {xyz: [0.1, 0, 0.2], rpy: [0, 0, 0]}
      - function: my_pkg.grippers:two_finger     # returns a Robot or URDF text
        at: arm_tool
        prefix: gripper_
        joint_name: arm_to_gripper       # default: <at>_to_<prefixed root>

``file`` is relative to the assembly file's folder, or ``package://pkg/...``; a part's
relative mesh paths are rewritten to stay right from there. A YAML file
is an assembly when its name ends in ``.assembly.yaml`` (``.yml``) or when it has a
top-level ``parts:`` key; other YAML files are DH tables.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
import importlib
import inspect
import math
from os import PathLike
from pathlib import Path
import re
from typing import Any, TYPE_CHECKING

from urdfgenpy_ros.model.errors import ParseError, SourceLocation, UrdfgenpyError
from urdfgenpy_ros.model.geometry import Origin

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

    Load = Callable[[Path, dict[str, str], list[Any]], RobotModel]

CODE = 'A001'
ASSEMBLY_SUFFIXES = ('.assembly.yaml', '.assembly.yml')
_TOP_KEYS = ('name', 'parts')
_PART_KEYS = ('file', 'function', 'args', 'at', 'prefix', 'origin', 'joint_name')
_PARTS_KEY = re.compile(r'^parts\s*:', re.MULTILINE)


def is_assembly(path: str | PathLike[str]) -> bool:
    """Return whether ``path`` is an assembly file (by its name, or a top-level ``parts:``)."""
    name = Path(path).name.lower()
    if name.endswith(ASSEMBLY_SUFFIXES):
        return True
    if not name.endswith(('.yaml', '.yml')):
        return False
    try:
        return _PARTS_KEY.search(Path(path).read_text(encoding='utf-8')) is not None
    except (OSError, UnicodeDecodeError):
        return False


Place = tuple[int, int]  # line, column


class _Mapping(dict):
    """A YAML mapping that remembers where it and each of its keys start."""

    line: Place = (1, 1)
    lines: dict[Any, Place]


def _loader() -> Any:
    try:
        import yaml
    except ImportError:
        from urdfgenpy_ros.model.errors import MissingDependencyError
        raise MissingDependencyError('yaml', 'dh', 'Reading an assembly file') from None

    class Loader(yaml.SafeLoader):
        pass

    def mapping(loader: Any, node: Any) -> _Mapping:
        loader.flatten_mapping(node)
        result = _Mapping()
        result.line = (node.start_mark.line + 1, node.start_mark.column + 1)
        result.lines = {}
        for key_node, value_node in node.value:
            key = loader.construct_object(key_node, deep=True)
            result[key] = loader.construct_object(value_node, deep=True)
            result.lines[key] = (key_node.start_mark.line + 1, key_node.start_mark.column + 1)
        return result

    Loader.add_constructor('tag:yaml.org,2002:map', mapping)
    return Loader


class _File:
    """The assembly file being read: says where a problem is."""

    def __init__(self, path: Path) -> None:
        self.path = path

    def error(self, place: Place, key: str | None, message: str) -> ParseError:
        where = SourceLocation(str(self.path), place[0], place[1])
        return ParseError(f"'{key}': {message}" if key else message, where, CODE)

    def at(self, mapping: _Mapping, key: str) -> Place:
        return mapping.lines.get(key, mapping.line)


def read_assembly(path: str | PathLike[str],
                  search_paths: Iterable[str | PathLike[str]] = (), *, load: Load) -> RobotModel:
    """
    Build the robot the assembly file ``path`` describes, reading its parts with ``load``.

    ``load`` is :func:`urdfgenpy_ros.formats.load` (passed in: that front door reads
    assembly files with this function).

    :raises ParseError: one line with the file, line, key and the fix (code A001).
    """
    import yaml
    file = _File(Path(path))
    text = Path(path).read_text(encoding='utf-8')
    try:
        data = yaml.load(text, Loader=_loader())  # noqa: S506 - a SafeLoader subclass
    except yaml.YAMLError as error:
        mark = getattr(error, 'problem_mark', None)
        raise ParseError(f'YAML syntax: {getattr(error, "problem", error)}',
                         SourceLocation(str(path), mark.line + 1 if mark else 1,
                                        mark.column + 1 if mark else 1), CODE) from None
    if not isinstance(data, _Mapping) or not isinstance(data.get('parts'), list) \
            or not data['parts']:
        raise file.error((1, 1), 'parts', 'an assembly file is a mapping with a non-empty list '
                         "'parts:' (- file: base.urdf, then parts with at: and prefix:)")
    _known(file, data, _TOP_KEYS)
    robot = None
    included = [str(Path(path).resolve())]
    for index, entry in enumerate(data['parts']):
        if not isinstance(entry, _Mapping):
            raise file.error(data.lines['parts'], 'parts', f'part {index + 1} is not a mapping'
                             ' (write - file: arm.urdf or - function: module:function)')
        _known(file, entry, _PART_KEYS)
        part, files = _load_part(file, entry, list(search_paths), load)
        included += files
        if robot is None:
            for key in ('at', 'prefix', 'origin', 'joint_name'):
                if key in entry:
                    raise file.error(file.at(entry, key), key, 'the first part is the base: '
                                     f"it takes no '{key}' (move it to the parts attached)")
            robot = part
            if 'name' in data:
                robot.name = _text(file, data, 'name')
            continue
        _attach(file, entry, robot, part)
    assert robot is not None
    robot.included_files = list(dict.fromkeys(included))
    return robot


def _known(file: _File, mapping: _Mapping, keys: tuple[str, ...]) -> None:
    for key in mapping:
        if key not in keys:
            import difflib
            close = difflib.get_close_matches(str(key), keys, n=1)
            hint = f'did you mean {close[0]!r}?' if close else f'known keys: {", ".join(keys)}'
            raise file.error(file.at(mapping, key), str(key), f'unknown key ({hint})')


def _text(file: _File, mapping: _Mapping, key: str) -> str:
    value = mapping[key]
    if not isinstance(value, str) or not value.strip():
        raise file.error(file.at(mapping, key), key, f'expected a non-empty string, got '
                         f'{value!r}')
    return value


def _load_part(file: _File, entry: _Mapping, search_paths: list[Any], load: Load
               ) -> tuple[RobotModel, list[str]]:
    """Return the part's robot and the files it was read from."""
    if ('file' in entry) == ('function' in entry):
        raise file.error(entry.line, 'file', "each part has either 'file:' (a .urdf, "
                         ".xacro, DH table) or 'function:' (module:function), not both")
    args = entry.get('args', {})
    if not isinstance(args, dict):
        raise file.error(file.at(entry, 'args'), 'args', 'Xacro arguments are a mapping '
                         '{name: value}')
    if 'function' in entry:
        target = _text(file, entry, 'function')
        return _from_function(file, entry, target), _module_file(target)
    from urdfgenpy_ros.resources import PackageResolver, rebase_meshes, ResourceError
    uri = _text(file, entry, 'file')
    try:
        found = PackageResolver(search_paths).resolve(uri, file.path.parent)
    except ResourceError as error:
        raise file.error(file.at(entry, 'file'), 'file', f'{error} (paths are relative to '
                         'the assembly file)') from None
    mappings = {str(name): _xacro_value(value) for name, value in args.items()}
    try:
        robot = load(found, mappings, search_paths)
    except UrdfgenpyError as error:
        raise file.error(file.at(entry, 'file'), 'file', f'part {uri}: {error}') from None
    rebase_meshes(robot, found.parent, file.path.parent)
    return robot, [str(found.resolve()), *robot.included_files]


def _xacro_value(value: object) -> str:
    if isinstance(value, bool):
        return 'true' if value else 'false'
    return str(value)


def _from_function(file: _File, entry: _Mapping, target: str) -> RobotModel:
    from urdfgenpy_ros.formats.builders import robot_from_function
    try:
        return robot_from_function(target)
    except UrdfgenpyError as error:
        raise file.error(file.at(entry, 'function'), 'function', str(error)) from None


def _module_file(target: str) -> list[str]:
    """Return the source file of the builder's module, so that ``watch`` follows it."""
    try:
        source = inspect.getsourcefile(importlib.import_module(target.partition(':')[0]))
    except (ImportError, TypeError):
        return []
    return [str(Path(source).resolve())] if source else []


def _attach(file: _File, entry: _Mapping, robot: RobotModel, part: RobotModel) -> None:
    from urdfgenpy_ros.model.errors import ModelError
    from urdfgenpy_ros.reshape.assembly import attach
    if 'at' not in entry:
        raise file.error(entry.line, 'at', 'every part after the first needs the link it '
                         f'attaches to (at: {robot.root.name})')
    at = _text(file, entry, 'at')
    prefix = entry.get('prefix', '')
    if not isinstance(prefix, str):
        raise file.error(file.at(entry, 'prefix'), 'prefix', f'expected text, got {prefix!r}'
                         " (quote it: prefix: 'arm_')")
    origin = _origin(file, entry)
    joint_name = _text(file, entry, 'joint_name') if 'joint_name' in entry else None
    try:
        attach(robot, part, at, origin, prefix, joint_name)
    except ModelError as error:
        key = 'at' if not robot.has_link(at) else \
            'joint_name' if _only_joint_name_taken(robot, part, prefix, joint_name) else 'prefix'
        raise file.error(file.at(entry, key), key, str(error)) from None


def _only_joint_name_taken(robot: RobotModel, part: RobotModel, prefix: str,
                           joint_name: str | None) -> bool:
    """Return whether a given ``joint_name`` is taken while the prefixed part's names are not."""
    if joint_name is None:
        return False
    joints = {prefix + joint.name for joint in part.joints}
    return (robot.has_joint(joint_name) or joint_name in joints) and not any(
        robot.has_link(prefix + link.name) for link in part.links) and not any(
        robot.has_joint(name) for name in joints)


def _origin(file: _File, entry: _Mapping) -> Origin:
    value = entry.get('origin', {})
    line = file.at(entry, 'origin')
    if not isinstance(value, dict) or set(value) - {'xyz', 'rpy'}:
        raise file.error(line, 'origin', 'expected {xyz: [x, y, z], rpy: [roll, pitch, yaw]}'
                         ' (metres, radians)')
    vectors = []
    for key in ('xyz', 'rpy'):
        vector = value.get(key, [0.0, 0.0, 0.0])
        if not isinstance(vector, list) or len(vector) != 3 or not all(
                isinstance(number, (int, float)) and not isinstance(number, bool)
                and math.isfinite(number) for number in vector):
            raise file.error(line, f'origin.{key}', f'expected 3 finite numbers [a, b, c], '
                             f'got {vector!r}')
        vectors.append(tuple(float(number) for number in vector))
    return Origin(vectors[0], vectors[1])
