"""The coat clause: "oak with a glossy white varnish" -> a coat layer with its own groups."""

from __future__ import annotations

from ..state import Context, MaterialState
from .words import apply_coat_entry, apply_group, pigment_base


def apply_coat_clause(state: MaterialState, ctx: Context) -> MaterialState:
    clause = state.selection.coat
    if clause is None or clause.coat.unknown:
        return state
    apply_coat_entry(state, ctx, clause.coat.key, f"coats.{clause.coat.key}", (clause.coat,))
    for group in clause.groups:
        apply_group(state, ctx, group, target="coat")
    if any(g.kind == "colour" for g in clause.groups):
        pigment_base(state, ctx)
    return state
