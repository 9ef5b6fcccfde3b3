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
One declaration per URDF element: its attributes (type, default, model field) and children.

The reader, the writer, what is preserved and how edits are detected all follow from this
table. To support a new URDF attribute, add the field to the model class and one
:class:`Attr` line here; a new element is one :class:`Element` entry (and its class).
"""

from __future__ import annotations

from collections.abc import Callable
import types
from typing import Any, NamedTuple

from urdfgenpy_ros.model.geometry import Box, Capsule, Cylinder, IDENTITY, Mesh, Origin, Sphere
from urdfgenpy_ros.model.inertial import INERTIA_ATTRS, Inertial
from urdfgenpy_ros.model.joint import (
    Joint, JointCalibration, JointDynamics, JointLimit, JointMimic, SafetyController)
from urdfgenpy_ros.model.link import Collision, Link, Visual
from urdfgenpy_ros.model.material import Material


class _Required:
    """The default of an attribute a file must give."""

    def __repr__(self) -> str:
        return 'REQUIRED'


REQUIRED: Any = _Required()
FLOAT, VEC3, VEC4, TEXT = 'float', 'vec3', 'vec4', 'text'
LENGTHS = {VEC3: 3, VEC4: 4}
"""How many numbers a vector attribute holds."""
_ZERO3 = (0.0, 0.0, 0.0)


class Attr(NamedTuple):
    """An attribute: XML ``name``, the model ``field`` it fills, its kind and default."""

    name: str
    field: str
    kind: str = FLOAT
    default: Any = REQUIRED  # REQUIRED: the reader refuses a file without it
    expected: str = ''  # what a missing required attribute should hold (for the message)
    unless: str = ''  # a field that, when not None, is written instead of this one


class Child(NamedTuple):
    """
    A known child element.

    ``field`` names the owner's field that holds the child's model object; None means the
    child has no object of its own and its attributes are fields of the owner (``<mass>``).
    ``many`` children fill a list; ``optional`` field-less children are left out while all
    their fields are None; ``missing`` is the message for a required child that is absent.
    """

    tags: tuple[str, ...]
    field: str | None = None
    many: bool = False
    optional: bool = False
    missing: str = ''


class Element(NamedTuple):
    """A URDF element: tag, attributes, children in written order, and its model class."""

    tag: str
    attrs: tuple[Attr, ...] = ()
    children: tuple[Child, ...] = ()
    cls: type | None = None
    make: Callable[..., Any] | None = None  # builds ``cls`` from the fields, when not cls(**)


def _box(size: tuple[float, float, float], **hidden: Any) -> Box:
    return Box(*size, **hidden)


_SHAPES = 'box, cylinder, sphere, capsule or mesh'
ORIGIN = Element('origin', (Attr('xyz', 'xyz', VEC3, _ZERO3),
                            Attr('rpy', 'rpy', VEC3, _ZERO3, unless='quat_xyzw'),
                            Attr('quat_xyzw', 'quat_xyzw', VEC4, None)), cls=Origin)
BOX = Element('box', (Attr('size', 'size', VEC3),), cls=Box, make=_box)
CYLINDER = Element('cylinder', (Attr('radius', 'radius'), Attr('length', 'length')),
                   cls=Cylinder)
SPHERE = Element('sphere', (Attr('radius', 'radius'),), cls=Sphere)
CAPSULE = Element('capsule', (Attr('radius', 'radius'), Attr('length', 'length')),
                  cls=Capsule)
MESH = Element('mesh', (Attr('filename', 'filename', TEXT), Attr('scale', 'scale', VEC3, None)),
               cls=Mesh)
GEOMETRY = Element('geometry', (), (
    Child(('box', 'cylinder', 'sphere', 'capsule', 'mesh'), 'geometry'),))
MASS = Element('mass', (Attr('value', 'mass'),))
INERTIA = Element('inertia', tuple(Attr(name, name) for name in INERTIA_ATTRS))
INERTIAL = Element('inertial', (), (
    Child(('origin',), 'origin'),
    Child(('mass',), missing='missing <mass value=...> (the mass in kg)'),
    Child(('inertia',), missing='missing <inertia ixx=... izz=...> (the tensor about the '
                                'centre of mass)')), cls=Inertial)
COLOR = Element('color', (Attr('rgba', 'rgba', VEC4),))
TEXTURE = Element('texture', (Attr('filename', 'texture', TEXT, ''),))
MATERIAL = Element('material', (Attr('name', 'name', TEXT, expected='the material name'),), (
    Child(('color',), optional=True), Child(('texture',), optional=True)), cls=Material)
_GEOMETRY_CHILD = Child(('geometry',), missing=f'missing <geometry> (give a {_SHAPES})')
VISUAL = Element('visual', (Attr('name', 'name', TEXT, None),), (
    Child(('origin',), 'origin'), _GEOMETRY_CHILD, Child(('material',), 'material')),
    cls=Visual)
COLLISION = Element('collision', (Attr('name', 'name', TEXT, None),), (
    Child(('origin',), 'origin'), _GEOMETRY_CHILD), cls=Collision)
LINK = Element('link', (Attr('name', 'name', TEXT, expected='the link name'),), (
    Child(('inertial',), 'inertial'), Child(('visual',), 'visuals', many=True),
    Child(('collision',), 'collisions', many=True)), cls=Link)
PARENT = Element('parent', (Attr('link', 'parent', TEXT, expected='the parent link name'),))
CHILD = Element('child', (Attr('link', 'child', TEXT, expected='the child link name'),))
AXIS = Element('axis', (Attr('xyz', 'axis', VEC3, (1.0, 0.0, 0.0)),))
CALIBRATION = Element('calibration', (Attr('rising', 'rising', FLOAT, None),
                                      Attr('falling', 'falling', FLOAT, None)),
                      cls=JointCalibration)
DYNAMICS = Element('dynamics', (Attr('damping', 'damping', FLOAT, 0.0),
                                Attr('friction', 'friction', FLOAT, 0.0)), cls=JointDynamics)
LIMIT = Element('limit', (Attr('lower', 'lower', FLOAT, 0.0), Attr('upper', 'upper', FLOAT, 0.0),
                          Attr('effort', 'effort'), Attr('velocity', 'velocity'),
                          Attr('acceleration', 'acceleration', FLOAT, None),
                          Attr('deceleration', 'deceleration', FLOAT, None),
                          Attr('jerk', 'jerk', FLOAT, None)),
                cls=JointLimit)
MIMIC = Element('mimic', (Attr('joint', 'joint', TEXT,
                               expected='the name of the joint to follow'),
                          Attr('multiplier', 'multiplier', FLOAT, 1.0),
                          Attr('offset', 'offset', FLOAT, 0.0)), cls=JointMimic)
SAFETY_CONTROLLER = Element('safety_controller', (
    Attr('soft_lower_limit', 'soft_lower_limit', FLOAT, 0.0),
    Attr('soft_upper_limit', 'soft_upper_limit', FLOAT, 0.0),
    Attr('k_position', 'k_position', FLOAT, 0.0), Attr('k_velocity', 'k_velocity')),
    cls=SafetyController)
JOINT = Element('joint', (Attr('name', 'name', TEXT, expected='the joint name'),
                          Attr('type', 'type', TEXT)), (
    Child(('origin',), 'origin'),
    Child(('parent',), missing='missing <parent link=...> (the parent link)'),
    Child(('child',), missing='missing <child link=...> (the child link)'),
    Child(('axis',), optional=True), Child(('calibration',), 'calibration'),
    Child(('dynamics',), 'dynamics'), Child(('limit',), 'limit'), Child(('mimic',), 'mimic'),
    Child(('safety_controller',), 'safety_controller')), cls=Joint)

ELEMENTS: dict[str, Element] = {element.tag: element for element in (
    ORIGIN, BOX, CYLINDER, SPHERE, CAPSULE, MESH, GEOMETRY, MASS, INERTIA, INERTIAL, COLOR,
    TEXTURE, MATERIAL, VISUAL, COLLISION, LINK, PARENT, CHILD, AXIS, CALIBRATION, DYNAMICS,
    LIMIT, MIMIC, SAFETY_CONTROLLER, JOINT)}
"""Every URDF element below ``<robot>``, by tag."""

SLOTS: dict[str, dict[str, Child]] = {
    tag: {name: child for child in element.children for name in child.tags}
    for tag, element in ELEMENTS.items()}
"""Per element tag, the declaration each child tag fills."""


MAY_BE_UNUSABLE = frozenset((('link', 'inertial'), ('visual', 'material')))
"""The (owner, child) tags for which :func:`unusable` can find a reason."""


def unusable(tag: str, node: Any) -> str | None:
    """
    Return why urdfdom drops the child ``node`` of a ``tag`` element, or None if it reads it.

    urdfdom logs such a child and reads on; so does the reader (with a warning), and the
    writer keeps the child as written, like an unknown one, until the model gets a value
    for it, which then takes its place.
    """
    if node.tag == 'inertial' and tag == 'link':
        for _ in node.iterchildren('inertia'):
            return None
        return '<inertial> without <inertia> (MuJoCo refuses it): add <inertia ixx=... izz=.../>'
    if node.tag == 'material' and tag == 'visual' and node.get('name') is None:
        return ('<material> without a name (urdfdom then drops the whole <visual>, so RViz '
                'does not show it): name it, e.g. <material name="red">')
    if node.tag == 'material' and tag == 'visual' and len(node):
        color = next(node.iterchildren('color'), None)
        rgba = color.get('rgba') if color is not None else None
        if rgba is not None and not _numbers(rgba, 4):
            return (f'<material> colour rgba {rgba!r} is not 4 numbers (MuJoCo refuses it): '
                    'write red green blue alpha, each 0..1')
    return None


def _numbers(text: str, count: int) -> bool:
    parts = text.split()
    try:
        return len([float(part) for part in parts]) == count
    except ValueError:
        return False


def slot_of(tag: str, node: Any) -> Child | None:
    """Return the declaration the source child ``node`` of a ``tag`` element fills, or None."""
    if unusable(tag, node) is not None:
        return None
    return SLOTS[tag].get(node.tag)


OF_CLASS: dict[type, Element] = {element.cls: element for element in ELEMENTS.values()
                                 if element.cls is not None}
"""The declaration of each model class."""

_FROZEN = (Origin, Box, Cylinder, Sphere, Capsule, Mesh, Material)
DEFAULT_CHILD: dict[str, Any] = {'origin': IDENTITY}
"""The value of an object child the file leaves out (others: None, or an empty list)."""


def _plan(element: Element) -> tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]]:
    """Return the element's value fields, mutable object children and list children."""
    values: list[str] = [attr.field for attr in element.attrs]
    nested: list[str] = []
    lists: list[str] = []
    for child in element.children:
        if child.field is None:
            inner = _plan(ELEMENTS[child.tags[0]])
            values += inner[0]
            nested += inner[1]
            lists += inner[2]
        elif child.many:
            lists.append(child.field)
        elif ELEMENTS[child.tags[0]].cls in _FROZEN or child.tags[0] in GEOMETRY.children[0].tags:
            values.append(child.field)
        else:
            nested.append(child.field)
    return tuple(values), tuple(nested), tuple(lists)


