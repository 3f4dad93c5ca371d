"""The IR: a versioned, target-independent JSON form of the compiled materials (docs/ir.md)."""

from __future__ import annotations

from .conventions import alpha_of
from .formulas import round6_list, rounded
from .state import MaterialState, step_json

IR_VERSION = 1

PARAMS_BY_MODEL = {
    "diffuse": ("base_color",),
    "dielectric": ("base_color", "roughness", "ior"),
    "conductor": ("base_color", "roughness", "eta", "k", "f0", "f82"),
    "glass": ("base_color", "roughness", "ior"),
}


def material_ir(state: MaterialState, convention: str) -> dict:
    model = state.model
    return {
        "name": state.name,
        "phrase": state.phrase,
        "variant": state.variant,
        "model": model,
        "params": _params(state, model, convention),
        "maps": rounded(state.maps),
        "provenance": _provenance(state),
    }


def _params(state: MaterialState, model: dict, convention: str) -> dict:
    """The parameters the model uses, rounded."""
    p, base = state.params, model["base"]
    noun = state.noun.data if state.noun is not None else {}
    out = {}
    for k in PARAMS_BY_MODEL[base]:
        if k in p:
            value = p[k]
            if type(value) is not list:
                out[k] = rounded(value)
            elif value is noun.get(k):
                out[k] = _rounded_lexicon_list(value)
            else:
                out[k] = round6_list(value)
    if model["diffuse"] == "oren_nayar":
        out["diffuse_roughness"] = rounded(p.get("diffuse_roughness", 0.0))
    if base != "diffuse":
        aniso = p.get("anisotropy", 0.0) if model["anisotropic"] else 0.0
        out["alpha"] = round6_list(alpha_of(p["roughness"], aniso, convention))
        out["alpha_convention"] = convention
    if model["anisotropic"]:
        out["anisotropy"] = rounded(p["anisotropy"])
        out["anisotropy_rotation"] = rounded(p.get("anisotropy_rotation", 0.0))
    out["coat"] = rounded(_coat(state.coat, convention)) if model["coat"] else None
    return out


_ROUNDED_LISTS: dict = {}  # id(lexicon list) -> (the list, rounded); keeping the list keeps its id unique


def _rounded_lexicon_list(values: list) -> list:
    """round6_list of a list straight from the lexicon (a metal's optics), made once per list."""
    found = _ROUNDED_LISTS.get(id(values))
    if found is None or found[0] is not values:
        if len(_ROUNDED_LISTS) >= 4096:
            _ROUNDED_LISTS.clear()
        found = _ROUNDED_LISTS[id(values)] = (values, round6_list(values))
    return list(found[1])  # a copy: whoever reads the IR may change it


def _coat(coat: dict, convention: str) -> dict:
    return {
        "name": coat["name"],
        "ior": coat["ior"],
        "roughness": coat["roughness"],
        "alpha": alpha_of(coat["roughness"], 0.0, convention),
        "color": coat["color"],
        "thickness": coat["thickness"],
    }


def _provenance(state: MaterialState) -> dict:
    """param -> its steps in JSON form; steps naming the same words share their word lists."""
    shared: dict = {}
    out = {}
    for param, steps in state.provenance.items():  # most parameters have a single step
        out[param] = [step_json(steps[0], shared)] if len(steps) == 1 else [step_json(s, shared) for s in steps]
    return out


def document_ir(materials: list[dict], diagnostics: list, source_name: str, lexicon_sources) -> dict:
    return {
        "ir_version": IR_VERSION,
        "source": source_name,
        "lexicon": list(lexicon_sources),
        "colour_space": "linear Rec.709",
        "materials": materials,
        "diagnostics": [d.to_json() for d in diagnostics],
    }
