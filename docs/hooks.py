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
MkDocs hooks: the generated parts of the site, made from the code at every build.

A page asks for a part with an HTML comment on a line of its own:

- ``<!-- generated: codes -->``: the finding codes, from ``model/codes.py``;
- ``<!-- generated: node-parameters -->``: the node's parameters, from its declarations
  in ``publisher/node.py`` (read with ``ast``: building the site needs no ROS);
- ``<!-- generated: commands -->``: every ``urdfgenpy`` command's ``--help``;
- ``<!-- generated: include FILE -->``: a file of the repository (``bench/RESULTS.md``,
  ``CHANGELOG.md``), its first heading dropped and the others one level down.

Lines between a marker and ``<!-- end generated -->`` are what a reader of the page on
GitHub sees instead (where the part is); the site replaces them with the part. The parts
in ``COMMITTED`` (the codes and the node's parameters) are kept there as the code makes
them, so GitHub shows the tables too: ``python docs/hooks.py`` writes them again after a
change, and ``test/test_docs_generated.py`` fails while one is not current.

Sphinx roles in docstrings (``:func:`name```) are shown as the code they name. Pages in
``docs/`` that ``nav`` does not list are added under "More" (new pages appear
without editing mkdocs.yml; move them where they belong when you like).
"""

from __future__ import annotations

import ast
from pathlib import Path
import re
from typing import Any

REPO = Path(__file__).resolve().parent.parent
MARKER = re.compile(r'^<!-- generated: (?P<what>[\w-]+)(?: (?P<argument>\S+))? -->$'
                    r'(?:\n(?:(?!<!-- generated)(?!<!-- end generated -->).*\n)*'
                    r'<!-- end generated -->$)?', re.M)

FAMILIES = {
    'P': 'Reading', 'X': 'Xacro', 'S': 'Structure', 'J': 'Joints', 'I': 'Inertia',
    'R': 'References and values', 'V': 'URDF versions', 'C': 'Conventions',
    'M': 'MuJoCo pre-flight (`check --engines mujoco`)',
    'G': 'Gazebo pre-flight (`check --engines gazebo`)',
}
KINDS = {
    'PARAMETER_STRING': 'string', 'PARAMETER_BOOL': 'bool', 'PARAMETER_INTEGER': 'integer',
    'PARAMETER_DOUBLE': 'double', 'PARAMETER_STRING_ARRAY': 'string array',
}


def _cell(text: str) -> str:
    """Return ``text`` safe inside a Markdown table cell; XML tags become code."""
    text = re.sub(r'(<[^<>]+>)+', lambda match: f'`{match[0]}`', text)
    return text.replace('|', '\\|').replace('\n', ' ')


def codes_table() -> str:
    """Return a table per code family, made from ``CODES`` and ``PREFLIGHT_HINTS``."""
    from urdfgenpy_ros.model.codes import CODES, PREFLIGHT_HINTS
    lines: list[str] = []
    family = ''
    for code, (severity, title) in CODES.items():
        hinted = code in PREFLIGHT_HINTS
        if code[0] != family:
            family = code[0]
            lines += ['', f'### {FAMILIES.get(family, family)}', '',
                      '| code | severity | meaning |' + (' what to do |' if hinted else ''),
                      '|---|---|---|' + ('---|' if hinted else '')]
        row = f'| {code} | {severity.value} | {_cell(title)} |'
        lines.append(row + (f' {_cell(PREFLIGHT_HINTS[code])} |' if hinted else ''))
    return '\n'.join(lines).strip() + '\n'


def _kind(node: ast.expr, names: dict[str, ast.expr]) -> str:
    """Return the ROS parameter type an expression of the declarations names."""
    if isinstance(node, ast.Name) and node.id in names:
        return _kind(names[node.id], names)
    if isinstance(node, ast.Attribute):
        return KINDS[node.attr]
    if isinstance(node, ast.Constant) and node.value is None:
        return 'integer or double'
    raise ValueError(f'publisher/node.py: unknown parameter type {ast.dump(node)}')


def node_parameters() -> list[tuple[str, Any, str, str]]:
    """Return (name, default, type, description) as ``publisher/node.py`` declares them."""
    tree = ast.parse((REPO / 'urdfgenpy_ros' / 'publisher' / 'node.py').read_text())
    names: dict[str, ast.expr] = {}
    table: ast.Dict | None = None
    for statement in tree.body:
        if isinstance(statement, ast.Assign) and isinstance(statement.targets[0], ast.Name):
            names[statement.targets[0].id] = statement.value
        elif isinstance(statement, ast.AnnAssign) and isinstance(statement.target, ast.Name):
            if statement.target.id == '_PARAMETERS' and isinstance(statement.value, ast.Dict):
                table = statement.value
    if table is None:
        raise ValueError('publisher/node.py: no _PARAMETERS table of declarations')
    rows = []
    for key, value in zip(table.keys, table.values):
        assert isinstance(key, ast.expr) and isinstance(value, ast.Tuple)
        default, kind, description = value.elts
        rows.append((ast.literal_eval(key), ast.literal_eval(default),
                     _kind(kind, names), ast.literal_eval(description)))
    return rows


def _ros_value(value: Any) -> str:
    """Return ``value`` spelt as on a ``--ros-args -p`` line."""
    if isinstance(value, bool):
        return 'true' if value else 'false'
    if isinstance(value, str):
        return f"'{value}'"
    return str(value)


def parameters_table() -> str:
    """Return the node's parameters as a Markdown table."""
    lines = ['| parameter | type | default | meaning |', '|---|---|---|---|']
    for name, default, kind, description in node_parameters():
        lines.append(f'| `{name}` | {kind} | `{_ros_value(default)}` | {_cell(description)} |')
    return '\n'.join(lines) + '\n'


def commands_help() -> str:
    """Return every ``urdfgenpy`` command's ``--help`` as the command prints it."""
    from click.testing import CliRunner

    from urdfgenpy_ros.cli import main
    parts = []
    for name in ['', *sorted(main.commands)]:
        result = CliRunner(env={'COLUMNS': '88'}).invoke(
            main, [name, '--help'] if name else ['--help'], prog_name='urdfgenpy',
            terminal_width=88, max_content_width=88)
        if result.exit_code != 0:
            raise RuntimeError(f'urdfgenpy {name} --help failed: {result.output}')
        title = f'urdfgenpy {name}'.strip()
        parts += [f'## `{title}`', '', '```text', result.output.rstrip(), '```', '']
    return '\n'.join(parts)


def include(relative: str) -> str:
    """Return a repository file's Markdown, first heading dropped, the others one down."""
    text = (REPO / relative).read_text(encoding='utf-8')
    lines = text.splitlines()
    if lines and lines[0].startswith('# '):
        lines = lines[1:]
    fenced = False
    for number, line in enumerate(lines):
        if line.lstrip().startswith('```'):
            fenced = not fenced
        elif not fenced and re.match(r'#{1,5} ', line):
            lines[number] = '#' + line
    return '\n'.join(lines).strip() + '\n'


def generate(what: str, argument: str | None) -> str:
    """Return the Markdown a ``<!-- generated: ... -->`` marker stands for."""
    if what == 'codes':
        return codes_table()
    if what == 'node-parameters':
        return parameters_table()
    if what == 'commands':
        return commands_help()
    if what == 'include' and argument:
        return include(argument)
    raise ValueError(f'unknown generated part {what!r} {argument or ""}')


COMMITTED = frozenset(('codes', 'node-parameters'))
"""The parts kept in the pages' Markdown as generated (the others only on the site)."""


def with_committed_parts(markdown: str) -> str:
    """Return ``markdown`` with each committed part between its markers as made now."""
    def part(match: re.Match[str]) -> str:
        if match['what'] not in COMMITTED:
            return match[0]
        marker = match[0].split('\n', 1)[0]
        return f'{marker}\n\n{generate(match["what"], match["argument"])}\n<!-- end generated -->'
    return MARKER.sub(part, markdown)


def refresh(docs: Path = REPO / 'docs') -> list[Path]:
    """Write the committed parts of every page of ``docs`` again; return the pages changed."""
    changed = []
    for page in sorted(docs.glob('*.md')):
        text = page.read_text(encoding='utf-8')
        current = with_committed_parts(text)
        if current != text:
            page.write_text(current, encoding='utf-8')
            changed.append(page)
    return changed


def on_page_markdown(markdown: str, **_: Any) -> str:
    """Replace each marker by the part it names."""
    return MARKER.sub(lambda match: generate(match['what'], match['argument']), markdown)


SPHINX_ROLE = re.compile(r':(?:py:)?(?:func|class|meth|mod|attr|data|exc|obj):(?=<code)')


def on_page_content(html: str, **_: Any) -> str:
    """Drop the Sphinx roles (``:func:``) the docstrings use; their names stay as code."""
    return SPHINX_ROLE.sub('', html)


def _listed(nav: Any) -> set[str]:
    """Return every page file ``nav`` names."""
    if isinstance(nav, str):
        return {nav}
    if isinstance(nav, list):
        return set().union(*(_listed(item) for item in nav)) if nav else set()
    if isinstance(nav, dict):
        return set().union(*(_listed(item) for item in nav.values()))
    return set()


def on_config(config: Any, **_: Any) -> Any:
    """Add the pages of ``docs/`` that ``nav`` does not list under "More"."""
    nav = config['nav']
    if nav is None:
        return config
    listed = _listed(nav)
    docs = Path(config['docs_dir'])
    missing = sorted(path.relative_to(docs).as_posix() for path in docs.rglob('*.md')
                     if path.relative_to(docs).as_posix() not in listed)
    if missing:
        nav.append({'More': missing})
    return config


if __name__ == '__main__':  # python docs/hooks.py: the committed tables, as the code is
    import sys
    sys.path.insert(0, str(REPO))
    for written in refresh():
        print(f'wrote {written.relative_to(REPO)}')
