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
The package's import graph, read from its source, has no cycle, and its layers hold.

Every ``import`` and ``from ... import`` anywhere in a module counts, inside functions and
methods too, and those under ``if TYPE_CHECKING:`` as well: an import that runs late is
still a dependency, and one for the type hints says what a module works on, so a cycle
through either ties modules that then cannot be understood, tested or moved one without
the other. ``from pkg import name`` is an edge to ``pkg.name`` when that is a module, else
to ``pkg``; relative imports are resolved. Names given to ``importlib.import_module`` as
strings (the user's builder functions, the viewer's optional engines) are not read.

Packages have no cycle either: each subpackage (``formats``, ``validation``, ``dynamics``,
``reshape``, ``moveit``, ``collision``, ``cli``, ...) is one node, with everything in it,
and each module at the top level is a node of its own (the top level as one node would be a
cycle by construction: it holds both the model and the facade). The edges that still close
a cycle of packages are named in :data:`CYCLE_LEFT`, each with why.

The layers (docs/architecture.md), each importing only those below it:

1. **Model** (:data:`MODEL`): the elements (``geometry``, ``link``, ``joint``,
   ``inertial``, ...), ``dh_row``, ``dh_skeleton``, ``mesh_inertia``, ``mesh_read`` and
   ``model.RobotModel``, the robot's data and tree.
2. **Operations** on a model: ``formats/``, ``validation/``, ``dynamics/``, ``reshape/``,
   ``assembly``, ``assembly_file``, ``builders``, ``tree``, ``lumping``, ``resources``,
   ``urdf_versions``, ``kinematics``, ``plugins``. They are typed against
   ``RobotModel`` and never name ``Robot``; a reader builds the class it is told
   (``Robot.from_urdf`` passes ``cls``) or else ``model.robot_class()``, which
   ``robot.py`` sets to ``Robot``; a copy is ``copy.deepcopy(robot)`` or
   ``type(robot)(...)``.
3. **Facade**: ``robot.Robot(RobotModel)``, whose methods (``save``, ``validate``, ``fk``,
   ``mirror``, ...) call down into the operations, and ``dh.DHTable``, whose
   ``to_robot`` gives a ``Robot`` (the skeleton is ``dh_skeleton``'s, the files
   ``formats.dh_table``'s).
4. **Above it** (:data:`USE_ROBOT`): the package's ``__init__``, the front ends (``cli/``,
   ``publisher/``, ``scaffold/``, ``viewer/``), ``examples``.
