"""What the compiler needs to know of procedural graphs: their parameters' names and ranges.

Read from the graph data files (stdlib/graphs/NAME.toml); evaluating graphs is the maps
backend's job, not the compiler's.
"""

from __future__ import annotations

from functools import cache
from importlib import resources


@cache
def graph_params(name: str) -> dict[str, tuple[float, float, float]]:
    """param -> (low, high, default) for a stdlib graph; {} when the graph is unknown."""
    import tomllib

    path = resources.files("cnlmc.stdlib").joinpath("graphs").joinpath(f"{name}.toml")
    if not path.is_file():
        return {}
    table = tomllib.loads(path.read_text("utf-8")).get("params", {})
    return {
        k: (float(v["range"][0]), float(v["range"][1]), float(v.get("default", 1.0)))
        for k, v in table.items()
        if "range" in v
    }
