"""Baking the IR `maps` dict: role -> {"graph", "output", "params", "seed"} -> arrays."""

from __future__ import annotations

import json
from collections.abc import Callable
from numbers import Integral

import numpy as np

from .blas import single_threaded_blas
from .errors import MapError
from .evaluate import Evaluation, nodes_needed, resolve_inputs, resolve_params
from .grid import Grid, derive_seed
from .library import load_graph

MIN_SIZE, MAX_SIZE = 8, 8192
OnProgress = Callable[[int, int, str], None]


def validate_size(size) -> int:
    """Accept a power of two in [8, 8192]; raise MapError saying what would work."""
    if isinstance(size, bool) or not isinstance(size, Integral):
        raise MapError(f"map size must be a whole number of pixels such as 512 or 1024, got {size!r}")
    size = int(size)
    if size < MIN_SIZE or size > MAX_SIZE:
        raise MapError(f"map size {size} is out of range: use a power of two from {MIN_SIZE} to {MAX_SIZE}")
    if size & (size - 1):
        lower = 1 << (size.bit_length() - 1)
        raise MapError(f"map size {size} is not a power of two: use {lower} or {lower * 2}")
    return size


def group_key(ref: dict) -> tuple:
    params = json.dumps(ref.get("params") or {}, sort_keys=True)
    return ref["graph"], params, int(ref.get("seed", 0) or 0)


def check_ref(role: str, ref) -> None:
    if not isinstance(ref, dict) or "graph" not in ref:
        raise MapError(f"maps.{role}: expected {{'graph': ..., 'output': ...}}, got {ref!r}")
    unknown = set(ref) - {"graph", "output", "params", "seed"}
    if unknown:
        raise MapError(f"maps.{role}: unknown keys {sorted(unknown)}")


def group_refs(map_refs: dict) -> dict[tuple, dict[str, str]]:
    """Roles sharing graph, params and seed -> one evaluation: key -> {role: output}."""
    groups: dict[tuple, dict[str, str]] = {}
    for role, ref in map_refs.items():
        check_ref(role, ref)
        groups.setdefault(group_key(ref), {})[role] = ref.get("output", role)
    return groups


def start_evaluation(key: tuple, material: dict | None, size: int, seed: int, on_node) -> Evaluation:
    name, params, ref_seed = key
    graph = load_graph(name)
    grid = Grid(size, derive_seed(seed, ref_seed, name))
    return Evaluation(graph, grid, resolve_params(graph, json.loads(params)), resolve_inputs(graph, material), on_node)


def bake(
    map_refs: dict,
    material_params: dict | None = None,
    size: int = 1024,
    seed: int = 0,
    on_progress: OnProgress | None = None,
) -> dict[str, np.ndarray]:
    """Evaluate every map reference; each graph (with its params and seed) runs once.

    Returns role -> float32 array: colour roles (H, W, 3) linear RGB, `normal` (H, W, 3)
    unit vectors (OpenGL tangent space), other roles (H, W) in [0, 1].
    """
    size = validate_size(size)
    groups = group_refs(map_refs or {})
    graphs = {key: load_graph(key[0]) for key in groups}
    total = sum(len(nodes_needed(graphs[k], roles.values())) for k, roles in groups.items())
    done = [0]

    def on_node(graph_name):
        def report(node):
            done[0] += 1
            if on_progress:
                on_progress(done[0], total, f"{graph_name}/{node}")

        return report

    arrays = {}
    with single_threaded_blas():
        for key, roles in groups.items():
            evaluation = start_evaluation(key, material_params, size, seed, on_node(key[0]))
            arrays.update({role: evaluation.output(output) for role, output in roles.items()})
    return arrays
