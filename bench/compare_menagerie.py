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
Side by side with MuJoCo Menagerie: DOF, joint ranges and masses of our MJCF export.

For each robot whose Menagerie README names the URDF it came from, and that
example-robot-data (the bench extra) ships: convert that URDF with ``Robot.to_mjcf`` and
the options a Menagerie user would pick, compile both models with MuJoCo, and print DOF
count, every joint's range and every body's mass after matching names. Menagerie is not
bundled: give the folder of a Menagerie checkout (or of copies of its model XMLs, laid out
as ``<model>/<file>.xml``). Its meshes are not needed: meshes, materials and textures are
stripped before compiling, and bodies keep their written ``<inertial>``.

    python bench/compare_menagerie.py /path/to/mujoco_menagerie
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass, field
from importlib import metadata
import math
from pathlib import Path
import sys
import tempfile
from typing import Any
import warnings

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE.parent)]


# Menagerie's files hold MuJoCo's saved XML: 6 significant digits.
MASS_TOLERANCE = 5e-6
RANGE_TOLERANCE = 5e-5  # rad or m: their ranges are written to 6 digits too


@dataclass(frozen=True)
class Pair:
    """A Menagerie model and the example-robot-data URDF its README names."""

    model: str  # Menagerie folder/file
    urdf: str  # under example-robot-data's robots/
    options: dict[str, Any]
    rename: dict[str, str] = field(default_factory=dict)  # our body/joint name -> theirs
    strip: str = ''  # prefix of our names that Menagerie dropped


PAIRS = (
    Pair('anybotics_anymal_b/anymal_b.xml', 'anymal_b_simple_description/robots/anymal.urdf',
         {'base': 'floating', 'fuse_fixed': True}),
    Pair('franka_emika_panda/panda.xml', 'panda_description/urdf/panda.urdf',
         {'base': 'fixed', 'fuse_fixed': False},
         {'leftfinger': 'left_finger', 'rightfinger': 'right_finger'}, 'panda_'),
    Pair('unitree_a1/a1.xml', 'a1_description/urdf/a1.urdf',
         {'base': 'floating', 'fuse_fixed': True}, {'base': 'trunk'}),
    Pair('unitree_go1/go1.xml', 'go1_description/urdf/go1.urdf',
         {'base': 'floating', 'fuse_fixed': True}, {'base': 'trunk'}),
    Pair('unitree_go2/go2.xml', 'go2_description/urdf/go2.urdf',
         {'base': 'floating', 'fuse_fixed': True}),
    Pair('unitree_z1/z1_gripper.xml', 'z1_description/urdf/z1.urdf',
         {'base': 'fixed', 'fuse_fixed': False}),
)


def robots_folder() -> Path:
    """Return example-robot-data's robots/ folder (the bench extra installs it)."""
    try:
        share = metadata.distribution('example-robot-data').locate_file(
            'cmeel.prefix/share/example-robot-data/robots')
    except metadata.PackageNotFoundError:
        sys.exit("example-robot-data is missing: pip install -e '.[bench]'")
    return Path(str(share))


def stripped(path: Path) -> str:
    """Return Menagerie's XML without meshes, materials, textures or includes."""
    from lxml import etree
    tree = etree.parse(str(path))
    root = tree.getroot()
    for element in list(root.iter()):
        if not isinstance(element.tag, str):
            continue
        if element.tag in ('asset', 'include') or (element.tag == 'geom' and (
                element.get('mesh') or element.get('type') in ('mesh', 'hfield'))):
            element.getparent().remove(element)
            continue
        for attribute in ('material', 'texture', 'hfield'):
            element.attrib.pop(attribute, None)
    # A default geom type of mesh would need a mesh: make defaults plain boxes.
    for geom in root.iterfind('.//default//geom'):
        if geom.get('type') == 'mesh':
            geom.set('type', 'box')
    for light in root.iter('light'):  # its target may be a stripped body; harmless otherwise
        light.attrib.pop('target', None)
    return etree.tostring(root, encoding='unicode')


def compile_menagerie(path: Path) -> Any:
    """Compile Menagerie's model with meshes stripped (each body keeps its inertial)."""
    import mujoco
    return mujoco.MjModel.from_xml_string(stripped(path))


def compile_ours(pair: Pair, folder: Path, out: Path) -> tuple[Any, list[str]]:
    """Convert the URDF with our exporter, compile it, and return it and its findings."""
    import mujoco
    from urdfgenpy_ros.formats import load
    source = folder / pair.urdf
    search = [folder]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        load(source, {}, search).to_mjcf(out / 'robot.xml', search_paths=search, **pair.options)
    return mujoco.MjModel.from_xml_path(str(out / 'robot.xml')), [str(w.message) for w in caught]


def urdf_mass(path: Path) -> float:
    """Return the sum of the URDF's ``<mass>`` values, read with lxml (not through us)."""
    from lxml import etree
    return sum(float(mass.get('value', '0'))
               for mass in etree.parse(str(path)).iterfind('link/inertial/mass'))


def _name(model: Any, kind: Any, index: int) -> str:
    import mujoco
    return mujoco.mj_id2name(model, kind, index) or ''


