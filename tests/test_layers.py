"""The import graph of the cnlmc package: no cycles, and the language (compiler/) never imports
a target (backends/).

Every module of the package (the folders pyproject.toml maps to cnlmc.*) is read with `ast`;
every import counts, those inside functions included, since a function-level import only
hides a cycle until the function runs. Imports under ``if TYPE_CHECKING:`` never run, so they
count for the layer rule but not for cycles.

The front ends in compiler/ (the CLI, api.emit) may import cnlmc.backends.registry and nothing
else of backends/. ALLOWED lists an edge that breaks these rules, with its reason (one: the teaching of a
failed line compiles its offers); test_allowed_edges_still_exist keeps every entry honest.
"""

from __future__ import annotations

import ast
import tomllib
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BACKENDS = "cnlmc.backends"

#: The front ends over both layers (the CLI, and the facade's emit) reach targets only through
#: the registry, which imports none of them until one is asked for by name.
FRONT_ENDS = frozenset(
    {
        "cnlmc.cli",
        "cnlmc.commands",
        "cnlmc.api",
        # batch builds (#20): the `build` command, and the one module that parses each target's
        # options and runs a target on a material in a worker (cnlmc.batch's only registry users)
        "cnlmc.batch.command",
        "cnlmc.batch.work",
        # speech input (#18): the `listen` command runs the target on what was said
        "cnlmc.speech.command",
        # the web studio (#17): the `serve` command, its exports and its marker AR run targets
        "cnlmc.studio.command",
        "cnlmc.studio.exports",
        "cnlmc.studio.ar",
    }
)
REGISTRY = "cnlmc.backends.registry"

#: (importer, imported) -> why an edge that breaks the rules is still there. Empty: keep it so.
ALLOWED: dict[tuple[str, str], str] = {
    ("cnlmc.teach", "cnlmc.api"): (
        "a rejected line's offered phrases ('matte black' -> 'matte black paint') are each compiled to "
        "check that the compiler accepts them as offered: a compile inside the teaching of a failed "
        "line, imported in the function, only when a line has no noun"
    ),
    ("cnlmc.studio.view_payload", "cnlmc.backends.preview.web"): (
        "the studio's live WebGL2 view (#17) draws what `cnlmc preview` draws: its payload is the preview "
        "backend's splitsum shader, tables, environment and meshes, as data; imported in the function, "
        "only when the studio asks for a payload or an asset"
    ),
    ("cnlmc.api", "cnlmc.batch"): (
        "the facade's build() (#20) hands a catalogue to the batch front end, which compiles it through "
        "the facade: imported in the function, only when a build is asked for"
    ),
}


@dataclass(frozen=True)
class Edge:
    importer: str
    imported: str
    line: int
    runtime: bool  # False under `if TYPE_CHECKING:`

    @property
    def pair(self) -> tuple[str, str]:
        return self.importer, self.imported

    def where(self) -> str:
        return f"{self.importer} -> {self.imported} (line {self.line})"


def package_folders() -> dict[str, Path]:
    """Package name -> folder, from pyproject.toml's [tool.setuptools.package-dir]."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))
    return {name: ROOT / folder for name, folder in config["tool"]["setuptools"]["package-dir"].items()}


def module_files() -> dict[str, Path]:
    """Every module of the package: dotted name -> file. A sub-package mapped to its own folder
    (cnlmc.backends -> backends/) wins over the same path seen from its parent's folder."""
    modules: dict[str, Path] = {}
    for package, folder in sorted(package_folders().items(), key=lambda item: item[0].count(".")):
        for path in sorted(folder.rglob("*.py")):
            parts = path.relative_to(folder).with_suffix("").parts
            if parts[-1] == "__init__":
                parts = parts[:-1]
            modules[".".join((package, *parts))] = path
    return modules


def is_package(path: Path) -> bool:
    return path.name == "__init__.py"


def resolve(module: str, path: Path, level: int, target: str | None) -> str:
    """The absolute name a (possibly relative) `from` import refers to."""
    if level == 0:
        return target or ""
    package = module if is_package(path) else module.rpartition(".")[0]
    base = package.rsplit(".", level - 1)[0] if level > 1 else package
    return f"{base}.{target}" if target else base


def type_checking_lines(tree: ast.AST) -> set[int]:
    """Line numbers of the statements under `if TYPE_CHECKING:`."""
    lines: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.If) and "TYPE_CHECKING" in ast.unparse(node.test):
            for statement in node.body:
                for inner in ast.walk(statement):
                    if hasattr(inner, "lineno"):
                        lines.add(inner.lineno)
    return lines


