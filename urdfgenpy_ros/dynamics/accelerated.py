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
Poses, gravity torques and Jacobians through pinocchio where installed: the same numbers.

pinocchio is not read from a file: its model is built from the compiled arrays of
:mod:`.model` and the masses of :mod:`.gravity`, once per compiled model (a new one when
the tree changed) and again when an inertial changed. Every joint a value moves (a mimic
one too) is an unaligned revolute or prismatic joint; fixed, floating and planar joints
are merged into the placement of what they carry, as the numpy path keeps them at their
origin.
q is spread over pinocchio's joints by the mimic formula, and pinocchio's torques and
Jacobian columns are folded back (a mimic joint's times its multiplier, added to its
leader's), as the numpy path does. One configuration's link poses stay pinocchio's
placements until read (:class:`PlacedPoses`): each is turned into a 4x4 array when asked
for, as reading every one of them costs ten times pinocchio's forward kinematics.
Without pinocchio, nothing here is used.
"""

from __future__ import annotations

from collections.abc import Mapping
import copy
import operator
from typing import Any, TYPE_CHECKING
import weakref

import numpy

from urdfgenpy_ros.dynamics.forward import LinkPoses
from urdfgenpy_ros.dynamics.gravity import mass_model, MassModel
from urdfgenpy_ros.dynamics.model import ChainModel, REVOLUTE

if TYPE_CHECKING:
    from urdfgenpy_ros.model import RobotModel

FOLD_BY_ROUNDS = 64  # configurations: fewer are folded by one reduceat
_MODULE: list[Any] = []  # [pinocchio or None], once looked for


def _pinocchio() -> Any:
    if not _MODULE:
        try:
            import pinocchio
        except (ImportError, OSError):  # not installed, or its libraries not loadable
            pinocchio = None
        _MODULE.append(pinocchio)
    return _MODULE[0]


class Accelerated:
    """A pinocchio model and data of one compiled model and its masses."""

    def __init__(self, pin: Any, chain: ChainModel, masses: MassModel) -> None:
        self.pin, self.chain = pin, chain
        self.mass = masses.mass.copy()
        self.moment = masses.moment.copy()
        model = pin.Model()
        joint = numpy.zeros(len(chain.links), dtype=int)  # pinocchio joint carrying each
        placement = numpy.tile(numpy.eye(4), (len(chain.links), 1, 1))  # link in that joint
        moving: list[int] = []
        for link in range(1, len(chain.links)):
            parent = int(chain.parent[link])
            local = placement[parent] @ chain.origin[link]
            if chain.source[link] >= 0:
                kind = (pin.JointModelRevoluteUnaligned if chain.motion[link] == REVOLUTE
                        else pin.JointModelPrismaticUnaligned)
                joint[link] = model.addJoint(int(joint[parent]), kind(chain.axis[link].copy()),
                                             pin.SE3(local), f'{chain.joints[link]}#{link}')
                moving.append(link)
            else:
                joint[link], placement[link] = joint[parent], local
        self.frames = [self._body(model, link, int(joint[link]), placement[link])
                       for link in range(len(chain.links))]
        self.model, self.data = model, model.createData()
        # q to pinocchio's joints and back without a matrix product (BLAS's threads spin)
        self.column, self.factor = chain.source[moving], chain.multiplier[moving]
        self.offset = chain.offset[moving]
        self.mimics = bool((self.factor != 1.0).any() or self.offset.any())
        self._folding(len(chain.movable))
        self.gravity = model.gravity.linear.copy()
        self.state: tuple[list, list] = ([], [])  # the masses' mass_state when made

    def _folding(self, columns: int) -> None:
        """Plan :meth:`_fold`: each column's first joint, then its others round by round."""
        self.order = numpy.argsort(self.column, kind='stable')  # each column's joints together
        self.starts = numpy.searchsorted(self.column[self.order], numpy.arange(columns))
        self.heads = self.order[self.starts]
        self.scaled = not bool((self.factor[self.heads] == 1.0).all())
        rank = numpy.arange(len(self.order)) - self.starts[self.column[self.order]]
        self.rounds = [(self.column[self.order[rank == number]], self.order[rank == number])
                       for number in range(1, int(rank.max(initial=0)) + 1)]
        self.plain = (not self.scaled and not self.rounds
                      and bool((self.heads == numpy.arange(len(self.heads))).all()))

    def _body(self, model: Any, link: int, joint: int, placement: numpy.ndarray) -> int:
        pin, mass = self.pin, float(self.mass[link])
        com = self.moment[link] / mass if mass > 0.0 else numpy.zeros(3)
        inertia = pin.Inertia(mass, com, numpy.zeros((3, 3)))
        model.appendBodyToJoint(joint, inertia, pin.SE3(placement))
        return int(model.addFrame(pin.Frame(f'{self.chain.links[link]}#{link}', joint, 0,
                                            pin.SE3(placement), pin.FrameType.OP_FRAME)))

    def gravity_torques(self, q: numpy.ndarray, gravity: numpy.ndarray) -> numpy.ndarray:
        """Return the (N, dof) torques at the (N, dof) configurations ``q``."""
        if not numpy.array_equal(gravity, self.gravity):
            self.model.gravity.linear = gravity
            self.gravity = gravity.copy()
        pin, model, data = self.pin, self.model, self.data
        found = numpy.empty((len(q), model.nv))
        for number, values in enumerate(self._spread(q)):
            found[number] = pin.computeGeneralizedGravity(model, data, values)
        return self._fold(found)

    def jacobian(self, link: int, q: numpy.ndarray, local: bool) -> numpy.ndarray:
        """Return the (N, 6, dof) Jacobians of link number ``link``."""
        pin, model, data = self.pin, self.model, self.data
        frame = self.frames[link]
        where = pin.LOCAL if local else pin.LOCAL_WORLD_ALIGNED
        found = numpy.empty((len(q), 6, model.nv))
        flat = found.reshape(len(q), 6 * model.nv)  # pinocchio gives one column 1-D
        for number, values in enumerate(self._spread(q)):
            flat[number] = pin.computeFrameJacobian(model, data, values, frame, where).ravel()
        return self._fold(found)

    def poses(self, q: numpy.ndarray) -> PlacedPoses:
        """Return every link's pose at the one configuration ``q`` (a (1, dof) array)."""
        values = q[0].take(self.column)
        if self.mimics:
            numpy.multiply(values, self.factor, out=values)
            numpy.add(values, self.offset, out=values)
        self.pin.framesForwardKinematics(self.model, self.data, values)
        return PlacedPoses(self.chain.links, self.chain.index, copy.copy(self.data.oMf),
                           self.frames)

    def _spread(self, q: numpy.ndarray) -> numpy.ndarray:
        """Return each pinocchio joint's value: its column of ``q`` by the mimic formula."""
        return q[:, self.column] * self.factor + self.offset

    def _fold(self, found: numpy.ndarray) -> numpy.ndarray:
        """Return pinocchio's last axis over our columns: each joint's times its multiplier."""
        if self.plain:  # one joint a column, in order: nothing to fold
            return found
        if len(found) < FOLD_BY_ROUNDS:  # one pass over a small copy
            return numpy.add.reduceat((found * self.factor)[..., self.order], self.starts,
                                      axis=-1)
        result = found.take(self.heads, axis=-1)  # no copy of every joint's answers
        if self.scaled:
            result *= self.factor[self.heads]
        for columns, joints in self.rounds:  # a column once a round
            result[..., columns] += found[..., joints] * self.factor[joints]
        return result


class PlacedPoses(LinkPoses):
    """
    Link poses held as pinocchio's placements, each made a 4x4 array when first read.

    As :class:`LinkPoses`: ``poses[link]`` is a view of ``poses.array``, which is filled
    row by row as links are read, and whole when ``array`` itself is asked for.
    """

    def __init__(self, links: tuple[str, ...], index: Mapping[str, int], placements: Any,
                 frames: list[int]) -> None:
        self.links, self._index = links, index
        self._placements, self._frames = placements, frames
        self._rows: numpy.ndarray | None = None  # made at the first read
        self._unread = bytearray(b'\x01') * len(links)  # rows not filled yet

    @property
    def array(self) -> numpy.ndarray:
        """Return every link's pose, (L, 4, 4), links in ``links`` order."""
        for number in [number for number, unread in enumerate(self._unread) if unread]:
            self._fill(number)
        return self._filled()

    @array.setter
    def array(self, value: numpy.ndarray) -> None:
        self._rows, self._unread = value, bytearray(len(self.links))

    def _filled(self) -> numpy.ndarray:
        if self._rows is None:
            self._rows = numpy.empty((len(self.links), 4, 4))
        return self._rows

    def _fill(self, number: int) -> numpy.ndarray:
        rows = self._filled()
        rows[number] = self._placements[self._frames[number]].homogeneous
        self._unread[number] = 0
        return rows

    def __getitem__(self, link: str) -> numpy.ndarray:
        """Return the pose of ``link``."""
        try:
            number = self._index[link]
        except KeyError:
            raise KeyError(f'{link!r} is not a link of the robot') from None
        rows = self._fill(number) if self._unread[number] else self._filled()
        return rows[number]


_CACHE: dict[int, list] = {}  # id of a ChainModel: [weak reference, Accelerated]
_INERTIAL = operator.attrgetter('inertial')
_MASS = operator.attrgetter('mass', 'origin')


def mass_state(robot: RobotModel) -> tuple[list, list]:
    """Return what the masses depend on: each link's inertial, and their masses and origins."""
    inertials = list(map(_INERTIAL, robot.links))
    return inertials, list(map(_MASS, filter(None, inertials)))


def accelerated(chain: ChainModel, robot: RobotModel, masses: bool) -> Accelerated | None:
    """
    Return pinocchio's model of ``robot`` compiled as ``chain``, or None.

    None without pinocchio, or with nothing it would move. With ``masses``, its masses are
    the robot's as they are now (read again when an inertial changed since).
    """
    pin = _pinocchio()
    if pin is None or not chain.movable:
        return None
    entry = _CACHE.get(id(chain))
    if entry is not None and entry[0]() is chain:
        if not masses:
            return entry[1]
        state = mass_state(robot)
        if state == entry[1].state:
            return entry[1]
    else:
        state = mass_state(robot)
    if len(set(chain.source[chain.moving].tolist())) < len(chain.movable):
        return None  # a column moves no link of the tree: the numpy path gives its zeros
    found = Accelerated(pin, chain, mass_model(robot, chain))
    found.state = state
    if len(_CACHE) > 32:
        for number in [number for number, item in _CACHE.items() if item[0]() is None]:
            del _CACHE[number]
    _CACHE[id(chain)] = [weakref.ref(chain), found]
    return found
