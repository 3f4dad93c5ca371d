"""Evaluating a checked graph on a grid: parameters, material inputs, nodes on demand."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from .blas import single_threaded_blas
from .errors import MapError, did_you_mean
from .grid import Grid, derive_seed
from .registry import NODE_TYPES
from .roles import finish
from .schema import node_refs
from .spec import Graph, Ref

Progress = Callable[[str], None]


def resolve_params(graph: Graph, given: dict) -> dict[str, float]:
    """Graph defaults, then a `preset` (if given), then explicit values; all range-checked."""
    given = dict(given or {})
    values = {name: p.default for name, p in graph.params.items()}
    preset = given.pop("preset", None)
    if preset is not None:
        if preset not in graph.presets:
            raise MapError(f"graph '{graph.name}' has no preset '{preset}'{did_you_mean(str(preset), graph.presets)}")
        values.update(graph.presets[preset])
    for name, value in given.items():
        values[name] = checked_param(graph, name, value)
    return values


def checked_param(graph: Graph, name: str, value) -> float:
    if name not in graph.params:
        known = ", ".join(graph.params) or "none"
        raise MapError(
            f"graph '{graph.name}' has no parameter '{name}'{did_you_mean(name, graph.params)}; parameters: {known}"
        )
    spec = graph.params[name]
    if not spec.low <= float(value) <= spec.high:
        raise MapError(f"graph '{graph.name}': {name} = {value} is outside [{spec.low}, {spec.high}]")
    return float(value)


def resolve_inputs(graph: Graph, material: dict | None) -> dict[str, np.ndarray]:
    """Material values (e.g. base_color) for the inputs the graph declares, else defaults."""
    material = material or {}
    return {name: np.asarray(material.get(name, spec.default), np.float32) for name, spec in graph.inputs.items()}


class Evaluation:
    """Evaluates nodes on demand, each at most once."""

    def __init__(self, graph: Graph, grid: Grid, params: dict, inputs: dict, on_node: Progress | None = None):
        self.graph, self.grid, self.params, self.inputs = graph, grid, params, inputs
        self.cache: dict[str, np.ndarray] = {}
        self.on_node = on_node

    def value(self, arg, kind: str):
        if isinstance(arg, list):
            return [self.value(item, "color") for item in arg]
        if not isinstance(arg, Ref):
            return arg
        if arg.source == "node":
            return self.node(arg.name)
        base = self.params[arg.name] if arg.source == "param" else self.inputs[arg.name]
        scaled = np.asarray(base, np.float32) * np.float32(arg.mul) + np.float32(arg.add)
        return int(round(float(scaled))) if kind == "int" else (float(scaled) if scaled.ndim == 0 else scaled)

    def node(self, name: str) -> np.ndarray:
        if name not in self.cache:
            spec = self.graph.nodes[name]
            node_type = NODE_TYPES[spec.type]
            kwargs = {arg: self.value(v, node_type.inputs[arg].kind) for arg, v in spec.args.items()}
            self.cache[name] = node_type.function(self.grid.with_seed(name), **kwargs)
            if self.on_node:
                self.on_node(name)
        return self.cache[name]

    def output(self, role: str) -> np.ndarray:
        if role not in self.graph.outputs:
            outputs = ", ".join(self.graph.outputs)
            raise MapError(
                f"graph '{self.graph.name}' has no output '{role}'{did_you_mean(role, self.graph.outputs)}; outputs: {outputs}"
            )
        node = self.graph.outputs[role]
        return finish(role, self.node(node), self.grid.size, f"{self.graph.name}.{role}")


def nodes_needed(graph: Graph, roles) -> list[str]:
    """Nodes the given outputs depend on (for progress totals)."""
    seen: list[str] = []
    stack = [graph.outputs[r] for r in roles if r in graph.outputs]
    while stack:
        name = stack.pop()
        if name not in seen:
            seen.append(name)
            stack.extend(dep for arg in graph.nodes[name].args.values() for dep in node_refs(arg))
    return seen


def evaluate(
    graph: Graph,
    size: int,
    seed: int = 0,
    params: dict | None = None,
    material: dict | None = None,
    outputs=None,
    on_node: Progress | None = None,
) -> dict[str, np.ndarray]:
    """All (or the named) outputs of one graph, each finished for its role."""
    evaluation = Evaluation(
        graph,
        Grid(size, derive_seed(seed, graph.name)),
        resolve_params(graph, params or {}),
        resolve_inputs(graph, material),
        on_node,
    )
    with single_threaded_blas():
        return {role: evaluation.output(role) for role in (outputs or graph.outputs)}