Joint = tuple[str, tuple[float, float] | None]  # type, range (None: unlimited)


def joints(model: Any, pair: Pair | None = None) -> dict[str, Joint]:
    """Return each non-free joint's (type, range or None when unlimited), by matched name."""
    import mujoco
    kinds = {int(mujoco.mjtJoint.mjJNT_HINGE): 'hinge', int(mujoco.mjtJoint.mjJNT_SLIDE): 'slide',
             int(mujoco.mjtJoint.mjJNT_BALL): 'ball'}
    found = {}
    for index in range(model.njnt):
        kind = int(model.jnt_type[index])
        if kind == int(mujoco.mjtJoint.mjJNT_FREE):
            continue
        limited = bool(model.jnt_limited[index])
        span = (float(model.jnt_range[index][0]), float(model.jnt_range[index][1]))
        name = _name(model, mujoco.mjtObj.mjOBJ_JOINT, index)
        found[matched(name, pair)] = (kinds[kind], span if limited else None)
    return found


def bodies(model: Any, pair: Pair | None = None) -> dict[str, float]:
    """Return each body's mass by matched name (the world left out)."""
    import mujoco
    return {matched(_name(model, mujoco.mjtObj.mjOBJ_BODY, index), pair):
            float(model.body_mass[index]) for index in range(1, model.nbody)}


def matched(name: str, pair: Pair | None) -> str:
    """Return our name as Menagerie spells it (``pair`` None: Menagerie's own name)."""
    if pair is None:
        return name
    if pair.strip and name.startswith(pair.strip):
        name = name[len(pair.strip):]
    return pair.rename.get(name, name)


def free(model: Any) -> bool:
    import mujoco
    return any(int(kind) == int(mujoco.mjtJoint.mjJNT_FREE) for kind in model.jnt_type)


def _span(value: Joint | None) -> str:
    if value is None:
        return 'absent'
    kind, span = value
    return f'{kind} unlimited' if span is None else f'{kind} [{span[0]:.6g}, {span[1]:.6g}]'


def _same_span(a: tuple[float, float] | None, b: tuple[float, float] | None) -> bool:
    if a is None or b is None:
        return a is b
    return all(math.isclose(x, y, abs_tol=RANGE_TOLERANCE) for x, y in zip(a, b))


def compare(pair: Pair, menagerie: Path, folder: Path) -> list[str]:
    """Return the report lines of one robot."""
    theirs = compile_menagerie(menagerie / pair.model)
    with tempfile.TemporaryDirectory() as scratch:
        ours, findings = compile_ours(pair, folder, Path(scratch))
    options = ', '.join(f'{key}={value!r}' for key, value in pair.options.items())
    lines = [f'## {pair.model} vs {pair.urdf} ({options})',
             f'DOF (nv): Menagerie {theirs.nv}, ours {ours.nv}; free joint: Menagerie '
             f'{free(theirs)}, ours {free(ours)}; bodies: Menagerie {theirs.nbody - 1}, '
             f'ours {ours.nbody - 1}',
             f'total mass (kg): Menagerie {sum(theirs.body_mass):.6g}, ours '
             f'{sum(ours.body_mass):.6g} (the sum of the URDF <mass> values: '
             f'{urdf_mass(folder / pair.urdf):.6g})']
    their_joints, our_joints = joints(theirs), joints(ours, pair)
    same = 0
    for name in sorted(set(their_joints) | set(our_joints)):
        a, b = their_joints.get(name), our_joints.get(name)
        if a is not None and b is not None and a[0] == b[0] and _same_span(a[1], b[1]):
            same += 1
            continue
        lines.append(f'  joint {name}: Menagerie {_span(a)}, ours {_span(b)}')
    lines.append(f'  joints with the same type and range: {same} of {len(their_joints)}')
    their_bodies, our_bodies = bodies(theirs), bodies(ours, pair)
    same = 0
    for name in sorted(set(their_bodies) | set(our_bodies)):
        a_mass, b_mass = their_bodies.get(name), our_bodies.get(name)
        if a_mass is not None and b_mass is not None and math.isclose(
                a_mass, b_mass, rel_tol=MASS_TOLERANCE, abs_tol=1e-9):
            same += 1
            continue
        text = [('absent' if mass is None else f'{mass:.6g} kg') for mass in (a_mass, b_mass)]
        lines.append(f'  body {name}: Menagerie {text[0]}, ours {text[1]}')
    lines.append(f'  bodies with the same mass: {same} of {len(their_bodies)}')
    lines.append(f'  our conversion report: {len(findings)} finding(s)')
    return lines


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('menagerie', type=Path,
                        help='a mujoco_menagerie checkout (or copies of its model XMLs)')
    arguments = parser.parse_args(argv)
    folder = robots_folder()
    for pair in PAIRS:
        if not (arguments.menagerie / pair.model).is_file():
            print(f'## {pair.model}: not in {arguments.menagerie}, skipped')
            continue
        print('\n'.join(compare(pair, arguments.menagerie, folder)))
    return 0


if __name__ == '__main__':
    sys.exit(main())
