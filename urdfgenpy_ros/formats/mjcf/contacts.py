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
Self-collision exclusions, as Gazebo has none by default and Menagerie writes by hand.

MuJoCo itself finds them: it compiles the model, and each body whose parent is welded to
the world (MuJoCo's parent filter skips those), and each pair of bodies whose collision
geoms touch at the ``home`` keyframe, gets a ``<contact><exclude>``.
"""

from __future__ import annotations

from typing import Any

from lxml import etree


def write_excludes(document: Any, assets: dict[str, bytes], meshdir: str | None
                   ) -> str:
    """Add ``<exclude>`` pairs to ``document``; return the note saying what was done."""
    try:
        import mujoco
    except ImportError:
        return ('contacts: no self-collision excluded (MuJoCo finds the pairs: '
                "pip install 'urdfgenpy_ros[engines]')")
    files = {f'{meshdir}/{name}' if meshdir else name: data for name, data in assets.items()}
    text, used = _without_visuals(document)
    try:
        try:  # MuJoCo copies every file it is given: only those the contact model reads
            model = mujoco.MjModel.from_xml_string(text, {
                f'{meshdir}/{name}' if meshdir else name: data
                for name, data in assets.items() if name in used})
        except ValueError:  # an overlay names a visual geom: the whole model, then
            model = mujoco.MjModel.from_xml_string(
                etree.tostring(document, encoding='unicode'), files)
    except ValueError as error:
        return f'contacts: no self-collision excluded: MuJoCo refuses the model ({error})'
    pairs = _pairs(mujoco, model)
    contact = document.find('contact')
    taken = set()
    if contact is not None:
        taken = {frozenset((exclude.get('body1'), exclude.get('body2')))
                 for exclude in contact.iter('exclude')}
    new = [pair for pair in pairs if frozenset(pair) not in taken]
    if new:
        if contact is None:
            contact = etree.Element('contact')
            worldbody = document.find('worldbody')
            worldbody.addnext(contact)
        contact.append(etree.Comment(' self-collisions excluded by urdfgenpy_ros: a body '
                                     "and its world-welded parent; bodies touching at 'home' "))
        for first, second in new:
            etree.SubElement(contact, 'exclude', body1=first, body2=second)
    return (f'contacts: {len(new)} body pair(s) excluded from self-collision (a body and '
            "its world-welded parent, and bodies touching at the 'home' keyframe, as "
            'MuJoCo finds them; Gazebo has no self-collision by default)')


def _without_visuals(document: Any) -> tuple[str, set[str]]:
    """
    Return the model's text without visual geoms and the meshes only they use (faster).

    With it, the names of the files its meshes read.
    """
    import copy
    model = copy.deepcopy(document)
    for geom in list(model.iter('geom')):
        if geom.get('class') == 'visual':
            geom.getparent().remove(geom)
    used = {geom.get('mesh') for geom in model.iter('geom')}
    asset = model.find('asset')
    for mesh in list(asset.iter('mesh')) if asset is not None else ():
        if mesh.get('name') not in used:
            asset.remove(mesh)
    files = {mesh.get('file') for mesh in model.iter('mesh') if mesh.get('file')}
    return etree.tostring(model, encoding='unicode'), files


def _pairs(mujoco: Any, model: Any) -> list[tuple[str, str]]:
    """Return the body pairs to exclude, in body order, each once."""
    found: dict[frozenset[int], tuple[int, int]] = {}
    colliding = {int(model.geom_bodyid[geom]) for geom in range(model.ngeom)
                 if model.geom_contype[geom] or model.geom_conaffinity[geom]}
    for body in range(1, model.nbody):
        parent = int(model.body_parentid[body])
        if parent and int(model.body_weldid[parent]) == 0 and body in colliding \
                and parent in colliding and int(model.body_weldid[body]) != 0:
            found[frozenset((parent, body))] = (parent, body)
    data = mujoco.MjData(model)
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, 'home')
    if key >= 0:
        mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_forward(model, data)
    for contact in data.contact[:data.ncon]:
        bodies = sorted((int(model.geom_bodyid[contact.geom1]),
                         int(model.geom_bodyid[contact.geom2])))
        if bodies[0] != bodies[1]:
            found.setdefault(frozenset(bodies), (bodies[0], bodies[1]))
    return [(model.body(first).name, model.body(second).name)
            for first, second in sorted(found.values())]
