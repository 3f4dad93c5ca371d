"""Graph data model: what a graph TOML file becomes after the schema check."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

OUTPUT_ROLES = ("color", "normal", "roughness", "metallic", "mask", "height")


@dataclass(frozen=True)
class Ref:
    """A reference from a node input to another node, a graph parameter or a material input.
    Parameter and input values are used as value * mul + add."""

    source: str  # "node" | "param" | "input"
    name: str
    mul: float = 1.0
    add: float = 0.0


@dataclass(frozen=True)
class GraphParam:
    default: float
    low: float
    high: float
    doc: str


@dataclass(frozen=True)
class GraphInput:
    default: Any  # a number or an RGB triple
    doc: str


@dataclass(frozen=True)
class NodeSpec:
    type: str
    args: dict[str, Any]


@dataclass(frozen=True)
class GraphScale:
    """The graph's real size (the `[scale]` table): one texture unit spans `metres_per_unit` metres,
    and its features repeat every `feature` metres (what `what` names; measured on `measure`, along
    `axis`: "u", "v" or "any"), as `source` says."""

    metres_per_unit: float
    feature: float
    what: str
    measure: str
    axis: str
    source: str


@dataclass
class Graph:
    name: str
    doc: str
    file: str
    params: dict[str, GraphParam] = field(default_factory=dict)
    inputs: dict[str, GraphInput] = field(default_factory=dict)
    nodes: dict[str, NodeSpec] = field(default_factory=dict)
    outputs: dict[str, str] = field(default_factory=dict)
    presets: dict[str, dict[str, float]] = field(default_factory=dict)
    scale: GraphScale | None = None
