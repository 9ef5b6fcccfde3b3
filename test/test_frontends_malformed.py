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
Every front end meets malformed input with a documented exit code and no traceback.

Hypothesis mutates valid descriptions, DH tables and options; the CLI commands, ``init`` and
the publisher node must answer with one line and their documented status, never a bug.
"""

from __future__ import annotations

from pathlib import Path
import signal
import subprocess
import tempfile

from click.testing import CliRunner
import pytest

from urdfgenpy_ros.cli import main
from urdfgenpy_ros.examples import pan_tilt_unit
from urdfgenpy_ros.scaffold.command import main as init_main

hypothesis = pytest.importorskip('hypothesis')  # its decorators are needed at import time
st = pytest.importorskip('hypothesis.strategies')
given, HealthCheck, settings = hypothesis.given, hypothesis.HealthCheck, hypothesis.settings

DH_YAML = """convention: standard
degrees: false
rows:
  - {joint: 1, a: 0.0, alpha: 1.5707963, d: 0.089159, theta_offset: 0.0}
  - {joint: 2, a: -0.425, alpha: 0.0, d: 0.0, type: revolute, lower: -3, upper: 3}
  - {joint: 3, a: 0.0, alpha: 0.0, d: 0.1, type: prismatic, lower: 0, upper: 0.2}
