"""Light inside the body (docs/subsurface.md): the medium a noun or a describing word asks for.

`apply_subsurface` (a build pass, after the describing words) starts from the noun's medium
(`subsurface*` fields of its lexicon entry) and lets the words with a `subsurface` table
(translucent, milky, thin, backlit) change it; `select_subsurface` (after select_model) writes
`model.subsurface` and moves a matte diffuse host to the dielectric model (the medium needs a boundary
with an IOR). A conductor lets no light in (W150); glass keeps its own transmission (N150).
"""

from __future__ import annotations

from typing import Any

from .. import ast
from ..diagnostics import Diagnostic, Severity, warning
from ..lexicon import Entry
from ..state import Context, MaterialState
from .base import noun_of, noun_word

Medium = dict[str, Any]
NO_LIGHT_IN = "W150"  # a word asks for light inside a body that lets none in (a metal)
OWN_TRANSMISSION = "N150"  # a word asks for a medium in glass, which transmits already


def noun_medium(noun: Entry) -> Medium | None:
    """The medium a noun's lexicon entry declares, or None."""
    data = noun.data
    if not data.get("subsurface"):
        return None
    thin = data["subsurface"] == "thin"
    return {
        "model": data["subsurface"],
        "color": list(data.get("subsurface_color", data["base_color"])),
        "radius": list(data["subsurface_radius"]),
        "anisotropy": float(data.get("subsurface_anisotropy", 0.0)),
        "thickness": float(data.get("subsurface_thickness", 0.0005)) if thin else None,
    }


def apply_subsurface(state: MaterialState, ctx: Context) -> MaterialState:
    noun = noun_of(state)
    medium = noun_medium(noun)
    if medium is not None:
        state.record("subsurface", dict(medium), f"nouns.{noun.key}", (noun_word(state),), noun.data.get("source"))
    for key, word in state.applied:
        table = _subsurface_table(ctx, key)
        if table:
            _apply_word(state, key, table, word)
    return state


def _subsurface_table(ctx: Context, key: str) -> dict[str, Any] | None:
    """The adjective's `subsurface` table, or None; read once per lexicon and key
    (LexiconCaches.subsurface_tables): most applied words have none."""
    tables = ctx.lexicon.caches.subsurface_tables
    if key not in tables:
        tables[key] = ctx.lexicon.require("adjectives", key).get("subsurface")
    return tables[key]


def _apply_word(state: MaterialState, key: str, table: dict[str, Any], word: ast.Word) -> None:
    if state.kind in ("conductor", "glass"):
        if state.kind == "conductor":
            state.diagnostics.append(_no_light_in(state, word))
        return
    current = state.params.get("subsurface")
    medium = _changed(current, table, state) if isinstance(current, dict) else _new(table, state)
    state.record("subsurface", medium, f"adjectives.{key}.subsurface", (word,))


def _changed(current: Medium, table: dict[str, Any], state: MaterialState) -> Medium:
    """A medium the noun has, changed by the word: its radius scaled; 'thin' makes a volume a sheet."""
    medium = dict(current)
    medium["radius"] = [r * float(table.get("radius_scale", 1.0)) for r in current["radius"]]
    if table["model"] == "thin" and current["model"] == "volume" and not _keeps_volume(table):
        medium["model"], medium["thickness"] = "thin", float(table.get("thickness", 0.0005))
    return medium


def _keeps_volume(table: dict[str, Any]) -> bool:
    """'backlit' on a thick body keeps it thick: it names the light, not the shape (docs/subsurface.md)."""
    return bool(table.get("keeps_volume", False))


def _new(table: dict[str, Any], state: MaterialState) -> Medium:
    """A medium for a noun that has none (translucent plastic): its colour is the surface colour."""
    thin = table["model"] == "thin"
    return {
        "model": table["model"],
        "color": list(state.params.get("base_color", [0.8, 0.8, 0.8])),
        "radius": list(table["radius"]),
        "anisotropy": 0.0,
        "thickness": float(table.get("thickness", 0.0005)) if thin else None,
    }


def _no_light_in(state: MaterialState, word: ast.Word) -> Diagnostic:
    return warning(
        word.span,
        NO_LIGHT_IN,
        f"'{word.text}' asks for light inside the body, but {noun_of(state).key} is a metal and lets none in",
        ("drop the word, or name a translucent material (wax, jade, skin, milk, marble)",),
    )


def select_subsurface(state: MaterialState, ctx: Context) -> MaterialState:
    """model.subsurface from the medium; a medium needs a dielectric boundary (a diffuse host becomes one)."""
    medium = state.params.get("subsurface")
    model = state.model
    assert model is not None, "select_model runs first"
    if not isinstance(medium, dict):
        return state
    if model["base"] not in ("diffuse", "dielectric"):
        del state.params["subsurface"]
        state.diagnostics.append(_own_transmission(state))
        return state
    if model["base"] == "diffuse":
        model.update(base="dielectric", distribution="ggx")
        state.params.setdefault("ior", 1.5)
    model["subsurface"] = medium["model"]
    medium["color"] = tinted_medium(medium["color"], _noun_base(state), state.params["base_color"])
    return state


def _noun_base(state: MaterialState) -> list[float]:
    steps = state.provenance.get("base_color", [])
    return list(steps[0].value) if steps else list(state.params["base_color"])


def tinted_medium(medium: list[float], noun_base: list[float], base: list[float]) -> list[float]:
    """The medium's albedo after colour words: scaled per channel as the surface colour was ('white wax',
    'darker jade'; our choice: the body takes the colour the surface shows), at most 1."""
    return [min(1.0, m * (b / n if n > 1e-6 else 1.0)) for m, n, b in zip(medium, noun_base, base, strict=True)]


def _own_transmission(state: MaterialState) -> Diagnostic:
    message = f"{noun_of(state).key} transmits light already: no medium added"
    return Diagnostic(state.selection.span, Severity.NOTE, OWN_TRANSMISSION, message, ())


def refine_translucency(
    state: MaterialState, adjective: Entry, item: ast.RefineItem, direction: int, weight: float
) -> None:
    """'more translucent' / 'less milky': the medium's mean free path times the word's radius_scale
    (at least 1.5) per step, up or down; 'more translucent' on a body without one gives it one."""
    table: dict[str, Any] = adjective.get("subsurface")
    words = (item.word, item.target) if isinstance(item.target, ast.Word) else (item.word,)
    current = state.params.get("subsurface")
    if not isinstance(current, dict):
        if direction > 0 and state.kind not in ("conductor", "glass"):
            state.record("subsurface", _new(table, state), f"refinements.{item.word.key} {adjective.key}", words)
        elif state.kind == "conductor" and isinstance(item.target, ast.Word):
            state.diagnostics.append(_no_light_in(state, item.target))
        return
    factor = max(float(table.get("radius_scale", 1.0)), 1.5) ** (direction * weight)
    medium = dict(current)
    medium["radius"] = [r * factor for r in current["radius"]]
    state.record("subsurface", medium, f"refinements.{item.word.key} {adjective.key}: radius x{factor:.3g}", words)
