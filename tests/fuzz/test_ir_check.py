"""The IR writer's fast check (cnlmc.ir_check) accepts exactly what Material.from_ir accepts (#13).

Real materials (every model kind, a coat, anisotropy, maps, a variant, a label) are mutated at a
every place in their JSON tree: a value replaced by one of a wrong type, out of range, NaN or
infinite, a key removed or one the table lacks added. Both checks must agree: both accept, or
both refuse with the same message (the fast check hands anything it is not sure of to from_ir).
"""

from __future__ import annotations

import copy
import math
from types import MappingProxyType
from typing import Any

import pytest

from cnlmc.api import compile_source, lexicon_for
from cnlmc.ir_check import check_material
from cnlmc.material import Material

PHRASES = (
    "hull: lightly brushed, blue anodized aluminum",
    "名前 ünïcødé: oak with a glossy white varnish",
    "clear glass",
    "rough concrete",
    "red or blue plastic",
    "gold",
    "polished copper with a clear coat",
    "black velvet",
    "jade",  # a medium under the boundary (model.subsurface "volume", params.subsurface)
    "green leaf",  # a thin sheet (model.subsurface "thin", the medium's thickness)
)

MAP_REF = {"graph": "wood", "output": "color", "params": {"grain": 0.5}, "seed": 3}  # valid under a map role
REPLACEMENTS: tuple[Any, ...] = (
    None,
    math.nan,
    math.inf,
    -math.inf,
    -1.0,
    0.5,
    2,
    1e9,
    10**400,
    True,
    False,
    "x",
    "",
    [],
    [0.5, 0.5],
    [0.5, 0.5, 0.5],
    [0.5, math.nan, 0.5],
    (0.5, 0.5, 0.5),
    {},
    {"x": 1},
    MappingProxyType({"graph": "wood", "output": "color"}),
    MAP_REF,
    "squared",
    "ggx",
    "oren_nayar",
    "conductor",
    "base_color",
    "volume",
    "thin",
)


@pytest.fixture(scope="module")
def materials() -> list[dict[str, Any]]:
    lexicon = lexicon_for()
    found = [m for phrase in PHRASES for m in compile_source(phrase, "<ir_check>", lexicon).materials]
    assert {m["model"]["base"] for m in found} == {"conductor", "dielectric", "glass", "diffuse"}
    assert any(m["params"].get("coat") for m in found) and any(m["maps"] for m in found)
    assert any(m["variant"] for m in found) and any("label" in m for m in found)
    assert {m["model"].get("subsurface") for m in found} == {None, "volume", "thin"}
    return [copy.deepcopy(dict(m)) for m in found]


def places(value: Any, path: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """Every path into the JSON tree (dict keys and list indices), but not inside a provenance step
    (neither check reads a step's fields): the places a check can get wrong are then drawn often."""
    out = [path]
    if len(path) == 3 and path[0] == "provenance":
        return out
    if isinstance(value, dict):
        for key, item in value.items():
            out += places(item, (*path, key))
    elif isinstance(value, list):
        for i, item in enumerate(value):
            out += places(item, (*path, i))
    return out


def outcome(check: Any, material: Any) -> str:
    try:
        check(material, "materials[3]")
    except ValueError as exc:
        return f"refused: {exc}"
    return "accepted"


def mutated(material: dict[str, Any], path: tuple[Any, ...], how: str, replacement: Any) -> Any:
    """`material` with one change at `path`; the containers on the path are copied, the rest shared."""
    if not path:
        return replacement
    out = parent = dict(material)
    for key in path[:-1]:
        child = parent[key]
        parent[key] = child = dict(child) if isinstance(child, dict) else list(child)
        parent = child
    last = path[-1]
    if how == "replace":
        parent[last] = replacement
    elif how == "remove":
        del parent[last]
    elif isinstance(parent[last], dict):
        parent[last] = {**parent[last], "unknown_key": replacement}
    elif isinstance(parent[last], list):
        parent[last] = [*parent[last], replacement]
    return out


def test_every_real_material_is_accepted(materials: list[dict[str, Any]]) -> None:
    for material in materials:
        assert outcome(check_material, material) == "accepted" == outcome(Material.from_ir, material)


def test_fast_check_agrees_with_from_ir_on_every_mutation(materials: list[dict[str, Any]]) -> None:
    """Every place of every material: each replacement, the key removed, an item or key added."""
    cases = disagreements = 0
    for material in materials:
        for path in places(material):
            changes = [("replace", r) for r in REPLACEMENTS] + [("remove", None)] * bool(path)
            changes += [("add", r) for r in (*REPLACEMENTS[:8], MAP_REF)]
            for how, replacement in changes:
                candidate = mutated(material, path, how, replacement)
                fast, slow = outcome(check_material, candidate), outcome(Material.from_ir, candidate)
                cases += 1
                if fast != slow:
                    disagreements += 1
                    assert fast == slow, (path, how, replacement)
    assert cases > 10_000 and disagreements == 0
