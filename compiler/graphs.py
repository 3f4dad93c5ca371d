"""What the compiler needs to know of procedural graphs: their parameters' names and ranges.

Read from the graph data files (stdlib/graphs/NAME.toml); evaluating graphs is the maps
backend's job, not the compiler's.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache
from importlib import resources
from types import MappingProxyType


@cache
def graph_params(name: str) -> Mapping[str, tuple[float, float, float]]:
    """param -> (low, high, default) for a stdlib graph; empty when the graph is unknown.
    Read once per process from package data (immutable), and handed out read-only."""
    import tomllib

    path = resources.files("cnlmc.stdlib").joinpath("graphs").joinpath(f"{name}.toml")
    if not path.is_file():
        return MappingProxyType({})
    table = tomllib.loads(path.read_text("utf-8")).get("params", {})
    return MappingProxyType(
        {
            k: (float(v["range"][0]), float(v["range"][1]), float(v.get("default", 1.0)))
            for k, v in table.items()
            if "range" in v
        }
    )
