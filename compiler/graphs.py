"""What the compiler needs to know of procedural graphs: their names, outputs, parameters and ranges.

Read from the graph data files (stdlib/graphs/NAME.toml); evaluating graphs is the maps
backend's job, not the compiler's. Only the bundled graphs exist: a name that is not one of
them (say '../x') is never turned into a path.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache
from types import MappingProxyType
from typing import Any

from .material import freeze_json
from .package_data import package_folder


@cache
def graph_names() -> frozenset[str]:
    """The names of the bundled graphs (read once per process from package data)."""
    folder = package_folder("cnlmc.stdlib") / "graphs"
    if not folder.is_dir():
        return frozenset()
    return frozenset(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".toml"))


@cache
def _graph_table(name: str) -> Mapping[str, Any]:
    """A graph's table, read-only all the way down (it is shared by every caller in the process)."""
    frozen: Mapping[str, Any] = freeze_json(_graph_tables().get(name, {}))
    return frozen


@cache
def _graph_tables() -> Mapping[str, dict[str, Any]]:
    """Every bundled graph's table, read once per process; kept in the disk cache as plain JSON
    (cnlmc.cache, keyed by the graph files), so a cold start does not import tomllib (#14 speed)."""
    from .cache import cached, dump_json, load_json

    folder = package_folder("cnlmc.stdlib") / "graphs"
    paths = [folder / f"{name}.toml" for name in sorted(graph_names())]

    def build() -> dict[str, dict[str, Any]]:
        import tomllib

        return {path.name[:-5]: tomllib.loads(path.read_text("utf-8")) for path in paths}

    def load(payload: bytes) -> dict[str, dict[str, Any]]:
        tables = load_json(payload)
        if not isinstance(tables, dict) or set(tables) != graph_names():
            raise ValueError("not the bundled graphs")
        if not all(isinstance(table, dict) for table in tables.values()):
            raise TypeError("a graph's table is not a table")
        return tables

    return MappingProxyType(cached("graphs", [folder, *paths], build, dump_json, load))


@cache
def graph_params(name: str) -> Mapping[str, tuple[float, float, float]]:
    """param -> (low, high, default) for a stdlib graph; empty when the graph is unknown.
    Read once per process from package data (immutable), and handed out read-only."""
    table = _graph_table(name).get("params", {})
    return MappingProxyType(
        {
            k: (float(v["range"][0]), float(v["range"][1]), float(v.get("default", 1.0)))
            for k, v in table.items()
            if "range" in v
        }
    )


@cache
def graph_outputs(name: str) -> tuple[str, ...]:
    """The output names of a stdlib graph ('color', 'normal', ...); empty when the graph is unknown."""
    return tuple(_graph_table(name).get("outputs", {}))


@cache
def all_graph_params() -> frozenset[str]:
    """Every parameter name some bundled graph has (what a property's map_param may name)."""
    return frozenset(p for name in graph_names() for p in graph_params(name))


@cache
def graph_palette(name: str) -> Mapping[str, Any]:
    """A stdlib graph's `[palette]` table (what a colour word does to its colours: chroma cap,
    lightness range, parameters a dark colour sets; docs/maps.md); empty when it has none."""
    palette: Mapping[str, Any] = _graph_table(name).get("palette", MappingProxyType({}))
    return palette
