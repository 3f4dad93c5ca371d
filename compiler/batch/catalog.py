"""A catalogue read and compiled: its .cnl files, each material as a one-material IR document.

A material's document is what its files are made from, and nothing about where the material sits
in the catalogue: line numbers in its provenance count from the material's first line (a material
moved down the file keeps its key) and it names no lexicon folder (a folder added that changes no
entry the material uses keeps its key; the entries it uses are in its IR, values and sources).
"""

from __future__ import annotations

import copy
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..api import compile_source
from ..diagnostics import Diagnostic, render_all
from ..errors import UsageError
from ..inputs import DEFAULT_MAX_BYTES, read_text
from ..lexicon import Lexicon

SUFFIX = ".cnl"


@dataclass(frozen=True)
class Entry:
    """One material of the catalogue: where it is and what it compiles to."""

    file: str  # the catalogue file, relative to the catalogue's folder
    line: int
    name: str
    phrase: str
    folder: str  # its outputs' folder, relative to the output folder (one subfolder per target)
    document: dict[str, Any]


@dataclass(frozen=True)
class Problem:
    """A line of the catalogue that did not compile: its errors, rendered (file:line:col ...)."""

    file: str
    line: int
    text: str


@dataclass
class Catalog:
    files: list[str] = field(default_factory=list)
    entries: list[Entry] = field(default_factory=list)
    problems: list[Problem] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)


def catalog_files(path: Path) -> tuple[Path, list[Path]]:
    """(the catalogue's folder, its .cnl files in name order): one file, or every .cnl file under a folder."""
    if path.is_dir():
        files = sorted(p for p in path.rglob(f"*{SUFFIX}") if p.is_file() and not p.name.startswith("."))
        if not files:
            raise UsageError(f"catalogue folder '{path}' holds no {SUFFIX} file")
        return path, files
    if not path.exists():
        raise UsageError(f"catalogue '{path}' does not exist: give a .cnl file or a folder of them")
    return path.parent, [path]


def read_catalog(path: Path, lexicon: Lexicon, seed: int = 0, max_bytes: int = DEFAULT_MAX_BYTES) -> Catalog:
    root, files = catalog_files(path)
    nested = path.is_dir()
    catalog = Catalog()
    for file in files:
        relative = file.relative_to(root).as_posix()
        catalog.files.append(relative)
        source = read_text(str(file), limit=max_bytes, what="catalogue file")
        result = compile_source(source, relative, lexicon, seed, keep_stages=False)
        prefix = relative[: -len(SUFFIX)] + "/" if nested else ""
        catalog.entries += list(_entries(result.ir, relative, prefix))
        _add_diagnostics(catalog, result.diagnostics, source, relative)
    _refuse_shared_folders(catalog.entries)
    return catalog


def _entries(ir: dict[str, Any], file: str, prefix: str) -> Iterator[Entry]:
    head = {key: value for key, value in ir.items() if key not in ("materials", "diagnostics")}
    for material in ir["materials"]:
        first = first_line(material)
        document = {**head, "source": file, "lexicon": [], "materials": [relative_spans(material, first)]}
        document["diagnostics"] = []
        yield Entry(file, first, material["name"], material.get("phrase", ""), prefix + material["name"], document)


def _spans(material: dict[str, Any]) -> Iterator[list[int]]:
    for steps in (material.get("provenance") or {}).values():
        for step in steps:
            yield from step.get("spans", ())


def first_line(material: dict[str, Any]) -> int:
    """The material's first line: the earliest line its provenance points at (1 when none)."""
    return min((span[0] for span in _spans(material)), default=1)


def relative_spans(material: dict[str, Any], first: int) -> dict[str, Any]:
    """A copy of the material whose spans count lines from `first` (its line 1)."""
    moved = copy.deepcopy(material)
    for steps in (moved.get("provenance") or {}).values():
        for step in steps:  # new lists: one span list may be shared by several steps
            if "spans" in step:
                step["spans"] = [[span[0] - (first - 1), *span[1:]] for span in step["spans"]]
    return moved


def _add_diagnostics(catalog: Catalog, diags: list[Diagnostic], source: str, file: str) -> None:
    errors = [d for d in diags if d.is_error]
    by_line: dict[int, list[Diagnostic]] = {}
    for diag in errors:
        by_line.setdefault(diag.span.line if diag.span else 0, []).append(diag)
    for line, group in sorted(by_line.items()):
        catalog.problems.append(Problem(file, line, "\n".join(render_all(group, source, file))))
    catalog.warnings += list(render_all([d for d in diags if not d.is_error], source, file))


def _refuse_shared_folders(entries: list[Entry]) -> None:
    """Two materials may not share an output folder (the same name in one file is numbered by the compiler)."""
    seen: dict[str, Entry] = {}
    for entry in entries:
        other = seen.setdefault(entry.folder, entry)
        if other is not entry:
            raise UsageError(
                f"{entry.file}:{entry.line}: material '{entry.name}' would write into the folder of the one at "
                f"{other.file}:{other.line}: rename one of them"
            )
