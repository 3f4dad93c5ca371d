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
    if colour.base is not None:  # 'plaster pink': the colour word says the colour, as seen on the noun
        _lean_toward_noun(state, ctx, colour, noun)
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


#: nouns whose base colour is not the colour one sees: a metal's is a tint of its measured
#: reflectance ('chrome yellow', 'iron red' are the colour words; a glass's clear tint does lean
#: its colour word paler: 'sea glass green')
TINTED_MODELS = ("conductor",)


def _lean_toward_noun(state: MaterialState, ctx: Context, colour: ast.Colour, noun: ast.Word) -> None:
    """'plaster pink', 'concrete grey', 'oak green': the colour word leans toward the noun's own
    colour by colour_compounds.toml [named_after] share, in OKLab (plaster pink is a pale pink, not
    the survey's pink), with a note; a noun whose base colour is no colour one sees (a metal:
    TINTED_MODELS) or that has none leaves the colour word."""
    from ..colour import mix_oklab
    from .colour_compounds import rules

    entry = ctx.lexicon.entry("nouns", noun.key)
    own = entry.get("base_color") if entry is not None and entry.get("model") not in TINTED_MODELS else None
    current = state.params.get("base_color")
    assert colour.base is not None
    if own is None or current is None:
        _note(state, colour, f"read '{_text(colour)}' as the colour '{colour.base.text}', named after {noun.text}")
        return
    share = float(rules()["named_after"]["share"])
    state.params["base_color"] = mix_oklab(current, list(own), share)
    state.note("base_color", state.params["base_color"], f"colours: {_text(colour)} (toward {noun.key})", (noun,))
    _note(
        state,
        colour,
        f"read '{_text(colour)}' as the colour '{colour.base.text}' as seen on {noun.text}: {share:g} of the way toward its colour",
    )


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
