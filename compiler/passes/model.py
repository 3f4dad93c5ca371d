"""Select the simplest model that expresses the result ("model no more than a scene needs")."""

from __future__ import annotations

from typing import Any

from ..diagnostics import warning
from ..params import Params
from ..state import Context, MaterialState
from .base import noun_of

Settings = dict[str, Any]


def select_model(state: MaterialState, ctx: Context) -> MaterialState:
    settings = ctx.lexicon.settings  # ctx.settings, without the property's call
    base = _base_model(state, settings)
    anisotropic = base != "diffuse" and state.params.get("anisotropy", 0.0) > 0
    if base == "diffuse" and state.params.get("anisotropy", 0.0) > 0:
        _warn_no_highlight(state)
    if base == "glass":  # the depth its colour is seen through: the noun's, else the table's default
        state.params.setdefault("transmission_depth", Params.transmission_depth)
    state.model = {
        "base": base,
        "distribution": _distribution(base, anisotropic, settings),
        "anisotropic": anisotropic,
        "coat": state.coat is not None,
        "diffuse": _diffuse_lobe(state, base, settings),
    }
    return state


def _base_model(state: MaterialState, settings: Settings) -> str:
    if state.kind in ("conductor", "glass"):
        return state.kind
    rough = state.params.get("roughness", 1.0)
    if rough >= settings.get("diffuse_threshold", 0.85) and state.coat is None:
        return "diffuse"
    return "dielectric"


def _distribution(base: str, anisotropic: bool, settings: Settings) -> str | None:
    if base == "diffuse":
        return None
    if anisotropic:
        return str(settings.get("anisotropic_distribution", "ward"))
    return "ggx"


def _diffuse_lobe(state: MaterialState, base: str, settings: Settings) -> str | None:
    if base not in ("diffuse", "dielectric"):
        return None
    sigma = state.params.get("diffuse_roughness", 0.0)
    return "oren_nayar" if sigma > settings.get("oren_nayar_threshold", 0.05) else "lambert"


def _warn_no_highlight(state: MaterialState) -> None:
    steps = state.provenance.get("anisotropy", [])
    with_words = [s for s in steps if s.words]
    last = with_words[-1].words[-1] if with_words else None
    word = last.text if last else "anisotropy"
    span = last.span if last else state.selection.span
    state.diagnostics.append(
        warning(
            span,
            "W108",
            f"'{word}' stretches the highlight, but this {noun_of(state).key} "
            "is matte and has none: anisotropy is not modelled",
            ("make it glossier for a visible highlight",),
        )
    )
