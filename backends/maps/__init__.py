"""Procedural maps: node graphs described as data, the stdlib graphs, baking and writing.

bake(map_refs, material_params, size, seed, on_progress=None) -> {role: ndarray}
write_maps(arrays, out_dir, fmt="png8", stem="material") -> [Path]
validate_size(size) -> size, raising MapError
render_contact_sheet(path, size=256) -> Path (matplotlib, imported when it runs)
metres_per_unit(graph) -> metres one texture unit spans (the graph's [scale]; docs/maps.md "Real size")
dominant_period(array, axis) in feature_size: a baked map's feature size, in texture units
The baking service for targets (one error type, MapBakeError): bake_arrays, bake_files, bake_artifacts.
"""

from .bake import bake, validate_size
from .errors import GraphSchemaError, MapError
from .evaluate import evaluate
from .library import graph_names, load_graph, load_graph_file, metres_per_unit
from .registry import NODE_TYPES
from .service import MapBakeError, bake_arrays, bake_artifacts, bake_files
from .sheet import render_contact_sheet
from .writer import write_maps

__all__ = [
    "bake",
    "write_maps",
    "validate_size",
    "evaluate",
    "graph_names",
    "load_graph",
    "load_graph_file",
    "metres_per_unit",
    "MapError",
    "GraphSchemaError",
    "NODE_TYPES",
    "render_contact_sheet",
    "MapBakeError",
    "bake_arrays",
    "bake_artifacts",
    "bake_files",
]
