"""A colour word that names a metal, on a metal (issue #14, 'between two metals'): 'coppery brass',
'golden brass', 'silvery gold', 'gold steel', 'brass-coloured steel'. The metal looks part of the way
toward the named metal: the two metals' measured optical constants (eta, k) mixed at a share, and
f0 / F82 the exact Fresnel of the mix, in place of the tint and the film a colour word on a metal
gets otherwise (passes/conformal_coat.py). The word forms and shares are data
(stdlib/data/colour_compounds.toml [metal_tone]); the mix of constants is our choice, documented
in docs/language.md: no alloy between two named metals is measured in shared/data.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from .. import ast
from ..colour import mix_oklab
from ..degrees import compose_weights
from ..lexicon import Lexicon
from ..lexicon_model import Entry
from ..state import Context, MaterialState, Step
from .conformal_coat import COLOUR_RULES

OPTICS = ("eta", "k")
TONE_RULE = "metal_tone"  # its provenance rule: a metal's own look, no film over it
HEDGED_RULE = "colours"  # a hedged cast is still the colour word's (a film is laid over it)
F82_COSINE = math.cos(math.radians(82.0))  # where the F82 tint is read (Kutz et al. 2021, OpenPBR)


def tone_toward_named_metal(state: MaterialState, ctx: Context) -> MaterialState:
    """The last colour word on a bare conductor, when it names a metal: that metal's look, mixed in."""
    if state.kind != "conductor" or state.coat is not None or not all(p in state.params for p in OPTICS):
        return state
    steps = state.provenance.get("base_color", [])
    colour_steps = [s for s in steps if s.rule.split(":", 1)[0].strip() in COLOUR_RULES]
    if not colour_steps:
        return state
    step = colour_steps[-1]
    if step is not steps[-1]:
        return state  # a later plating replaced it
    found = named_metal(step, ctx)
    if found is None:
        _hedged_tint(state, step, _own_colour(steps, step))
        return state
    metal, share = found
    _mix(state, metal, share, _own_colour(steps, step), step)
    return state


def _hedged_tint(state: MaterialState, step: Step, own_colour: list[float]) -> None:
    """'greenish brass', 'bluish steel': a hedged colour word ('-ish': colour_compounds.toml
    [hedged] suffixes) on a metal is a cast, not a film of the full colour: the tint lies that
    share of the way from the metal's own colour to the word's in OKLab ([metal_tone]
    hedged_share), so the metal's own hue still shows (a green film over brass read as cyan)."""
    from .colour_compounds import rules

    said = [w for w in step.words if w.category != "adverbs"]
    suffixes = tuple(rules()["hedged"]["suffixes"])
    if len(said) != 1 or not said[0].text.lower().endswith(suffixes):
        return
    share = float(_table()["hedged_share"])
    tint = mix_oklab(own_colour, list(state.params["base_color"]), share)
    rule = f"{HEDGED_RULE}: '{said[0].text}' on a metal is a cast, {share:g} of the way to its colour"
    state.record("base_color", tint, rule, step.words)


def named_metal(step: Step, ctx: Context) -> tuple[Entry, float] | None:
    """The metal a colour step's word names and the share it moves toward it ('coppery': copper,
    0.5; 'slightly coppery': less); None unless its words are degree adverbs and one such word."""
    adverbs = [w for w in step.words if w.category == "adverbs"]
    said = [w for w in step.words if w.category != "adverbs"]
    if len(said) != 1:
        return None
    table = _table()
    for share, endings in ((1.0, table["full"]), (float(table["hedged_share"]), table["hedged"])):
        metal = metal_named(said[0].text.lower(), endings, ctx.lexicon)
        if metal is not None:
            return metal, min(1.0, share * _weight(adverbs, ctx))
    return None


def metal_named(text: str, endings: Sequence[str], lexicon: Lexicon) -> Entry | None:
    """The metal noun a word names with one of `endings` ('coppery' with 'y': copper), or None."""
    for ending in endings:
        if ending and not text.endswith(ending):
            continue
        stem = text[: len(text) - len(ending)] if ending else text
        for entry in lexicon.lookup(tuple(stem.replace("-", " ").split())):
            if entry.category == "nouns" and entry.get("model") == "conductor" and entry.get("eta") is not None:
                return entry
    return None


def _weight(adverbs: Sequence[ast.Word], ctx: Context) -> float:
    weights = []
    for word in adverbs:
        entry = ctx.lexicon.entry("adverbs", word.key)
        weights.append(float(entry.get("weight", 1.0)) if entry is not None else 1.0)
    return compose_weights(weights)


def _own_colour(steps: Sequence[Step], colour_step: Step) -> list[float]:
    """The base colour before the colour words (the noun's own tint: rose gold's pink)."""
    before = [s.value for s in steps[: steps.index(colour_step)] if s.rule.split(":", 1)[0].strip() not in COLOUR_RULES]
    return list(before[-1]) if before and before[-1] is not None else [1.0, 1.0, 1.0]


def _mix(state: MaterialState, metal: Entry, share: float, own_colour: list[float], step: Step) -> None:
    rule = f"{TONE_RULE}: '{' '.join(w.text for w in step.words)}' = {share:g} of the way to {metal.key}'s optics"
    for name in OPTICS:
        mixed = [float(a + share * (b - a)) for a, b in zip(state.params[name], metal.get(name))]
        state.record(name, mixed, rule, step.words, source=metal.get("source"))
    if share >= 1.0:  # the metal itself: its own measured values, as its noun has them
        for name in ("f0", "f82", "base_color"):
            state.record(name, list(metal.get(name)), rule, step.words, source=metal.get("source"))
        return
    from ..bsdf.fresnel import f0_conductor, fresnel_conductor  # numpy: only for a phrase that mixes metals

    eta, k = state.params["eta"], state.params["k"]
    state.record("f0", [float(f0_conductor(n, kk)) for n, kk in zip(eta, k)], rule, step.words)
    state.record("f82", [float(fresnel_conductor(F82_COSINE, n, kk)) for n, kk in zip(eta, k)], rule, step.words)
    theirs = metal.get("base_color", [1.0, 1.0, 1.0])
    colour = [a + share * (b - a) for a, b in zip(own_colour, theirs)]
    state.record("base_color", colour, rule, step.words)


def _table() -> Mapping[str, Any]:
    from .colour_compounds import rules

    table: Mapping[str, Any] = rules()["metal_tone"]
    return table
