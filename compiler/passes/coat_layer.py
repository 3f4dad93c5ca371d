"""One coat clause applied: its coat entry, then its groups on the coat ("a glossy white varnish")."""

from __future__ import annotations

from .. import ast
from ..state import Context, MaterialState
from .colour_compounds import colour_compounds
from .words import apply_coat_entry, apply_group, pigment_base


def apply_coat(state: MaterialState, ctx: Context, coat: ast.Coat) -> None:
    if coat.coat.unknown:
        return  # already reported as an unknown word
    apply_coat_entry(state, ctx, coat.coat.key, f"coats.{coat.coat.key}", (coat.coat,))
    groups = colour_compounds(coat.groups, ctx.lexicon, state.diagnostics)  # 'oxblood red lacquer': oxblood
    for group in groups:
        apply_group(state, ctx, group, target="coat")
    if any(g.kind == "colour" for g in coat.groups):
        pigment_base(state, ctx)