_PLANS = {cls: _plan(element) for cls, element in OF_CLASS.items()}


def plan(cls: type) -> tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...]]:
    """Return the fields a snapshot of a ``cls`` holds: values, nested objects, lists."""
    return _PLANS[cls]


def raw_field(cls: type, name: str) -> str:
    """
    Return the attribute that reads or sets field ``name`` of ``cls`` fastest: its bare slot.

    A field whose setter counts edits or renames (``Joint.parent``, ``Link.name``) has its
    slot also under ``<name>_slot``: the compiled readers, writers and snapshots use it.
    """
    slot = getattr(cls, f'{name}_slot', None)  # a slot whose setter counts edits keeps it
    return f'{name}_slot' if isinstance(slot, types.MemberDescriptorType) else name


def _compile_values() -> dict[type, Callable[[Any], tuple]]:
    """Return, per model class, a function that takes a by-value snapshot of an object."""
    namespace: dict[str, Any] = {}
    for number, (cls, (fields, nested, lists)) in enumerate(_PLANS.items()):
        read = {name: raw_field(cls, name) for name in (*fields, *nested, *lists)}
        parts = [f'item.{read[name]}' for name in fields]
        parts += [f'(None if (part := item.{read[name]}) is None else V[type(part)](part))'
                  for name in nested]
        parts += [f'tuple([V[type(part)](part) for part in item.{read[name]}])'
                  for name in lists]
        code = f'def values_{number}(item):\n    return ({", ".join(parts)},)'
        exec(compile(code, f'<values {cls.__name__}>', 'exec'), namespace)  # noqa: S102
    functions = {cls: namespace[f'values_{number}'] for number, cls in enumerate(_PLANS)}
    namespace['V'] = functions
    return functions


_VALUES: dict[type, Callable[[Any], tuple]] = {}  # compiled on first use (start-up)


def values(item: Any) -> tuple:
    """
    Return a by-value snapshot of a model element: equal snapshots, nothing was edited.

    Frozen parts (origins, shapes, materials) compare by value as they are; mutable ones
    (inertials, limits, visuals ...) are taken apart, so a later edit shows.
    """
    if not _VALUES:
        _VALUES.update(_compile_values())
    return _VALUES[type(item)](item)


def record(item: Any) -> tuple:
    """Store the snapshot of ``item`` and of every part of it read from a file; return it."""
    fields, nested, lists = _PLANS[type(item)]
    snapshot = []
    for name in fields:
        part = getattr(item, name)
        snapshot.append(part)
        if type(part) in _PLANS and part.extras is not None and part.extras.snapshot is None:
            part.extras.snapshot = values(part)
    for name in nested:
        part = getattr(item, name)
        snapshot.append(None if part is None else record(part))
    for name in lists:
        snapshot.append(tuple([record(part) for part in getattr(item, name)]))
    result = tuple(snapshot)
    if item.extras is not None:
        item.extras.snapshot = result
    return result
