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
A still picture of a robot without a display or GPU: VTK rendering off screen.

The camera is orthographic (as in engineering drawings), framed on the posed robot, so
``Camera.project`` maps a point in the root frame to its pixel exactly.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
import math
from os import PathLike
from pathlib import Path
from typing import Any

from urdfgenpy_ros.model.errors import UrdfgenpyError
from urdfgenpy_ros.robot import Robot
from urdfgenpy_ros.viewer.nothing import nothing_to_draw
from urdfgenpy_ros.viewer.scene import (
    joint_positions, link_matrices, MeshCache, Part, require, robot_parts)

VIEWS: dict[str, tuple[tuple[float, float, float], tuple[float, float, float]]] = {
    # name: (direction from the robot to the camera, the image's up)
    'iso': ((1.0, -0.9, 0.75), (0.0, 0.0, 1.0)),
    'front': ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0)),
    'side': ((0.0, -1.0, 0.0), (0.0, 0.0, 1.0)),
    'top': ((0.0, 0.0, 1.0), (1.0, 0.0, 0.0)),
}
BACKGROUND = (1.0, 1.0, 1.0)
SUPERSAMPLING = 2  # render at twice the size and average: anti-aliasing that OSMesa keeps


def _offscreen_window() -> Any:
    """Return an off-screen render window: OSMesa, else EGL, else VTK's default."""
    from ctypes.util import find_library
    import os
    from vtkmodules import vtkRenderingOpenGL2
    from vtkmodules.vtkRenderingCore import vtkRenderWindow
    if os.environ.get('VTK_DEFAULT_OPENGL_WINDOW'):
        return vtkRenderWindow()
    if find_library('OSMesa'):
        return vtkRenderingOpenGL2.vtkOSOpenGLRenderWindow()
    if find_library('EGL'):
        return vtkRenderingOpenGL2.vtkEGLRenderWindow()
    return vtkRenderWindow()


@dataclass(frozen=True)
class Camera:
    """An orthographic camera: pixel = centre + (offset . right, offset . up) / scale."""

    focal_point: tuple[float, float, float]
    right: tuple[float, float, float]
    up: tuple[float, float, float]
    metres_per_pixel: float
    width: int
    height: int

    def project(self, point: Iterable[float]) -> tuple[float, float]:
        """Return the (column, row) pixel where ``point`` (root frame) is drawn."""
        offset = [p - f for p, f in zip(point, self.focal_point)]
        across = sum(o * r for o, r in zip(offset, self.right))
        upward = sum(o * u for o, u in zip(offset, self.up))
        return (self.width / 2.0 + across / self.metres_per_pixel,
                self.height / 2.0 - upward / self.metres_per_pixel)


def _unit(vector: Iterable[float]) -> tuple[float, float, float]:
    x, y, z = vector
    norm = math.sqrt(x * x + y * y + z * z)
    return (x / norm, y / norm, z / norm)


def _cross(a: tuple[float, float, float], b: tuple[float, float, float]
           ) -> tuple[float, float, float]:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def frame(points: Any, view: str, width: int, height: int, margin: float = 0.08) -> Camera:
    """Return the camera of ``view`` that fits ``points`` (n x 3) in the image."""
    if view not in VIEWS:
        raise UrdfgenpyError(f'unknown view {view!r} (use one of {", ".join(VIEWS)})')
    towards, up_hint = VIEWS[view]
    direction = _unit(towards)
    right = _unit(_cross(up_hint, direction))
    up = _cross(direction, right)
    import numpy
    low, high = points.min(axis=0), points.max(axis=0)
    centre = (low + high) / 2.0
    across = (points - centre) @ numpy.array(right)
    upward = (points - centre) @ numpy.array(up)
    shift = ((across.max() + across.min()) / 2.0) * numpy.array(right) + \
        ((upward.max() + upward.min()) / 2.0) * numpy.array(up)
    centre = centre + shift
    extent_w = max(float(across.max() - across.min()), 1e-6)
    extent_h = max(float(upward.max() - upward.min()), 1e-6)
    scale = max(extent_w / (width * (1 - 2 * margin)), extent_h / (height * (1 - 2 * margin)))
    focal_point = (float(centre[0]), float(centre[1]), float(centre[2]))
    return Camera(focal_point, right, up, scale, width, height)


def _poly_data(part: Part, matrix: Any) -> Any:
    import numpy
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    vertices = numpy.asarray(part.mesh.vertices, dtype=float) @ matrix[:3, :3].T + matrix[:3, 3]
    faces = numpy.asarray(part.mesh.faces, dtype=numpy.int64)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(numpy.ascontiguousarray(vertices), deep=True))
    cells = vtkCellArray()
    offsets = numpy.arange(0, 3 * len(faces) + 1, 3, dtype=numpy.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(faces.ravel().copy(), deep=True))
    data = vtkPolyData()
    data.SetPoints(points)
    data.SetPolys(cells)
    if part.textured:
        visual = part.mesh.visual  # a texture's colours, or colours by vertex or face
        colours = numpy.asarray((visual.to_color() if hasattr(visual, 'to_color') else visual)
                                .vertex_colors, dtype=numpy.uint8)
        if len(colours) == len(vertices):
            array = numpy_to_vtk(numpy.ascontiguousarray(colours[:, :3]), deep=True)
            array.SetName('colours')
            data.GetPointData().SetScalars(array)
    return data