"""

from __future__ import annotations

import ast
from collections import deque
from collections.abc import Iterator
from pathlib import Path

from helpers import FIXTURES, REPO, require_module
import pytest

Graph = dict[str, set[str]]

PACKAGE = 'urdfgenpy_ros'
MODEL = frozenset([f'{PACKAGE}.model', *(f'{PACKAGE}.model.{path.stem}' for path in
                   (REPO / PACKAGE / 'model').glob('*.py') if path.stem != '__init__')])
"""The model layer: these import only each other."""
USE_ROBOT = (PACKAGE, f'{PACKAGE}.dh', f'{PACKAGE}.cli.', f'{PACKAGE}.publisher.',
             f'{PACKAGE}.scaffold.',
             f'{PACKAGE}.viewer.', f'{PACKAGE}.examples')
"""What may import the facade, ``urdfgenpy_ros.robot``, even for types (a module, or a
package's prefix ending in a dot)."""
CYCLE_LEFT: set[tuple[str, str]] = set()
"""The import edges that close a cycle of packages, each still to cut (and why it is there)."""


def _modules(root: Path) -> dict[str, Path]:
    """Return every module of the package in folder ``root``, by dotted name."""
    modules = {}
    for path in sorted(root.rglob('*.py')):
        parts = path.relative_to(root.parent).with_suffix('').parts
        if parts[-1] == '__init__':
            parts = parts[:-1]
        modules['.'.join(parts)] = path
    return modules


def _imports(node: ast.AST) -> Iterator[ast.Import | ast.ImportFrom]:
    """Yield every import statement under ``node``, TYPE_CHECKING's included."""
    if isinstance(node, ast.Import | ast.ImportFrom):
        yield node
    for child in ast.iter_child_nodes(node):
        yield from _imports(child)


def _targets(statement: ast.Import | ast.ImportFrom, package: str,
             modules: dict[str, Path]) -> Iterator[str]:
    """Yield the modules one import statement names (``package``: where it is written)."""
    if isinstance(statement, ast.Import):
        yield from (alias.name for alias in statement.names)
        return
    base = statement.module or ''
    if statement.level:
        parts = package.split('.')[:len(package.split('.')) - statement.level + 1]
        base = '.'.join(parts + ([base] if base else []))
    for alias in statement.names:
        yield f'{base}.{alias.name}' if f'{base}.{alias.name}' in modules else base


def import_graph(root: Path) -> Graph:
    """Return module -> the modules of the same package it imports, read from ``root``."""
    modules = _modules(root)
    graph: Graph = {}
    for name, path in modules.items():
        package = name if path.name == '__init__.py' else name.rpartition('.')[0]
        edges = graph.setdefault(name, set())
        tree = ast.parse(path.read_text(encoding='utf-8'), str(path))
        for statement in _imports(tree):
            edges.update(target for target in _targets(statement, package, modules)
                         if target in modules and target != name)
    return graph


def package_of(module: str, packages: set[str]) -> str:
    """Return the node of ``module`` in the package graph: its subpackage, else itself."""
    top = '.'.join(module.split('.')[:2])
    return top if top in packages else module


def package_graph(graph: Graph, root: Path) -> Graph:
    """Return the graph of :func:`package_of`'s nodes: a subpackage with all it holds is one."""
    packages = {f'{root.name}.{path.parent.name}' for path in root.glob('*/__init__.py')}
    nodes: Graph = {}
    for module, targets in graph.items():
        node = package_of(module, packages)
        edges = nodes.setdefault(node, set())
        edges.update(package_of(target, packages) for target in targets)
        edges.discard(node)
    return nodes


def _components(graph: Graph) -> list[list[str]]:
    """Return the strongly connected components of more than one module (Tarjan, no recursion)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, successors = work[-1]
            for successor in successors:
                if successor not in index:
                    index[successor] = low[successor] = len(index)
                    stack.append(successor)
                    on_stack.add(successor)
                    work.append((successor, iter(sorted(graph[successor]))))
                    break
                if successor in on_stack:
                    low[node] = min(low[node], index[successor])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[node])
                if low[node] == index[node]:
                    component = []
                    while True:
                        member = stack.pop()
                        on_stack.discard(member)
                        component.append(member)
                        if member == node:
                            break
                    if len(component) > 1:
                        found.append(sorted(component))
    return sorted(found)


def _shortest_cycle(graph: Graph, component: list[str]) -> list[str]:
    """Return the shortest cycle inside ``component``, as a path ending where it starts."""
    inside = set(component)
    best: list[str] | None = None
    for start in component:
        came_from: dict[str, str] = {}
        queue = deque([start])
        while queue:
            node = queue.popleft()
            if start in graph[node]:
                path = [node]
                while path[-1] != start:
                    path.append(came_from[path[-1]])
                cycle = path[::-1] + [start]
                if best is None or len(cycle) < len(best):
                    best = cycle
                break
            for successor in sorted(graph[node] & inside):
                if successor not in came_from and successor != start:
                    came_from[successor] = node
                    queue.append(successor)
    assert best is not None
    return best


def cycles(graph: Graph) -> list[str]:
    """Return each import cycle, the shortest of each component, as ``a -> b -> a``."""
    return [' -> '.join(_shortest_cycle(graph, component))
            for component in _components(graph)]


def assert_no_cycle(graph: Graph) -> None:
    """Fail naming each import cycle."""
    found = cycles(graph)
    assert found == [], 'import cycles (the shortest of each tangle):\n' + '\n'.join(found)


@pytest.fixture(scope='module')
def graph() -> Graph:
    return import_graph(REPO / PACKAGE)


def test_the_package_has_no_import_cycle(graph: Graph) -> None:
    assert len(graph) > 50 and f'{PACKAGE}.formats.table' in graph[f'{PACKAGE}.robot']
    assert_no_cycle(graph)


def test_the_packages_have_no_import_cycle(graph: Graph) -> None:
    still = {edge for edge in CYCLE_LEFT if edge[1] in graph.get(edge[0], ())}
    assert still == set(CYCLE_LEFT), 'gone: take them off CYCLE_LEFT'
    cut = {module: targets - {target for source, target in CYCLE_LEFT if source == module}
           for module, targets in graph.items()}
    packages = package_graph(cut, REPO / PACKAGE)
    assert {f'{PACKAGE}.formats', f'{PACKAGE}.validation', f'{PACKAGE}.robot'} <= set(packages)
    assert_no_cycle(packages)


def test_the_model_imports_nothing_above_it(graph: Graph) -> None:
    assert MODEL <= set(graph)
    above = {f'{module} -> {target}' for module in MODEL for target in graph[module] - MODEL}
    assert above == set()


def _above(module: str) -> bool:
    return any(module == name or name.endswith('.') and module.startswith(name)
               for name in USE_ROBOT)


def test_only_what_is_above_the_facade_imports_it(graph: Graph) -> None:
    users = {module for module, targets in graph.items() if f'{PACKAGE}.robot' in targets}
    assert {f'{PACKAGE}.cli.view', f'{PACKAGE}.examples', f'{PACKAGE}.dh', PACKAGE} <= users
    assert {module for module in users if not _above(module)} == set()
    assert not _above(f'{PACKAGE}.dh_row') and _above(f'{PACKAGE}.cli.view')


def _package(folder: Path, files: dict[str, str]) -> Path:
    for name, text in files.items():
        path = folder / 'pkg' / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return folder / 'pkg'


def test_a_cycle_through_an_import_inside_a_function_is_found(tmp_path: Path) -> None:
    root = _package(tmp_path, {
        '__init__.py': 'from pkg.facade import Facade\n',
        'facade.py': 'from pkg import model\n\nclass Facade(model.Model):\n'
                     '    def save(self):\n        from .ops.write import write\n',
        'model.py': 'class Model:\n    pass\n',
        'ops/__init__.py': '',
        'ops/write.py': 'def write(robot):\n    from pkg.facade import Facade\n',
        'ops/typed.py': 'from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n'
                        '    from pkg.facade import Facade\nelse:\n    from pkg import model\n',
        'ops/deep.py': 'import pkg.ops.write\nfrom .. import model\n',
        'other.py': 'from pkg.ops import deep\n',
    })
    graph = import_graph(root)
    assert graph['pkg.ops.write'] == {'pkg.facade'}
    assert graph['pkg.ops.typed'] == {'pkg.facade', 'pkg.model'}  # TYPE_CHECKING's counts
    assert graph['pkg.ops.deep'] == {'pkg.ops.write', 'pkg.model'}
    assert graph['pkg.other'] == {'pkg.ops.deep'}
    assert cycles(graph) == ['pkg.facade -> pkg.ops.write -> pkg.facade']
    with pytest.raises(AssertionError, match='pkg.facade -> pkg.ops.write -> pkg.facade'):
        assert_no_cycle(graph)


def test_each_component_names_its_shortest_cycle(tmp_path: Path) -> None:
    root = _package(tmp_path, {
        '__init__.py': '',
        'a.py': 'import pkg.b\nimport pkg.c\n',
        'b.py': 'import pkg.c\n',
        'c.py': 'def f():\n    import pkg.a\n',
        'x.py': 'class X:\n    def m(self):\n        from pkg.y import Y\n',
        'y.py': 'from pkg import x\n',
        'z.py': 'import pkg.a\n',
    })
    assert cycles(import_graph(root)) == ['pkg.a -> pkg.c -> pkg.a', 'pkg.x -> pkg.y -> pkg.x']


def test_a_cycle_between_packages_is_found_without_one_between_modules(tmp_path: Path) -> None:
    root = _package(tmp_path, {
        '__init__.py': '', 'top.py': 'from pkg.a import x\n', 'low.py': '',
        'a/__init__.py': '', 'a/x.py': 'from pkg.b import y\nfrom pkg import low\n',
        'a/z.py': '',
        'b/__init__.py': '', 'b/y.py': 'from typing import TYPE_CHECKING\n'
                                       'if TYPE_CHECKING:\n    from pkg.a.z import Z\n',
    })
    graph = import_graph(root)
    assert cycles(graph) == []
    assert package_graph(graph, root) == {
        'pkg': set(), 'pkg.top': {'pkg.a'}, 'pkg.low': set(), 'pkg.a': {'pkg.b', 'pkg.low'},
        'pkg.b': {'pkg.a'}}
    assert cycles(package_graph(graph, root)) == ['pkg.a -> pkg.b -> pkg.a']


def numbers(root: Path) -> dict[str, int]:
    """Return the sizes of the import graph read from ``root``, for the record."""
    graph = import_graph(root)
    packages = package_graph(graph, root)
    return {'modules': len(graph), 'edges': sum(map(len, graph.values())),
            'module cycles': len(cycles(graph)),
            'modules in cycles': sum(map(len, _components(graph))),
            'packages': len(packages), 'package edges': sum(map(len, packages.values())),
            'package cycles': len(cycles(packages)),
            'packages in cycles': sum(map(len, _components(packages))),
            'importers of robot': sum(f'{root.name}.robot' in targets
                                      for targets in graph.values())}


def test_every_reader_and_copy_builds_a_robot_of_the_class_asked(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The readers do not import Robot, yet what they build is one (or the subclass asked)."""
    require_module('xacro')
    from urdfgenpy_ros import Robot
    from urdfgenpy_ros.dh import DHRow, DHTable
    from urdfgenpy_ros.formats import load
    from urdfgenpy_ros.formats.builders import robot_from_function
    from urdfgenpy_ros.formats.urdf_downgrade import as_version
    from urdfgenpy_ros.model import RobotModel

    class Mine(Robot):
        pass

    urdf = FIXTURES / 'packages' / 'fixture_description' / 'urdf' / 'every_element.urdf'
    xacro = urdf.with_name('arm.urdf.xacro')
    packages = [FIXTURES / 'packages']
    table = DHTable('standard', [DHRow(1, 0.1), DHRow(2, 0.2, joint_type='prismatic')])
    table.save(tmp_path / 'arm.yaml')
    (tmp_path / 'base.urdf').write_bytes(urdf.read_bytes())
    (tmp_path / 'builder_of_text.py').write_text(
        'def text():\n    return """<robot name=\'r\'><link name=\'l\'/></robot>"""\n')
    (tmp_path / 'both.assembly.yaml').write_text(
        f'parts:\n  - file: base.urdf\n  - file: arm.yaml\n'
        f'    at: {Robot.from_urdf(urdf).root.name}\n    prefix: arm_\n')
    built = {
        'load .urdf': load(urdf), 'load .urdf.xacro': load(xacro, search_paths=packages),
        'load DH table': load(tmp_path / 'arm.yaml'),
        'load assembly': load(tmp_path / 'both.assembly.yaml'),
        'from_assembly': Robot.from_assembly(tmp_path / 'both.assembly.yaml'),
        'from_urdf_string': Robot.from_urdf_string(urdf.read_bytes()),
        'to_robot': table.to_robot('arm'), 'merge_fixed': load(urdf).merge_fixed(),
        'as_version': as_version(load(urdf), '1.0')[0],
    }
    monkeypatch.chdir(tmp_path)  # the builder's module is found from here, as the node does
    built['builder function'] = robot_from_function('builder_of_text:text')
    assert {name: type(robot) for name, robot in built.items()} == dict.fromkeys(built, Robot)
    mine = [Mine.from_urdf(urdf), Mine.from_urdf_string(urdf.read_bytes()),
            Mine.from_xacro(xacro, search_paths=packages),
            as_version(Mine.from_urdf(urdf), '1.0')[0], Mine.from_urdf(urdf).merge_fixed()]
    assert [type(robot) for robot in mine] == [Mine] * len(mine)
    assert isinstance(mine[0], RobotModel)
    assert type(DHTable.from_file(tmp_path / 'arm.yaml')) is DHTable


if __name__ == '__main__':  # python test/test_import_graph.py [package folder]
    import sys
    folder = Path(sys.argv[1]) if len(sys.argv) > 1 else REPO / PACKAGE
    for name, count in numbers(folder).items():
        print(f'{name}: {count}')
    found = import_graph(folder)
    print(*cycles(found), *cycles(package_graph(found, folder)), sep='\n')
