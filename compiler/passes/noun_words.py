"""Nouns used as describing words, before the material noun: "chrome plated steel" (the plating
is chrome), "walnut brown paint" (a colour named after walnut), "glass with an amber tint"
(amber's own colour). The grammar gives such a noun as ast.Colour.noun (grammar/cnl.lark
`noun_colour`); the groups pass has applied the rest of the group; this pass says what the noun
means, with a note for every reading it infers.
"""

from __future__ import annotations

from .. import ast
from ..diagnostics import Diagnostic, Severity
from ..state import Context, MaterialState
from .base import colour_seen_through, through_depth
from .colours import shade
from .words import copy_optics

READING = "N122"  # a noun read as a describing word


def apply_noun_qualifiers(state: MaterialState, ctx: Context) -> None:
    """Every noun that names a colour or a plating in the material's describing groups."""
    for group in state.selection.groups:
        for colour in group.colours:
            if colour.noun is not None and not colour.noun.unknown:
                _apply(state, ctx, group, colour, colour.noun)


def _apply(state: MaterialState, ctx: Context, group: ast.Group, colour: ast.Colour, noun: ast.Word) -> None:
    if colour.base is not None:  # 'walnut brown': the colour word says the colour
        _note(state, colour, f"read '{_text(colour)}' as the colour '{colour.base.text}', named after {noun.text}")
        return
    adjective = ctx.lexicon.entry("adjectives", group.adjectives[0].key) if group.adjectives else None
    target = adjective.get("colour_target", "base") if adjective is not None else "base"
    if target == "material" and adjective is not None:
        rule = f"adjectives.{adjective.key}: {noun.text}"
        if copy_optics(state, ctx, noun.key, rule, (noun, *group.adjectives)):
            _note(state, colour, f"read '{noun.text} {group.adjectives[0].text}' as {adjective.key} with {noun.text}")
            return
    param = "coat.color" if target == "coat" and state.coat is not None else "base_color"
    apply_noun_colour(state, ctx, colour, param)


def noun_colour(ctx: Context, colour: ast.Colour) -> list[float] | None:
    """The colour of a noun named alone ('amber' in 'an amber tint'): its lexicon base colour."""
    if colour.noun is None or colour.base is not None or colour.noun.unknown:
        return None
    entry = ctx.lexicon.entry("nouns", colour.noun.key)
    if entry is None:
        return None
    rgb = list(entry.get("base_color"))
    for word in reversed(colour.shades):  # 'a dark walnut stain': the shade nearest the noun first
        rgb = shade(rgb, ctx.lexicon.require("shades", word.key).get("ops"))
    return rgb


def apply_noun_colour(state: MaterialState, ctx: Context, colour: ast.Colour, param: str) -> None:
    """Set `param` (base_color or coat.color) to the noun's own colour, with a note."""
    rgb = noun_colour(ctx, colour)
    if rgb is None or colour.noun is None:
        return
    if param == "coat.color" and state.coat is not None:
        state.coat["color"] = rgb
        state.note(param, rgb, f"nouns.{colour.noun.key}: the colour of {colour.noun.text}", (colour.noun,))
    else:
        colour_seen_through(state, (colour.noun,))
        depth = ctx.lexicon.require("nouns", colour.noun.key).get("transmission_depth")
        if state.kind == "glass" and depth is not None:  # 'a red wine tint': the wine as seen, not its 1 cm
            rgb = through_depth(rgb, depth, state.params["transmission_depth"])
        state.record("base_color", rgb, f"nouns.{colour.noun.key}: the colour of {colour.noun.text}", (colour.noun,))
    _note(state, colour, f"read '{_text(colour)}' as the colour of {colour.noun.text}")


def _text(colour: ast.Colour) -> str:
    return " ".join(w.text for w in colour.words)


def _note(state: MaterialState, colour: ast.Colour, message: str) -> None:
    state.diagnostics.append(Diagnostic(colour.span, Severity.NOTE, READING, message))
