"""What a lexicon entry is and does, in words: for hover and completion items."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from ..colour import linear_to_hex
from ..formulas import describe
from ..lexicon import Entry
from .markdown import code_span, prose, strong

CATEGORY_NAMES = {
    "nouns": "material noun",
    "adjectives": "adjective",
    "adverbs": "adverb",
    "colours": "colour",
    "shades": "shade",
    "refinements": "refinement",
    "properties": "property",
    "coats": "coat",
    "features": "feature of a 'with' clause",
}


def effect_lines(entry: Entry) -> list[str]:
    """What the word does to the material parameters, one line each."""
    describe_by_category = {
        "adjectives": _adjective_effects,
        "nouns": _noun_effects,
        "adverbs": _adverb_effects,
        "colours": _colour_effects,
        "shades": _shade_effects,
        "refinements": _refinement_effects,
        "properties": _property_effects,
        "coats": _coat_effects,
        "features": _feature_effects,
    }
    return describe_by_category[entry.category](entry)


def _adjective_effects(entry: Entry) -> list[str]:
    lines = [describe(e, 1.0) for e in entry.get("effects", [])]
    for target, effects in entry.get("on", {}).items():
        lines.append(f"on {target}: " + "; ".join(describe(e, 1.0) for e in effects))
    if entry.get("material"):
        lines.append(f"optics of {entry.get('material')}")
    if entry.get("coat"):
        lines.append(f"adds a {entry.get('coat')} coat")
    for role, ref in entry.get("maps", {}).items():
        lines.append(f"{role} map: {ref['graph']}")
    if entry.get("applies_to"):
        lines.append(f"applies to: {', '.join(entry.get('applies_to'))}")
    if entry.get("opposes"):
        lines.append(f"contradicts: {', '.join(entry.get('opposes'))}")
    return lines


def _noun_effects(entry: Entry) -> list[str]:
    lines = [f"class {entry.get('class')}, model {entry.get('model')}"]
    for param in ("roughness", "ior"):
        if entry.get(param) is not None:
            lines.append(f"{param} = {entry.get(param)}")
    if entry.get("base_color") is not None:
        lines.append(f"base_color = {_rgb(entry.get('base_color'))}")
    if entry.get("eta") is not None:
        lines.append(f"eta = {_rgb(entry.get('eta'))}, k = {_rgb(entry.get('k'))}")
    for role, ref in entry.get("maps", {}).items():
        lines.append(f"{role} map: {ref['graph']}")
    return lines


def _adverb_effects(entry: Entry) -> list[str]:
    return [f"weight {entry.get('weight')} on the following adjective"]


def _colour_effects(entry: Entry) -> list[str]:
    return [f"colour {entry.get('hex') or linear_to_hex(entry.get('rgb'))} (linear {_rgb(entry.get('rgb'))})"]


def _shade_effects(entry: Entry) -> list[str]:
    return [" then ".join(_shade_op(op) for op in entry.get("ops", []))]


def _shade_op(op: dict[str, Any]) -> str:
    if op["op"] == "mul":
        return f"colour *= {op['value']}"
    if op["op"] == "blend":
        return f"blend to {op['value']} by {op['amount']}"
    if op["op"] == "lightness":
        return f"OKLab L {op['amount']:.0%} of the way to {'white' if op['toward'] else 'black'}"
    if op["op"] == "chroma":
        return f"OKLCh chroma *= {op['scale']}"
    if op["op"] == "toward":
        return f"OKLab a, b {op['amount']:.0%} of the way to {op['oklab'][1:]}"
    return f"saturate by {op['amount']}"


def _refinement_effects(entry: Entry) -> list[str]:
    direction = "raises" if entry.get("direction", 1) > 0 else "lowers"
    return [f"{direction} {entry.get('target')} (bracket rule: steps, then bisects)"]


def _property_effects(entry: Entry) -> list[str]:
    target = entry.get("param") or entry.get("map_param")
    return [f"names {target}" + (" (inverted)" if entry.get("invert") else "")]


def _feature_effects(entry: Entry) -> list[str]:
    """'with fine scratches': what draws the feature (passes/features.py)."""
    lines = []
    if entry.get("adjective"):
        lines.append(f"drawn as '{entry.get('adjective')}' (weight {entry.get('weight', 1.0):g})")
    for role, ref in entry.get("maps", {}).items():
        lines.append(f"{role}: map {ref['graph']}")
    if entry.get("finish"):
        lines.append("its adjectives describe the surface ('with a matte finish' = matte)")
    if entry.get("coat"):
        lines.append(f"coat {entry.get('coat')}")
    if entry.get("missing"):
        lines.append(entry.get("missing"))
    return lines


def _coat_effects(entry: Entry) -> list[str]:
    return [
        f"coat ior {entry.get('ior')}, roughness {entry.get('roughness')}, colour {_rgb(entry.get('color', [1, 1, 1]))}"
    ]


def _rgb(values: Sequence[float]) -> str:
    return "(" + ", ".join(f"{v:.3g}" for v in values) + ")"


def entry_markdown(entry: Entry, surface: str | None = None) -> str:
    """The entry's doc and effects in Markdown; the surface word (document text) and the lexicon's
    text are escaped (lsp/markdown.py), so neither can add links, images or HTML."""
    title = f"{strong(surface or entry.key)} — {CATEGORY_NAMES[entry.category]}"
    if surface and surface.lower() != entry.key:
        title += f" ({code_span(entry.key)})"
    parts = [title, prose(str(entry.get("doc", "")))]
    effects = effect_lines(entry)
    if effects:
        parts.append("\n".join(f"- {prose(line)}" for line in effects))
    if entry.get("example"):
        parts.append(f"e.g. *{prose(str(entry.get('example')))}*")
    return "\n\n".join(p for p in parts if p)
