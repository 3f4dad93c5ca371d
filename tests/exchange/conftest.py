"""Fixtures for the exchange backends: IR for every stdlib noun and a set of phrases.

Maps whose graph the maps library cannot bake yet are stripped (the backends are tested
map-free for those); everything bakes at 16x16 so the folder runs quickly.
"""

from __future__ import annotations

import copy
import functools
import math

import pytest

from cnlmc.api import compile_source, lexicon_for
from tests.helpers import require

PHRASES = [
    "white varnished oak",
    "lightly brushed, blue anodized aluminum",
    "clear-coated red car paint",
    "frosted glass",
    "red or green glass",
    "rusty iron",
    "polished gold",
    "deep red velvet",
    "brushed steel",
    "lacquered maple",
    "glazed terracotta",
    "hammered copper",
    "tinted glass",
    "varnished brass",
    "rough stone",
    "blue or red or green plastic",
    "satin nickel",
    "wet asphalt",
]
FAST = {"map_size": "16"}


@functools.lru_cache(maxsize=1)
def bakeable_graphs() -> frozenset:
    try:
        from cnlmc.backends.maps import graph_names
    except ImportError:
        return frozenset()
    return frozenset(graph_names())


def bakeable(ir: dict) -> dict:
    """A copy of the IR without map references the maps library cannot bake yet."""
    ir = copy.deepcopy(ir)
    graphs = bakeable_graphs()
    for material in ir["materials"]:
        material["maps"] = {r: ref for r, ref in material["maps"].items() if ref["graph"] in graphs}
    return ir


@functools.cache
def _compiled(source: str) -> dict:
    result = compile_source(source + "\n")
    assert result.ok, [d.message for d in result.diagnostics]
    return result.ir


def ir_of(source: str) -> dict:
    return bakeable(_compiled(source))


def nouns() -> list[str]:
    return sorted(lexicon_for().all_of("nouns"))


def synthetic_materials() -> list[dict]:
    """One material per model kind x feature the stdlib phrases may not reach."""
    plastic = ir_of("glossy red plastic")["materials"][0]
    gold = ir_of("polished gold")["materials"][0]
    glass = ir_of("frosted glass")["materials"][0]
    out = []

    def variant(base, name, **changes):
        m = copy.deepcopy(base)
        m["name"] = name
        for path, value in changes.items():
            target = m
            keys = path.split("__")
            for k in keys[:-1]:
                target = target[k]
            target[keys[-1]] = value
        out.append(m)

    variant(
        plastic,
        "aniso_plastic",
        model__anisotropic=True,
        model__distribution="ward",
        params__anisotropy=0.6,
        params__anisotropy_rotation=math.pi / 4,
        params__alpha=[0.08, 0.03],
    )
    variant(
        gold,
        "coated_tinted_gold",
        model__coat=True,
        params__coat={"ior": 1.5, "roughness": 0.2, "alpha": [0.04, 0.04], "color": [0.9, 0.5, 0.2], "thickness": 2.0},
    )
    variant(
        glass,
        "aniso_glass",
        model__anisotropic=True,
        params__anisotropy=0.5,
        params__anisotropy_rotation=0.3,
        params__alpha=[0.09, 0.02],
        params__roughness=0.2,
    )
    variant(plastic, "linear_plastic", params__alpha_convention="linear", params__alpha=[0.3, 0.3])
    return out


def synthetic_ir() -> dict:
    ir = copy.deepcopy(ir_of("glossy red plastic"))
    ir["materials"] = synthetic_materials()
    return ir


def all_sources() -> list[str]:
    return nouns() + PHRASES


@pytest.fixture(scope="session")
def mx_library():
    require("MaterialX", "materialx")
    from cnlmc.backends.exchange.materialx import TARGET

    return TARGET.library


def write_artifacts(artifacts, folder) -> None:
    """Write artifacts as the CLI would (text as UTF-8), so relative texture paths resolve."""
    from pathlib import Path

    for artifact in artifacts:
        path = Path(folder) / artifact.name
        path.parent.mkdir(parents=True, exist_ok=True)
        data = artifact.content if isinstance(artifact.content, bytes) else artifact.content.encode("utf-8")
        path.write_bytes(data)
