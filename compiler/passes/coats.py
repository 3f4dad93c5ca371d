"""The 'with' clauses: "oak with a glossy white varnish" -> a coat layer with its own groups;
"marble with grey veins", "steel with a few rust spots" -> features (passes/features.py); and,
first, the nouns used as describing words ("chrome plated steel", passes/noun_words.py)."""

from __future__ import annotations

from .. import ast
from ..state import Context, MaterialState
from .coat_layer import apply_coat
from .features import apply_features
from .noun_words import apply_noun_qualifiers


def apply_coat_clause(state: MaterialState, ctx: Context) -> MaterialState:
    """After the describing groups: the nouns among them ('chrome plated', passes/noun_words.py),
    then the coat clause and the feature clauses (a coat first: a feature may bring its own)."""
    apply_noun_qualifiers(state, ctx)
    apply_clauses(state, ctx, state.selection.coat, state.selection.features)
    return state


def apply_clauses(state: MaterialState, ctx: Context, coat: ast.Coat | None, features: tuple[ast.Feature, ...]) -> None:
    """A coat clause and feature clauses, of a material line or of a refinement line
    ('with a glossy varnish' below 'walnut' adds the coat)."""
    if coat is not None:
        apply_coat(state, ctx, coat)
    if features:
        apply_features(state, ctx, features)