"""
DH_CSV = """# convention: modified
joint,a,alpha,d,theta_offset,type,lower,upper,effort,velocity
1,0,0,0.333,0,revolute,-2.9,2.9,87,2.1
2,0,-1.5707963,0,0,revolute,-1.7,1.7,87,2.1
"""
VALID = {'.urdf': pan_tilt_unit().to_urdf(), '.urdf.xacro': pan_tilt_unit().to_xacro(),
         '.yaml': DH_YAML, '.csv': DH_CSV}
NOISE = st.sampled_from(['<', '>', '"', '/>', '</link>', '<joint name="x">', '${', '$(arg a)',
                         '-5', 'nan', 'inf', '1e999', ':', '- ', '{', ',', '\x00', 'é',
                         '<xacro:include filename="missing.xacro"/>', 'rows: 5',
                         '<!DOCTYPE x [<!ENTITY e "e">]>', '&e;', '\t', '\n'])


@st.composite
def malformed(draw: st.DrawFn) -> tuple[str, str]:
    """Return (suffix, text): a valid document with a few random cuts and insertions."""
    suffix = draw(st.sampled_from(sorted(VALID)))
    text = VALID[suffix]
    for _ in range(draw(st.integers(1, 4))):
        at = draw(st.integers(0, len(text)))
        if draw(st.booleans()):
            text = text[:at] + text[at + draw(st.integers(1, 40)):]
        else:
            text = text[:at] + draw(st.one_of(NOISE, st.text(max_size=8))) + text[at:]
    return suffix, text


def _write(folder: Path, suffix: str, text: str) -> Path:
    path = folder / f'robot{suffix}'
    path.write_bytes(text.encode('utf-8', 'surrogatepass'))
    return path


def _assert_no_bug(result, allowed: set[int]) -> None:
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise result.exception  # a bug: pytest shows its traceback
    assert result.exit_code in allowed, result.output
    assert 'Traceback' not in result.output


SLOW = settings(max_examples=60, deadline=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])


@SLOW
@given(document=malformed(), command=st.sampled_from(['tree', 'check', 'convert-urdf',
                                                      'convert-sdf', 'convert-xacro']))
def test_cli_commands_on_malformed_files(document: tuple[str, str], command: str) -> None:
    with tempfile.TemporaryDirectory() as folder:
        path = _write(Path(folder), *document)
        if command.startswith('convert'):
            out = Path(folder) / f'out.{command.split("-")[1]}'
            arguments, allowed = ['convert', str(path), str(out)], {0, 2}
        else:
            arguments, allowed = [command, str(path), '--no-meshes'] if command == 'check' \
                else [command, str(path)], {0, 1, 2} if command == 'check' else {0, 2}
        result = CliRunner().invoke(main, arguments)
        _assert_no_bug(result, allowed)
        if result.exit_code == 2:
            assert result.stderr.count('\n') == 1 or command == 'check', result.stderr


@SLOW
@given(mass=st.one_of(st.text(max_size=6), st.sampled_from(['-1', '0', 'nan', 'inf', '1'])),
       volume=st.sampled_from(['0', '-3', 'x', '15253.6', '']),
       tensor=st.lists(st.sampled_from(['1', '0', '-2', 'nan', 'a', '1e400']), max_size=10))
def test_cli_inertia_with_malformed_numbers(mass: str, volume: str, tensor: list[str]) -> None:
    result = CliRunner().invoke(main, ['inertia', '--meshlab', '--mass', mass, '--volume',
                                       volume, '--tensor', ' '.join(tensor)])
    _assert_no_bug(result, {0, 2})


@pytest.mark.slow  # 60 packages written
@SLOW
@given(name=st.one_of(st.text(max_size=12), st.sampled_from(['ok_description', 'a__b', '9x'])),
       build_type=st.sampled_from(['ament_cmake', 'ament_python', 'catkin', '']),
       email=st.text(max_size=10), document=st.none() | malformed(),
       xacro_args=st.lists(st.sampled_from(['a:=1', 'oops', ':=', 'x:=']), max_size=2))
def test_init_with_malformed_options(name: str, build_type: str, email: str,
                                     document: tuple[str, str] | None,
                                     xacro_args: list[str]) -> None:
    with tempfile.TemporaryDirectory() as folder:
        arguments = [name, '--destination-directory', folder, '--maintainer-email', email]
        if build_type:
            arguments += ['--build-type', build_type]
        if document is not None:
            arguments += ['--from', str(_write(Path(folder), *document))]
        if xacro_args:
            arguments += ['--xacro-args', *xacro_args]
        try:
            code = init_main(arguments)
        except SystemExit as stop:  # argparse refusing an option: its usage line, exit 2
            code = stop.code
        assert code in (0, 2)


NODE_PARAMETERS = st.fixed_dictionaries({}, optional={
    'rate': st.sampled_from(['-5', '0', 'nan', "'fast'", '1e9', '10']),
    'xacro_args': st.sampled_from(["['oops']", "[':=']", '[]', "['a:=1']", '5']),
    'zeros.pan_joint': st.sampled_from(['nan', "'x'", '99', '0.1']),
    'source_list': st.sampled_from(["['joint_states']", "['']", "['/bad topic']", '3']),
    'publish_tf': st.sampled_from(['true', 'false', "'maybe'"]),
    'watch': st.sampled_from(['true', '2']),
})


@pytest.mark.slow
@settings(max_examples=10, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(parameters=NODE_PARAMETERS, document=st.none() | malformed())
def test_node_with_malformed_parameters(graph, parameters: dict[str, str],
                                        document: tuple[str, str] | None) -> None:
    with tempfile.TemporaryDirectory() as folder:
        if document is not None:
            parameters = {**parameters, 'model': str(_write(Path(folder), *document))}
        process = graph.start(*(f'{name}:={value}' for name, value in parameters.items()))
        try:
            output, _ = process.communicate(timeout=4)
        except subprocess.TimeoutExpired:  # it is running: a valid set; Ctrl-C ends it
            process.send_signal(signal.SIGINT)
            output, _ = process.communicate(timeout=10)
            assert process.returncode == 0, output
        assert 'Traceback' not in output, output
        assert process.returncode in (0, 1), output
        if process.returncode == 1:
            errors = [line for line in output.splitlines() if '[ERROR]' in line]
            assert errors, output


def test_a_dh_row_with_a_number_for_a_column_name_is_one_line(tmp_path: Path) -> None:
    table = tmp_path / 'arm.yaml'
    table.write_text('convention: standard\nrows:\n  - {joint:, 1, a: 0}\n')
    result = CliRunner().invoke(main, ['check', str(table)])
    _assert_no_bug(result, {2})
    assert 'unknown column(s) 1' in result.stdout
