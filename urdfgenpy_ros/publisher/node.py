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
``ros2 run urdfgenpy_ros publisher``: load or build a robot, validate it, publish it.

Publishes ``robot_description`` (std_msgs/String, reliable, transient local, depth 1:
late subscribers get it) and ``joint_states`` (sensor_msgs/JointState) at ``rate`` Hz,
with joint_state_publisher's parameters; serves ``~/reload`` (std_srvs/Trigger) and,
with ``watch``, reloads when the model or a file it includes changes.
"""

from __future__ import annotations

from dataclasses import replace
import math
import os
import sys
import time
from typing import Any, cast, TYPE_CHECKING

from rcl_interfaces.msg import ParameterDescriptor, ParameterType, SetParametersResult
import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.impl.implementation_singleton import rclpy_implementation
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

from urdfgenpy_ros.formats.open import files_read, open_description
from urdfgenpy_ros.model.errors import Severity, UrdfgenpyError
from urdfgenpy_ros.publisher import NODE_WORDS
from urdfgenpy_ros.publisher.joint_states import JointStateOptions, JointStates
from urdfgenpy_ros.report import boundary, KNOWN_ERRORS
from urdfgenpy_ros.validation.checklist import review, ReviewOptions
from urdfgenpy_ros.validation.consumers import is_physics_only, physics_warning
from urdfgenpy_ros.validation.suppressions import parse_codes

if TYPE_CHECKING:  # imported when needed: sensor_msgs brings numpy, not needed to start
    from sensor_msgs.msg import JointState
    from std_srvs.srv import Trigger

    from urdfgenpy_ros.robot import Robot

_STRINGS = ParameterType.PARAMETER_STRING_ARRAY
_PARAMETERS: dict[str, tuple[Any, int | None, str]] = {
    'model': ('', ParameterType.PARAMETER_STRING,
              'a .urdf, .xacro/.urdf.xacro, DH table (.yaml, .csv), assembly file '
              '(*.assembly.yaml) or package.module:function returning a Robot or URDF text; '
              'empty: the example robot'),
    'xacro_args': ([], _STRINGS, 'xacro arguments as name:=value'),
    'package_paths': ([], _STRINGS, 'folders holding ROS packages, for $(find) and meshes'),
    'ignore': ([], _STRINGS, "finding codes that do not stop publishing, e.g. ['I203'] (the "
               "file's own 'urdfgenpy: ignore' comments count too)"),
    'target': ('jazzy', ParameterType.PARAMETER_STRING,
               'ROS distribution whose robot_state_publisher reads the description (jazzy: '
               'URDF 1.0 only; rolling: 1.0 to 1.2)'),
    'rate': (10, None, 'joint_states per second (integer or double)'),
    'source_list': ([], _STRINGS, 'JointState topics whose values are merged (unknown '
                    'names, mismatched arrays and NaN are ignored with a warning)'),
    'publish_default_positions': (True, ParameterType.PARAMETER_BOOL,
                                  'publish positions no source gives (as joint_state_publisher)'),
    'publish_default_velocities': (False, ParameterType.PARAMETER_BOOL,
                                   'publish zero velocities (as joint_state_publisher)'),
    'publish_default_efforts': (False, ParameterType.PARAMETER_BOOL,
                                'publish zero efforts (as joint_state_publisher)'),
    'use_mimic_tags': (True, ParameterType.PARAMETER_BOOL,
                       'mimic joints follow their leaders (as joint_state_publisher)'),
    'use_smallest_joint_limits': (True, ParameterType.PARAMETER_BOOL,
                                  'clamp to the safety controller limits when tighter (as '
                                  'joint_state_publisher)'),
    'delta': (0.0, ParameterType.PARAMETER_DOUBLE, 'move every joint by this each tick'),
    'publish_description': (True, ParameterType.PARAMETER_BOOL,
                            'false: leave robot_description to robot_state_publisher'),
    'watch': (False, ParameterType.PARAMETER_BOOL, 'reload when the model files change'),
    'strict': (False, ParameterType.PARAMETER_BOOL,
               'refuse on every error, physics-only ones (mass, inertia) too'),
    'publish_tf': (False, ParameterType.PARAMETER_BOOL,
                   '/tf for movable joints, /tf_static for fixed ones (needs tf2_msgs)'),
    'frame_prefix': ('', ParameterType.PARAMETER_STRING, 'prefix of every TF frame id'),
    'gui': (False, ParameterType.PARAMETER_BOOL, 'joint sliders on a local web page'),
    'gui_port': (8080, ParameterType.PARAMETER_INTEGER, 'port of the gui page'),
}


_EXPECTED = {
    ParameterType.PARAMETER_STRING: ('a string', lambda value: isinstance(value, str)),
    ParameterType.PARAMETER_BOOL: ('true or false', lambda value: isinstance(value, bool)),
    ParameterType.PARAMETER_INTEGER: ('an integer', lambda value: isinstance(value, int)
                                      and not isinstance(value, bool)),
    ParameterType.PARAMETER_DOUBLE: ('a number', lambda value: isinstance(value, (int, float))
                                     and not isinstance(value, bool)),
    _STRINGS: ("a list of strings, e.g. \"['a', 'b']\"", lambda value: isinstance(
        value, (list, tuple)) and all(isinstance(item, str) for item in value)),
}


def _check_type(name: str, kind: int | None, value: Any) -> None:
    """Refuse a parameter given with another type than declared (overrides keep theirs)."""
    if kind not in _EXPECTED:  # None: dynamically typed ('rate': int or double)
        return
    expected, accepts = _EXPECTED[kind]
    if not accepts(value):
        raise UrdfgenpyError(f'parameter {name!r}: {value!r} is not {expected}')


class PublisherNode(Node):
    """Publish a validated robot description and its joint states."""

    def __init__(self, **kwargs: Any) -> None:
        try:
            super().__init__('urdfgenpy_publisher',
                             automatically_declare_parameters_from_overrides=True, **kwargs)
        except ValueError as error:  # rclpy refusing an override it cannot type, e.g. []
            raise UrdfgenpyError(
                f'bad parameter: {error} (an empty list has no type in ROS 2: leave the '
                'parameter out to get its default)') from None
        self.values = self._declare_parameters()
        try:
            self.ignored = parse_codes(' '.join(self.values['ignore']))
        except ValueError as error:
            raise UrdfgenpyError(f"parameter 'ignore': {error}") from None
        # what the node's review checks and silences (its gui's viewer shows the same)
        self.review_options = ReviewOptions(search_paths=tuple(self.values['package_paths']),
                                            target=self.values['target'], ignore=self.ignored)
        rate = self.values['rate']
        if isinstance(rate, bool) or not isinstance(rate, (int, float)) or not rate > 0:
            raise UrdfgenpyError(f"parameter 'rate': {rate!r} is not a positive number of Hz")
        self.robot, self.watched = self._load()
        self.description = self.robot.to_urdf()
        self.states = self._joint_states(self.robot)
        self._publish_description()
        self._start_joint_states(rate)
        self._warned: set[str] = set()
        self._last_warning: dict[str, float] = {}
        self.gui = None
        if self.values['gui']:  # imported only here: the viewer's dependencies are heavy
            from urdfgenpy_ros.publisher.gui import NodeGui
            self.gui = NodeGui(self, self.values['gui_port'])
        self.get_logger().info(
            f'publishing {self.robot.name!r}: {len(self.robot.links)} links, '
            f'{len(self.states.names)} joint states at {rate} Hz'
            + ('' if self.description_publisher else ' (robot_description left to '
               'robot_state_publisher)'))

    def _declare_parameters(self) -> dict[str, Any]:
        """Declare every parameter not overridden; return the values, each of its type."""
        for name, (default, kind, description) in _PARAMETERS.items():
            descriptor = ParameterDescriptor(description=description)
            if kind is None:
                descriptor.dynamic_typing = True
            else:
                descriptor.type = kind
            if not self.has_parameter(name):
                self.declare_parameter(name, default, descriptor)
        values = {name: self.get_parameter(name).value for name in _PARAMETERS}
        for name, (_, kind, _) in _PARAMETERS.items():
            _check_type(name, kind, values[name])
        return values

    def _publish_description(self) -> None:
        """Declare ``robot_description`` (read-only) and publish it, latched, if asked."""
        self._updating_description = False
        self.declare_parameter('robot_description', self.description, ParameterDescriptor(
            description='the published URDF (read-only: change the model and call ~/reload)'))
        self.add_on_set_parameters_callback(self._refuse_description_edits)
        latched = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE,
                             durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.description_publisher = None
        if self.values['publish_description']:
            self.description_publisher = self.create_publisher(String, 'robot_description',
                                                               latched)
            self.description_publisher.publish(String(data=self.description))

    def _start_joint_states(self, rate: float) -> None:
        """Publish joint states at ``rate`` Hz, merge the sources, serve ~/reload, watch."""
        # Only now what the description does not need (sensor_msgs imports numpy).
        from sensor_msgs.msg import JointState
        from std_srvs.srv import Trigger
        self.joint_publisher = self.create_publisher(JointState, 'joint_states', 10)
        self.message = JointState()
        self._message_states: JointStates | None = None
        self._message_version = -1
        self._delta = float(self.values['delta'])
        for topic in self.values['source_list']:
            try:
                self.create_subscription(JointState, topic, self._merge, 10)
            except (rclpy.exceptions.InvalidTopicNameException, ValueError) as error:
                raise UrdfgenpyError(f"parameter 'source_list': {topic!r} is not a topic "
                                     f'name ({error})') from None
        self.create_service(Trigger, '~/reload', self._reload_service)
        self.tf = _TfPublisher(self) if self.values['publish_tf'] else None
        self.create_timer(1.0 / float(rate), self._publish_joint_states)
        self._stamps = self._modification_times()
        if self.values['watch']:
            self.create_timer(0.5, self._watch)

    # ---- model ------------------------------------------------------------------------

    def _load(self) -> tuple[Robot, list[str]]:
        robot, watched = _open(self.values['model'], self.values['xacro_args'],
                               self.values['package_paths'])
        # the file's own suppression comments count, as in `urdfgenpy check`, and 'ignore'
        found = review(robot, self.review_options)
        findings, silenced = found.findings, found.suppressed
        strict = self.values['strict']
        errors = [finding for finding in findings if finding.severity is Severity.ERROR
                  and (strict or not is_physics_only(finding))]
        for finding in findings:
            if finding in errors:
                self.get_logger().error(str(finding))
            elif finding.severity is Severity.ERROR:
                self.get_logger().warning(physics_warning(finding))
            else:
                self.get_logger().warning(str(finding))
        if silenced:
            codes = ', '.join(sorted({item.finding.code for item in silenced}))
            self.get_logger().info(f'{len(silenced)} finding(s) ignored ({codes}): parameter '
                                   "'ignore' or suppression comments in the file")
        if errors:
            codes = "', '".join(sorted({finding.code for finding in errors}))
            raise UrdfgenpyError(f'{len(errors)} validation error(s) in the model: fix them '
                                 '(listed above) before publishing, or publish anyway with '
                                 f"-p \"ignore:=['{codes}']\"")
        return robot, watched

    def _joint_states(self, robot: Robot) -> JointStates:
        # rclpy annotates the values as plain values; they are Parameter objects.
        parameters: dict[str, Any] = dict(self.get_parameters_by_prefix('zeros'))
        zeros = {}
        for name, parameter in parameters.items():
            value = parameter.value
            if isinstance(value, bool) or not isinstance(value, (int, float)) \
                    or not math.isfinite(value):
                raise UrdfgenpyError(f"parameter 'zeros.{name}': {value!r} is not a finite "
                                     'number (the joint position, in rad or m)')
            zeros[name] = float(value)
        options = JointStateOptions(
            zeros=zeros, use_mimic_tags=self.values['use_mimic_tags'],
            use_smallest_joint_limits=self.values['use_smallest_joint_limits'],
            publish_default_positions=self.values['publish_default_positions'],
            publish_default_velocities=self.values['publish_default_velocities'],
            publish_default_efforts=self.values['publish_default_efforts'])
        return JointStates(robot, options)

    def reload(self) -> tuple[bool, str]:
        """Load the model again; publish it if valid and changed, else keep the last one."""
        try:
            robot, watched = self._load()
            states = self._joint_states(robot)
        except KNOWN_ERRORS as error:
            said = NODE_WORDS.said(error)
            self.get_logger().error(f'reload failed, still publishing the last good model: '
                                    f'{said}')
            return False, said
        previous = dict(self.states.free)
        for name, joint in states.free.items():
            if name in previous:
                joint.position = states.clamp(name, previous[name].position)
        self.robot, self.watched, self.states = robot, watched, states
        self._stamps = self._modification_times()
        if self.tf is not None:
            self.tf.configure(robot)
        if self.gui is not None:
            self.gui.show(robot)
        description = robot.to_urdf()
        if description == self.description:
            return True, 'model unchanged'
        self.description = description
        self._updating_description = True
        try:
            self.set_parameters([Parameter('robot_description', value=description)])
        finally:
            self._updating_description = False
        if self.description_publisher is not None:
            self.description_publisher.publish(String(data=description))
        self.get_logger().info(f'published the reloaded model {robot.name!r}')
        return True, 'published the reloaded model'

    def _refuse_description_edits(self, parameters: list[Parameter]) -> SetParametersResult:
        if any(p.name == 'robot_description' for p in parameters) and \
                not self._updating_description:
            return SetParametersResult(successful=False, reason='robot_description is '
                                       'read-only: change the model and call ~/reload')
        return SetParametersResult(successful=True)

    def _reload_service(self, request: Trigger.Request,
                        response: Trigger.Response) -> Trigger.Response:
        response.success, response.message = self.reload()
        return response

    def _modification_times(self) -> dict[str, float]:
        stamps: dict[str, float] = {}
        for file in self.watched:
            try:
                stamps[file] = os.stat(file).st_mtime_ns
            except OSError:
                stamps[file] = -1
        return stamps

    def _watch(self) -> None:
        if self._modification_times() != self._stamps:
            self._stamps = self._modification_times()
            self.get_logger().info('model files changed: reloading')
            self.reload()

    # ---- joint states -----------------------------------------------------------------

    def _merge(self, message: JointState) -> None:
        try:
            unknown = self.states.merge(message.name, message.position, message.velocity,
                                        message.effort)
        except ValueError as error:  # at most one warning per kind of fault every 5 s
            kind = 'nan' if 'NaN' in str(error) else 'length'
            now = time.monotonic()
            if now - self._last_warning.get(kind, -math.inf) >= 5.0:
                self._last_warning[kind] = now
                self.get_logger().warning(f'ignored a JointState: {error}')
            return
        fresh = [name for name in unknown if name not in self._warned]
        if fresh:
            self._warned.update(fresh)
            self.get_logger().warning('ignored unknown joint(s): ' + ', '.join(fresh))

    def _publish_joint_states(self) -> None:
        states = self.states
        if self._delta > 0.0:
            states.step(self._delta)
        message = self.message
        if states is not self._message_states or states.version != self._message_version:
            self._message_states, self._message_version = states, states.version
            message.name, message.position, message.velocity, message.effort = \
                states.message_arrays()  # refilled only when a value changed
        if message.name:
            message.header.stamp = self.get_clock().now().to_msg()
            self.joint_publisher.publish(message)
            if self.tf is not None:
                self.tf.publish(message)


class _TfPublisher:
    """/tf and /tf_static from our own joint transforms, as robot_state_publisher does."""

    def __init__(self, node: PublisherNode) -> None:
        try:
            from geometry_msgs.msg import TransformStamped
            from tf2_msgs.msg import TFMessage
        except ImportError:
            raise UrdfgenpyError("parameter 'publish_tf' needs the tf2_msgs package: source "
                                 'a ROS 2 install (or run robot_state_publisher instead)'
                                 ) from None
        self.node, self.message_type, self.transform_type = node, TFMessage, TransformStamped
        self.prefix = node.values['frame_prefix']
        self.dynamic = node.create_publisher(TFMessage, '/tf', 100)
        self.static = node.create_publisher(TFMessage, '/tf_static', QoSProfile(
            depth=1, reliability=ReliabilityPolicy.RELIABLE,
            durability=DurabilityPolicy.TRANSIENT_LOCAL))
        self.configure(node.robot)

    def configure(self, robot: Robot) -> None:
        """Take a (new) robot: publish its fixed joints on /tf_static."""
        from urdfgenpy_ros.dynamics.kinematics import JointTransforms
        self.transforms = JointTransforms(robot)
        stamp = self.node.get_clock().now().to_msg()
        self.static.publish(self.message_type(transforms=[
            self._stamped(entry, stamp) for entry in self.transforms.static]))

    def _stamped(self, entry: tuple, stamp: Any) -> Any:
        parent, child, xyz, rotation = entry
        stamped = self.transform_type()
        stamped.header.stamp = stamp
        stamped.header.frame_id = self.prefix + parent
        stamped.child_frame_id = self.prefix + child
        translation, turn = stamped.transform.translation, stamped.transform.rotation
        translation.x, translation.y, translation.z = xyz
        turn.x, turn.y, turn.z, turn.w = rotation
        return stamped

    def publish(self, message: JointState) -> None:
        """Publish the moving joints' transforms for the joint state ``message``."""
        positions = dict(zip(message.name, message.position))
        self.dynamic.publish(self.message_type(transforms=[
            self._stamped(entry, message.header.stamp)
            for entry in self.transforms.moving(positions)]))