def _actor(part: Part, matrix: Any) -> Any:
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper
    normals = vtkPolyDataNormals()
    normals.SetInputData(_poly_data(part, matrix))
    normals.SetFeatureAngle(40.0)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.SetScalarVisibility(part.textured)
    actor = vtkActor()
    actor.SetMapper(mapper)
    properties = actor.GetProperty()
    properties.SetColor(*part.rgba[:3])
    properties.SetOpacity(part.rgba[3])
    properties.SetAmbient(0.15)
    properties.SetDiffuse(0.8)
    properties.SetSpecular(0.25)
    properties.SetSpecularPower(30.0)
    return actor


@dataclass
class Picture:
    """What ``render`` drew: the image (rows x columns x RGB) and its camera."""

    pixels: Any
    camera: Camera
    problems: list[str]


def render(robot: Robot, values: Mapping[str, float] | None = None, view: str = 'iso',
           size: tuple[int, int] = (800, 600), collision: bool = False,
           search_paths: Iterable[str | PathLike[str]] = ()) -> Picture:
    """
    Draw ``robot`` posed at joint ``values`` (mimic joints follow; missing ones at 0).

    :raises MissingDependencyError: without vtk, trimesh or numpy (the ``render`` extra).
    :raises UrdfgenpyError: for an unknown joint or view, or a robot with nothing to draw.
    """
    numpy = require('numpy', 'render', 'urdfgenpy render')
    require('vtkmodules', 'render', 'urdfgenpy render')
    require('trimesh', 'render', 'urdfgenpy render')
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 - registers the OpenGL back end
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
    from vtkmodules.vtkRenderingCore import vtkLightKit, vtkRenderer
    positions = joint_positions(robot, values or {})
    matrices = link_matrices(robot, positions)
    cache = MeshCache(robot, search_paths)
    parts = robot_parts(robot, 'collision' if collision else 'visual', cache)
    if not parts:
        raise UrdfgenpyError(nothing_to_draw(robot, collision, cache.problems))
    width, height = size
    renderer = vtkRenderer()
    renderer.SetBackground(*BACKGROUND)
    corners = []
    for part in parts:
        matrix = matrices[part.link]
        renderer.AddActor(_actor(part, matrix))
        low, high = part.mesh.bounds
        box = numpy.array([[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1])
                           for z in (low[2], high[2])])
        corners.append(box @ matrix[:3, :3].T + matrix[:3, 3])
    camera = frame(numpy.concatenate(corners), view, width, height)
    vtk_camera = renderer.GetActiveCamera()
    vtk_camera.ParallelProjectionOn()
    direction = numpy.cross(camera.right, camera.up)  # towards the viewer
    distance = 10.0 * camera.metres_per_pixel * max(width, height)
    vtk_camera.SetFocalPoint(*camera.focal_point)
    vtk_camera.SetPosition(*(numpy.array(camera.focal_point) + distance * direction))
    vtk_camera.SetViewUp(*camera.up)
    vtk_camera.SetParallelScale(camera.metres_per_pixel * height / 2.0)
    renderer.ResetCameraClippingRange()
    lights = vtkLightKit()
    lights.SetKeyLightIntensity(0.9)
    lights.AddLightsToRenderer(renderer)
    window = _offscreen_window()
    window.SetOffScreenRendering(1)
    window.SetSize(width * SUPERSAMPLING, height * SUPERSAMPLING)
    window.AddRenderer(renderer)
    window.Render()
    buffer = vtkUnsignedCharArray()
    big_width, big_height = window.GetSize()
    window.GetPixelData(0, 0, big_width - 1, big_height - 1, 0, buffer, 0)
    window.Finalize()
    big = vtk_to_numpy(buffer).reshape(height, SUPERSAMPLING, width, SUPERSAMPLING, 3)
    pixels = (big.sum(axis=(1, 3), dtype=numpy.uint32) // SUPERSAMPLING ** 2
              ).astype(numpy.uint8)  # anti-aliased
    return Picture(numpy.flipud(pixels).copy(), camera, cache.problems)


def _png_writer(picture: Picture) -> Any:
    import numpy
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOImage import vtkPNGWriter
    height, width, _ = picture.pixels.shape
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    flat = numpy.ascontiguousarray(numpy.flipud(picture.pixels)).reshape(-1, 3)
    image.GetPointData().SetScalars(numpy_to_vtk(flat, deep=True))
    writer = vtkPNGWriter()
    writer.SetInputData(image)
    return writer


def save_picture(picture: Picture, path: str | PathLike[str]) -> Path:
    """Write the picture as PNG."""
    writer = _png_writer(picture)
    writer.SetFileName(str(path))
    writer.Write()
    if writer.GetErrorCode():
        raise UrdfgenpyError(f'{path}: cannot write the picture (is the folder writable?)')
    return Path(path)


def picture_png(picture: Picture) -> bytes:
    """Return the picture as PNG bytes."""
    writer = _png_writer(picture)
    writer.WriteToMemoryOn()
    writer.Write()
    return bytes(writer.GetResult())
