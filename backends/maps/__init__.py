"""Procedural maps: node graphs described as data, the stdlib graphs, baking and writing.

bake(map_refs, material_params, size, seed, on_progress=None) -> {role: ndarray}
write_maps(arrays, out_dir, fmt="png8", stem="material") -> [Path]
validate_size(size) -> size, raising MapError
"""

from .bake import bake, validate_size
from .errors import GraphSchemaError, MapError
from .evaluate import evaluate
from .library import graph_names, load_graph, load_graph_file
from .registry import NODE_TYPES
from .writer import write_maps

__all__ = [
    "bake",
    "write_maps",
    "validate_size",
    "evaluate",
    "graph_names",
    "load_graph",
    "load_graph_file",
    "MapError",
    "GraphSchemaError",
    "NODE_TYPES",
    "render_contact_sheet",
]


def render_contact_sheet(path, size: int = 256):
    """See sheet.render_contact_sheet (imported lazily: it needs matplotlib)."""
    from .sheet import render_contact_sheet as render

    return render(path, size)
