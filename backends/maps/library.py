"""Finding and loading graph files: the stdlib graphs ship in cnlmc.stdlib/graphs/*.toml."""

from __future__ import annotations

import tomllib
from functools import cache
from importlib.resources import files
from pathlib import Path

from .errors import GraphSchemaError, MapError, did_you_mean
from .schema import check_graph
from .spec import Graph


def graph_dir():
    return files("cnlmc.stdlib") / "graphs"


def parse_graph(text: str, file: str, stem: str) -> Graph:
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise GraphSchemaError(f"{file}: not valid TOML: {error}") from None
    return check_graph(raw, file, stem)


def load_graph_file(path) -> Graph:
    """Load and check a graph from any path (for user graphs and tests)."""
    path = Path(path)
    return parse_graph(path.read_text(encoding="utf-8"), str(path), path.stem)


def graph_names() -> list[str]:
    """Names of the stdlib graphs, sorted."""
    return sorted(entry.name[:-5] for entry in graph_dir().iterdir() if entry.name.endswith(".toml"))


@cache
def load_graph(name: str) -> Graph:
    """A stdlib graph by name; unknown names suggest the closest one."""
    names = graph_names()
    if name not in names:
        raise MapError(f"unknown map graph '{name}'{did_you_mean(name, names)}; known graphs: {', '.join(names)}")
    entry = graph_dir() / f"{name}.toml"
    return parse_graph(entry.read_text(encoding="utf-8"), f"stdlib/graphs/{name}.toml", name)


def metres_per_unit(name: str) -> float | None:
    """Metres one texture unit of a stdlib graph's maps spans (its `[scale]` table; None when it
    states none): what an exporter's texture transform divides UVs in metres by."""
    scale = load_graph(name).scale
    return None if scale is None else scale.metres_per_unit
