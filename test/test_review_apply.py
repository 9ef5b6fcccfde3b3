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


"""``Review.apply(path)``: check --fix's write, from Python: only the repaired line changes."""

from __future__ import annotations

from pathlib import Path

from helpers import assert_check_urdf_accepts, load_yourdfpy

from urdfgenpy_ros import review, ReviewOptions, Robot

SOURCE = """<?xml version="1.0"?>
<!-- kept as written -->
<robot name="r">
  <link name="base"/>
  <link name="arm"/>
  <joint name="shoulder" type="continuous">
    <parent link="base"/>  <child link="arm"/>
    <axis xyz="0 0 2"/>
  </joint>
</robot>
"""


def test_apply_writes_the_repaired_line_only_and_reviews_what_it_wrote(tmp_path: Path
                                                                       ) -> None:
    path = tmp_path / 'r.urdf'
    path.write_text(SOURCE)
    found = review(Robot.from_urdf(path), ReviewOptions(check_meshes=False))
    assert [finding.code for finding in found.repairable] == ['J102']
    assert found.apply(path) is None  # nothing repaired yet: the file is left as it is
    assert [repair.code for repair in found.fix()] == ['J102']
    diff = found.diff(path)
    assert [line[0] for line in diff.splitlines()[2:] if line[0] in '+-'] == ['-', '+']
    written = found.apply(path)
    assert written is not None and not written.repairable
    text = path.read_text()
    assert text.replace('<axis xyz="0 0 1"/>', '<axis xyz="0 0 2"/>') == SOURCE
    assert_check_urdf_accepts(path)  # urdfdom and yourdfpy judge the file written
    assert list(load_yourdfpy(path).joints[0].axis) == [0.0, 0.0, 1.0]
