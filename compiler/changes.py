"""What a refinement changed: the rows a session prints after each line ('  roughness  0.3 -> 0.4').

Parameters, the coat's parameters and every procedural map's parameters are compared in their IR
form, so "more grain" (a map parameter) or "glossier" on a varnished wood (the coat's roughness)
is reported as the change it is, never as "no parameter changed".
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .graphs import graph_params

JSONDict = Mapping[str, Any]


def material_changes(before: JSONDict, after: JSONDict) -> list[str]:
    """'  name  old -> new' for every parameter, coat parameter, map and map parameter that differs."""
    old, new = before.get("params", {}), after.get("params", {})
    rows = _rows("", _flat_params(old), _flat_params(new))
    rows += _rows("maps.", _flat_maps(before.get("maps") or {}), _flat_maps(after.get("maps") or {}))
    if before.get("model") != after.get("model"):
        rows.append(f"  {'model':18s} {_model(before)} -> {_model(after)}")
    return rows


def _flat_params(params: JSONDict) -> dict[str, Any]:
    """The parameters, the coat's as 'coat.<name>' (the coat's name as 'coat')."""
    out: dict[str, Any] = {}
    for key, value in params.items():
        if key == "coat" and isinstance(value, Mapping):
            out["coat"] = value.get("name")
            out.update({f"coat.{k}": v for k, v in value.items() if k != "name"})
        else:
            out[key] = value
    return out


def _flat_maps(maps: JSONDict) -> dict[str, Any]:
    """Each map as '<role>' (its graph) and its parameters as '<role>.<param>', a parameter the
    map does not set at its graph's default (so 'higher contrast' reads 1 -> 1.5)."""
    out: dict[str, Any] = {}
    for role, ref in maps.items():
        graph = ref.get("graph")
        out[role] = graph
        params = {k: spec[2] for k, spec in graph_params(graph).items()} if isinstance(graph, str) else {}
        params.update(ref.get("params") or {})
        out.update({f"{role}.{k}": v for k, v in params.items()})
    return out


def _rows(prefix: str, old: dict[str, Any], new: dict[str, Any]) -> list[str]:
    rows = []
    for key in dict.fromkeys([*old, *new]):
        a = fmt(old[key]) if key in old else "(none)"
        b = fmt(new[key]) if key in new else "(none)"
        if a != b:
            rows.append(f"  {prefix + key:18s} {a} -> {b}")
    return rows


def _model(material: JSONDict) -> str:
    m = material["model"]
    return ", ".join(str(v) if not isinstance(v, bool) else k for k, v in m.items() if v)


def fmt(value: Any) -> str:
    """A value as the session prints it: 4 significant digits, lists in parentheses."""
    if isinstance(value, float):
        return f"{value:.4g}"
    if isinstance(value, (list, tuple)):
        return "(" + ", ".join(fmt(v) for v in value) + ")"
    if isinstance(value, Mapping):
        return "{" + ", ".join(f"{k}: {fmt(v)}" for k, v in value.items()) + "}"
    return str(value)
