"""Thin films over a metal (issue #15 item 2, docs/bsdf.md "Finishes and layers").

- A colour word on a bare metal names a surface film the words do not name (black oxide, gun
  bluing, a tinted lacquer): no metal is black or blue by its optics. The film is the coat
  `settings.metal_colour_coat` (stdlib: 'tinted film'), the colour stays the base's tint under it,
  so 'matte black metal' keeps a white highlight over a black body instead of reflecting nothing.
- A conformal coat (`follows_base`, an anodic oxide or that film) has the base's surface: it takes
  the base's roughness.
"""

from __future__ import annotations

from ..state import Context, MaterialState
from .words import apply_coat_entry

COLOUR_RULES = ("colours", "shades")  # provenance rules of colour words (passes/colours.py)
UNTINTED = 0.999  # a base colour channel at or above this leaves the metal's own reflectance


def lay_conformal_coats(state: MaterialState, ctx: Context) -> MaterialState:
    film = ctx.lexicon.settings.get("metal_colour_coat")  # ctx.settings, without the property's call
    if film and state.kind == "conductor" and state.coat is None and _coloured_by_words(state):
        words = tuple(w for step in state.provenance.get("base_color", []) for w in step.words)
        apply_coat_entry(state, ctx, film, f"settings.metal_colour_coat: a colour on a metal is a film ({film})", words)
    if state.coat is not None and state.coat.get("follows_base") and "roughness" in state.params:
        state.coat["roughness"] = state.params["roughness"]
        state.note("coat.roughness", state.params["roughness"], "a conformal coat takes the base's roughness")
    return state


def _coloured_by_words(state: MaterialState) -> bool:
    """A colour word set the base colour and it still tints the metal: a white tint is the bare
    metal (a later plating's optics replaced the colour: 'gold finish plastic'), no film to add."""
    steps = state.provenance.get("base_color", [])
    if steps and steps[-1].rule.startswith("metal_tone"):
        return False  # a metal's name as its colour: the metals' mixed optics (passes/metal_tone.py)
    tinted = any(channel < UNTINTED for channel in state.params.get("base_color", (1.0, 1.0, 1.0)))
    return tinted and any(step.rule.split(":", 1)[0].strip() in COLOUR_RULES for step in steps)