EXIT_NODE_ERROR = 1
"""The node's exit status for a user's mistake (a bad file, model or parameter)."""


def _open(model: str, xacro_args: list[str], package_paths: list[str]
          ) -> tuple[Robot, list[str]]:
    """Return the robot the ``model`` parameter names ('': the example), files to watch."""
    if not model:
        from urdfgenpy_ros.examples import pan_tilt_unit
        return pan_tilt_unit(), []
    robot = cast('Robot', open_description(model, xacro_args, package_paths))
    return robot, files_read(model, robot)


def _start() -> PublisherNode:
    try:
        return PublisherNode()
    except rclpy.exceptions.InvalidParameterTypeException as error:
        raise UrdfgenpyError(f"bad parameter: {error} (docs/node.md lists each parameter's "
                             'type)') from None


def main(args: list[str] | None = None) -> int:
    """Run the node until Ctrl-C; return 1 (one log line) when it cannot start."""
    rclpy.init(args=args)
    node = None
    said = replace(NODE_WORDS, say=rclpy.logging.get_logger('urdfgenpy_publisher').error)
    try:
        with boundary(said):
            node = _start()
            rclpy.spin(node)
    except SystemExit as stop:  # the boundary said the user's mistake
        return stop.code if isinstance(stop.code, int) else EXIT_NODE_ERROR
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    except rclpy_implementation.RCLError:
        if rclpy.ok():
            raise
        # Ctrl-C shut the context down while a timer was publishing: a normal stop
    finally:
        if node is not None:
            if node.gui is not None:
                node.gui.close()
            node.destroy_node()
        try:
            rclpy.try_shutdown()
        except rclpy_implementation.RCLError:
            if rclpy.ok():
                raise  # Ctrl-C's handler shut the context down between check and shutdown
    return 0


def console_main() -> None:
    """Entry point of the ``publisher`` executable: exit with main()'s status."""
    sys.exit(main())


if __name__ == '__main__':
    console_main()
