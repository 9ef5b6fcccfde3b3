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

"""Untrusted files reach neither network nor file system, and cannot blow up memory."""

from __future__ import annotations

from pathlib import Path
import socket
import tracemalloc

from helpers import check_urdf_verdict
import pytest

from urdfgenpy_ros import ParseError, Robot

LAUGHS = '<?xml version="1.0"?>\n<!DOCTYPE lolz [\n<!ENTITY lol "lol">\n' + ''.join(
    f'<!ENTITY lol{n} "{f"&lol{n - 1};" * 10 if n > 1 else "&lol;" * 10}">\n'
    for n in range(1, 10)) + ']>\n<robot name="&lol9;"><link name="a"/></robot>\n'


def test_entity_expansion_is_refused_before_it_costs_memory() -> None:
    Robot.from_urdf_string('<robot name="warm"><link name="a"/></robot>')  # imports done
    tracemalloc.start()
    try:
        with pytest.raises(ParseError, match=r'^bomb.urdf:2:1: error P008 <!DOCTYPE>'):
            Robot.from_urdf_string(LAUGHS, 'bomb.urdf')
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert peak < 1_000_000  # 10**9 'lol's would need gigabytes


def test_external_entities_cannot_read_files(tmp_path: Path) -> None:
    secret = tmp_path / 'secret.txt'
    secret.write_text('TOP-SECRET')
    xml = (f'<?xml version="1.0"?>\n<!DOCTYPE r [<!ENTITY x SYSTEM "{secret.as_uri()}">]>\n'
           '<robot name="r"><link name="&x;"/></robot>')
    with pytest.raises(ParseError, match='P008') as raised:
        Robot.from_urdf_string(xml)
    assert 'TOP-SECRET' not in str(raised.value)


def test_no_network_access(monkeypatch: pytest.MonkeyPatch) -> None:
    def refuse(*args, **kwargs):
        raise AssertionError('the reader opened a socket')
    monkeypatch.setattr(socket, 'create_connection', refuse)
    monkeypatch.setattr(socket.socket, 'connect', refuse)
    xml = ('<?xml version="1.0"?>\n<!DOCTYPE r SYSTEM "http://127.0.0.1:9/evil.dtd">\n'
           '<robot name="r"/>')
    with pytest.raises(ParseError, match='P008'):
        Robot.from_urdf_string(xml)
    # XInclude and schema locations are not followed either: a plain element stays inert.
    robot = Robot.from_urdf_string(
        '<robot name="r" xmlns:xi="http://www.w3.org/2001/XInclude">'
        '<xi:include href="http://127.0.0.1:9/x.xml"/><link name="a"/></robot>')
    assert [link.name for link in robot.links] == ['a']
    assert 'xi:include' in robot.to_urdf()


def test_a_doctype_that_declares_nothing_is_read_as_urdfdom_reads_it(tmp_path: Path) -> None:
    path = tmp_path / 'bare.urdf'
    path.write_text('<?xml version="1.0"?>\n<!DOCTYPE robot>\n<robot name="r">\n'
                    '  <link name="a"/>\n</robot>\n')
    assert check_urdf_verdict(path, timeout=10)  # urdfdom reads it
    robot = Robot.from_urdf(path)
    assert robot.to_urdf() == path.read_text()  # and it is kept
    for declared in ('<!DOCTYPE robot [ ]>', '<!DOCTYPE robot SYSTEM "r.dtd">'):
        with pytest.raises(ParseError, match='P008'):
            Robot.from_urdf_string(path.read_text().replace('<!DOCTYPE robot>', declared))