def imported_names(module: str, path: Path, node: ast.Import | ast.ImportFrom) -> Iterator[str]:
    if isinstance(node, ast.Import):
        yield from (alias.name for alias in node.names)
        return
    base = resolve(module, path, node.level, node.module)
    for alias in node.names:
        yield f"{base}.{alias.name}"  # a submodule, or a name defined in `base` (see known_module)
        yield base


def known_module(name: str, modules: dict[str, Path]) -> str | None:
    """The deepest module of the package `name` is, or is defined in."""
    while name:
        if name in modules:
            return name
        name = name.rpartition(".")[0]
    return None


def edges_of(module: str, path: Path, modules: dict[str, Path]) -> set[Edge]:
    tree = ast.parse(path.read_text("utf-8"), str(path))
    hidden = type_checking_lines(tree)
    edges: set[Edge] = set()
    for node in ast.walk(tree):
        if not isinstance(node, ast.Import | ast.ImportFrom):
            continue
        names = list(imported_names(module, path, node))
        if isinstance(node, ast.ImportFrom):  # `from pkg import sub` -> pkg.sub when sub is a module
            names = [n for n in names[0::2] if n in modules] or names[1:2]
        for name in names:
            target = known_module(name, modules)
            if target is not None and target != module:
                edges.add(Edge(module, target, node.lineno, node.lineno not in hidden))
    return edges


def import_graph() -> list[Edge]:
    modules = module_files()
    edges: set[Edge] = set()
    for module, path in modules.items():
        edges |= edges_of(module, path, modules)
    return sorted(edges, key=lambda e: (e.importer, e.imported, e.line))


def strongly_connected(nodes: set[str], successors: dict[str, set[str]]) -> list[list[str]]:
    """Tarjan's algorithm, iteratively: the components with more than one module."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    components: list[list[str]] = []
    for start in sorted(nodes):
        if start in index:
            continue
        work = [(start, iter(sorted(successors.get(start, ()))))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(successors.get(child, ())))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
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
                    components.append(sorted(component))
    return components


def cycle_through(start: str, members: set[str], successors: dict[str, set[str]]) -> list[str]:
    """A shortest chain start -> ... -> start inside one component (breadth first)."""
    previous: dict[str, str] = {}
    frontier = [start]
    while frontier:
        following = []
        for node in frontier:
            for child in sorted(successors.get(node, set()) & members):
                if child == start:
                    chain = [node]
                    while chain[-1] != start:
                        chain.append(previous[chain[-1]])
                    return [start, *reversed(chain[:-1]), start] if node != start else [start, start]
                if child not in previous:
                    previous[child] = node
                    following.append(child)
        frontier = following
    return [start]


def runtime_successors(edges: list[Edge]) -> dict[str, set[str]]:
    successors: dict[str, set[str]] = {}
    for edge in edges:
        if edge.runtime and edge.pair not in ALLOWED:
            successors.setdefault(edge.importer, set()).add(edge.imported)
    return successors


def is_compiler_layer(module: str) -> bool:
    return not (module == BACKENDS or module.startswith(BACKENDS + "."))


@pytest.fixture(scope="module")
def edges() -> list[Edge]:
    return import_graph()


def test_the_graph_sees_the_whole_package(edges: list[Edge]) -> None:
    modules = module_files()
    assert {"cnlmc", "cnlmc.api", "cnlmc.backends", "cnlmc.cli"} <= set(modules)
    assert len(edges) > 100  # function-level imports included


def test_no_import_cycles(edges: list[Edge]) -> None:
    successors = runtime_successors(edges)
    components = strongly_connected(set(successors), successors)
    lines = []
    for members in components:
        member_set = set(members)
        lines.append(
            f"cycle among {len(members)} modules: " + " -> ".join(cycle_through(members[0], member_set, successors))
        )
        lines += [
            f"    {e.where()}" for e in edges if e.runtime and e.pair not in ALLOWED and set(e.pair) <= member_set
        ]
    assert not components, "import cycles (break them, or add an edge to ALLOWED with its reason):\n" + "\n".join(lines)


def test_the_compiler_layer_imports_no_backend(edges: list[Edge]) -> None:
    violations = [
        e.where()
        for e in edges
        if is_compiler_layer(e.importer)
        and not is_compiler_layer(e.imported)
        and e.pair not in ALLOWED
        and not (e.importer in FRONT_ENDS and e.imported == REGISTRY)
    ]
    assert not violations, "compiler/ (cnlmc.*) imports backends (cnlmc.backends.*):\n" + "\n".join(violations)


def test_allowed_edges_still_exist(edges: list[Edge]) -> None:
    present = {e.pair for e in edges}
    stale = sorted(pair for pair in ALLOWED if pair not in present)
    assert not stale, "these ALLOWED edges are gone: delete them from tests/test_layers.py:\n" + "\n".join(
        f"    {a} -> {b}" for a, b in stale
    )
