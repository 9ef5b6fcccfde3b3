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
Judges of written meshes: the source read as RViz reads it, against what MuJoCo compiled.

RViz's reading, independently of the package: trimesh's vertices (node transforms applied,
the up axis ignored, as rviz_rendering's assimp loader with IGNORE_UP_DIRECTION) times the
file's ``<asset><unit meter>`` read here with lxml. Links are placed by yourdfpy's forward
kinematics at zero, MuJoCo's bodies by ``mj_kinematics`` at ``qpos0``.
"""

from __future__ import annotations

from pathlib import Path

import numpy

Y_UP_DAE = """<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="millimeter" meter="0.001"/><up_axis>Y_UP</up_axis></asset>
  <library_effects>
    <effect id="red-fx"><profile_COMMON><technique sid="t"><phong>
      <diffuse><color>0.8 0.1 0.2 1</color></diffuse></phong></technique></profile_COMMON>
    </effect>
    <effect id="blue-fx"><profile_COMMON><technique sid="t"><phong>
      <diffuse><color>0.1 0.3 0.9 0.5</color></diffuse></phong></technique></profile_COMMON>
    </effect>
  </library_effects>
  <library_materials>
    <material id="red" name="red"><instance_effect url="#red-fx"/></material>
    <material id="blue" name="blue"><instance_effect url="#blue-fx"/></material>
  </library_materials>
  <library_geometries>{geometries}</library_geometries>
  <library_visual_scenes><visual_scene id="scene">
    <node id="n"><matrix>1 0 0 10 0 1 0 20 0 0 1 30 0 0 0 1</matrix>
      <instance_geometry url="#g"><bind_material><technique_common>
        <instance_material symbol="red" target="#red"/>
        <instance_material symbol="blue" target="#blue"/>
      </technique_common></bind_material></instance_geometry></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
"""
"""A DAE in millimetres, Y up, of two boxes (red, and half-transparent blue) off its origin."""

RED = (0.8, 0.1, 0.2, 1.0)
BLUE = (0.1, 0.3, 0.9, 0.5)


def _box(low: tuple[float, float, float], high: tuple[float, float, float], offset: int
         ) -> tuple[list[list[float]], list[list[int]]]:
    corners = [[(low, high)[i >> 2 & 1][0], (low, high)[i >> 1 & 1][1],
                (low, high)[i & 1][2]] for i in range(8)]
    faces = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
             [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]
    return corners, [[offset + corner for corner in face] for face in faces]


BOXES = {'red': ((0.0, 0.0, 0.0), (100.0, 50.0, 20.0)),
         'blue': ((0.0, 60.0, 0.0), (40.0, 120.0, 30.0))}


def write_y_up_dae(path: Path) -> None:
    """Write :data:`Y_UP_DAE`'s file at ``path``."""
    positions: list[float] = []
    triangles = []
    for number, (name, (low, high)) in enumerate(BOXES.items()):
        corners, faces = _box(low, high, 8 * number)
        positions += [value for corner in corners for value in corner]
        indices = ' '.join(str(corner) for face in faces for corner in face)
        triangles.append(f'<triangles material="{name}" count="12"><input semantic="VERTEX" '
                         f'source="#v" offset="0"/><p>{indices}</p></triangles>')
    geometry = (f'<geometry id="g"><mesh><source id="p"><float_array id="pa" count='
                f'"{len(positions)}">{" ".join(map(str, positions))}</float_array>'
                '<technique_common><accessor source="#pa" count="16" stride="3">'
                '<param name="X" type="float"/><param name="Y" type="float"/>'
                '<param name="Z" type="float"/></accessor></technique_common></source>'
                '<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>'
                f'{"".join(triangles)}</mesh></geometry>')
    path.write_text(Y_UP_DAE.replace('{geometries}', geometry))


def rviz_vertices(path: Path) -> numpy.ndarray:
    """Return a mesh file's used vertices as RViz places them (see the module's text)."""
    import trimesh
    from lxml import etree
    mesh = trimesh.load(str(path), force='mesh', process=False)
    unit = 1.0
    if path.suffix.lower() == '.dae':
        found = etree.parse(str(path)).getroot().find('{*}asset/{*}unit')
        if found is not None and found.get('meter'):
            unit = float(found.get('meter'))
    return numpy.asarray(mesh.vertices)[numpy.unique(mesh.faces)] * unit


def source_boxes(urdf: Path, search_paths: list[Path]) -> dict[str, numpy.ndarray]:
    """Return each link's visual mesh vertices' bounds, sources read as RViz reads them."""
    import yourdfpy
    from urdfgenpy_ros.resources import PackageResolver
    model = yourdfpy.URDF.load(str(urdf), load_meshes=False, build_scene_graph=True,
                               build_collision_scene_graph=False)
    resolver = PackageResolver(search_paths)
    found: dict[str, list[numpy.ndarray]] = {}
    for name, link in model.link_map.items():
        pose = model.get_transform(name, model.base_link)
        for visual in link.visuals:
            mesh = visual.geometry.mesh
            if mesh is None:
                continue
            try:
                path = resolver.resolve(mesh.filename, urdf.parent)
            except Exception:  # noqa: B902 - not found: the export leaves it out too
                continue
            points = rviz_vertices(path) * (mesh.scale if mesh.scale is not None else 1.0)
            origin = visual.origin if visual.origin is not None else numpy.eye(4)
            placed = pose @ origin
            found.setdefault(name, []).append(points @ placed[:3, :3].T + placed[:3, 3])
    return {name: _bounds(numpy.concatenate(points)) for name, points in found.items()}


def written_boxes(model) -> dict[str, numpy.ndarray]:
    """Return each body's visual mesh geoms' vertex bounds, as MuJoCo compiled them."""
    import mujoco
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    found: dict[str, list[numpy.ndarray]] = {}
    for geom in range(model.ngeom):
        if model.geom_type[geom] != mujoco.mjtGeom.mjGEOM_MESH or model.geom_group[geom] != 2:
            continue
        mesh = model.geom_dataid[geom]
        start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
        local = model.mesh_vert[start:start + count].astype(float)
        placed = local @ data.geom_xmat[geom].reshape(3, 3).T + data.geom_xpos[geom]
        found.setdefault(model.body(model.geom_bodyid[geom]).name, []).append(placed)
    return {name: _bounds(numpy.concatenate(points)) for name, points in found.items()}


def _bounds(points: numpy.ndarray) -> numpy.ndarray:
    return numpy.array([points.min(axis=0), points.max(axis=0)])


def dae_colours(urdf: Path, search_paths: list[Path]) -> list[tuple[float, ...]]:
    """Return the colours trimesh reads from the DAE files of a URDF's visuals (0 to 1)."""
    import trimesh
    import yourdfpy
    from urdfgenpy_ros.resources import PackageResolver
    model = yourdfpy.URDF.load(str(urdf), load_meshes=False, build_scene_graph=False,
                               build_collision_scene_graph=False)
    resolver = PackageResolver(search_paths)
    found = []
    for link in model.link_map.values():
        for visual in link.visuals:
            mesh = visual.geometry.mesh
            if mesh is None or not mesh.filename.lower().endswith('.dae'):
                continue
            try:
                path = resolver.resolve(mesh.filename, urdf.parent)
            except Exception:  # noqa: B902 - not found: the export leaves it out too
                continue
            scene = trimesh.load(str(path), force='scene', process=False)
            for geometry in scene.geometry.values():
                material = getattr(geometry.visual, 'material', None)
                factor = getattr(material, 'baseColorFactor', None)
                if factor is not None and getattr(material, 'baseColorTexture', None) is None:
                    found.append(tuple(float(value) / 255.0 for value in factor))
    return found
