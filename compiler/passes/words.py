"""Apply the describing groups in their canonical order: adverb weights, adjectives, colours.

"lightly brushed, blue anodized aluminum": brushed at weight 0.5 (roughness * 1.1, anisotropic,
a normal map), then anodized (roughness = 0.3) whose colour 'blue' goes to the base colour.
The order is by stage (compiler/passes/order.py), not by the words' order; weights compose and
formulas saturate inside each parameter's range (compiler/degrees.py).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from types import MappingProxyType
from typing import Any, NamedTuple

from .. import ast
from ..degrees import compose_weights, weighted_formula
from ..diagnostics import Diagnostic, Severity, warning
from ..formulas import apply_op, describe
from ..lexicon import Entry, LexiconCaches
from ..params import COAT_PARAMS, PARAMS, ranges
from ..state import Context, MaterialState
from ..tagged import NOTE_CODE
from .base import _map_ref, applies_to, colour_seen_through, noun_of
from .colour_compounds import colour_compounds
from .colours import colour_text, opposed_shades, resolve_colour
from .diffuse_sigma import DIFFUSE_SIGMA, PARAM_BOUNDS, move_sigma
from .feature_maps import draw_feature_maps, weighted_map
from .negated_finish import already_not
from .order import canonical_groups, gloss_on_coat, stage_of
from .textured_colour import keep_pattern_visible

Effect = dict[str, Any]  # one formula of a lexicon entry: {"param": ..., "op": ..., "value": ...}
Holder = dict[str, Any]  # where a value goes: the material's parameters or its coat's
Words = tuple[ast.Word, ...]

PARAM_DEFAULTS = MappingProxyType(  # what a formula starts from when the material lacks the parameter (ior 1.5)
    {s.name: list(s.default) if isinstance(s.default, tuple) else s.default for s in PARAMS}
)
COAT_BOUNDS = ranges(COAT_PARAMS)
DEGREE_PARAMS = ("roughness", "anisotropy", DIFFUSE_SIGMA)  # scales whose set levels intensify ("very glossy")


def group_weight(group: ast.Group, ctx: Context) -> float:
    """The adverbs' weight: "very lightly" = lightly ** very (compiler/degrees.py)."""
    if not group.adverbs:
        return 1.0  # compose_weights([]), without the calls: most groups have no adverb
    return compose_weights([ctx.lexicon.require("adverbs", a.key).get("weight") for a in group.adverbs])


def apply_groups(state: MaterialState, ctx: Context) -> MaterialState:
    apply_described(state, ctx, state.selection.groups)
    return state


def apply_described(state: MaterialState, ctx: Context, said: Sequence[ast.Group]) -> None:
    """Describing groups applied in the canonical order (passes/order.py), gloss words on the
    coat the look comes from: the phrase's own, or a change line's ('make it glossy red')."""
    groups = colour_compounds(said, ctx.lexicon, state.diagnostics)
    ordered = canonical_groups(groups, ctx.lexicon)
    on_coat = gloss_on_coat(ordered, ctx.lexicon, state.coat is not None and not state.coat.get("follows_base"))
    for group in ordered:
        if group not in on_coat:
            apply_group(state, ctx, group, target="base")
    for group in on_coat:  # "matte varnished oak": the gloss one sees is the varnish's
        apply_group(state, ctx, group, target="coat")


def apply_group(state: MaterialState, ctx: Context, group: ast.Group, target: str) -> None:
    if _has_unknown(group):
        return  # already reported as an unknown word
    if group.kind == "dangling":
        _warn_dangling(state, group)
        return
    weight = group_weight(group, ctx)
    if group.kind == "colour":
        apply_colour(state, ctx, group.colours[0], group.adverbs, target, weight)
        return
    adjective = ctx.lexicon.require("adjectives", group.adjectives[0].key)
    apply_adjective(state, ctx, adjective, group, weight, target)


def _has_unknown(group: ast.Group) -> bool:
    for word in group.adverbs:
        if word.unknown:
            return True
    for c in group.colours:
        for word in c.shades:
            if word.unknown:
                return True
        if c.base is not None and c.base.unknown:
            return True
    for word in group.adjectives:
        if word.unknown:
            return True
    return False


def _warn_dangling(state: MaterialState, group: ast.Group) -> None:
    text = " ".join(w.text for w in group.adverbs)
    if text.lower() in _hedges_before_a_noun():  # 'some kind of metal': a hedge on the material named
        note = f"read past '{text}': a hedge on the material named, not a degree"
        state.diagnostics.append(Diagnostic(group.span, Severity.NOTE, NOTE_CODE, note))
        return
    state.diagnostics.append(
        warning(
            group.span,
            "W103",
            f"'{text}' has nothing to modify",
            ("put an adjective after it, e.g. 'lightly brushed'",),
        )
    )


def apply_colour(
    state: MaterialState, ctx: Context, c: ast.Colour, adverbs: Words, target: str, weight: float, ageing: bool = True
) -> None:
    """A colour word on the base (or the coat); `ageing`: it may name the colour a bare metal turns by
    itself ('green copper'), not when it qualifies a describing word ('green tinted copper')."""
    param, holder = _colour_slot(state, target)
    if param == "base_color":
        colour_seen_through(state, c.words)
    current = holder.get(param)
    rgb = resolve_colour(c, ctx, start=current, weight=weight)
    words = c.words
    if ageing and target == "base" and words and _colour_of_ageing(state, ctx, rgb, (*adverbs, *words), weight):
        return
    if target == "base" and words:
        rgb = keep_pattern_visible(state, ctx, rgb, words, noun_of(state).key)
    _warn_opposed_shades(state, ctx, c)
    if weight >= 1.0:  # a share of the way ('slightly red', 'blackish') moves the colour, replaces none
        _warn_second_colour(state, param if target == "base" else "coat.color", c)
    holder[param] = rgb
    text = " ".join([w.text for w in words])  # colour_text(c)
    state.note(param if target == "base" else "coat.color", rgb, f"colours: {text}", (*adverbs, *words))


def _colour_of_ageing(state: MaterialState, ctx: Context, rgb: list[float], words: Words, weight: float) -> bool:
    """'green copper', 'copper gone green': a colour word on a bare metal that is the colour the metal
    turns by itself (settings.metal_colour_ageing) draws that ageing at the word's weight instead
    of a tinted film, with a note; False for any other colour or material."""
    if state.kind != "conductor":
        return False
    noun = noun_of(state)
    for key, rule in (ctx.lexicon.settings.get("metal_colour_ageing") or {}).items():
        if noun.key not in rule["nouns"] or not _hue_within(rgb, rule["hues"], float(rule["least_chroma"])):
            continue
        adjective = ctx.lexicon.require("adjectives", key)
        state.applied.append((adjective.key, words[-1]))
        _apply_maps(state, ctx, adjective, weight, words)
        said = " ".join(w.text for w in words)
        message = f"read '{said}' on {noun.key} as {key}: the colour {noun.key} turns by itself (settings.metal_colour_ageing)"
        state.diagnostics.append(
            Diagnostic(words[0].span.to(words[-1].span), Severity.NOTE, SURVEY_COLOUR, message, ())
        )
        return True
    return False


def _hue_within(rgb: list[float], hues: Sequence[float], least_chroma: float) -> bool:
    from ..colour import linear_to_oklab

    _l, a, b = linear_to_oklab(rgb)
    hue = math.degrees(math.atan2(b, a)) % 360.0
    return math.hypot(a, b) >= least_chroma and hues[0] <= hue <= hues[1]


def _warn_opposed_shades(state: MaterialState, ctx: Context, c: ast.Colour) -> None:
    pair = opposed_shades(c, ctx) if c.shades else None
    if pair is not None:
        inner, outer = pair
        state.diagnostics.append(
            warning(
                c.span,
                "W101",
                f"'{outer}' contradicts '{inner}': '{outer}' wins",
                (f"shades apply from the colour outwards, '{inner}' first; drop the one you do not mean",),
            )
        )


def _colour_slot(state: MaterialState, target: str) -> tuple[str, Holder]:
    if target == "coat" and state.coat is not None:
        return "color", state.coat
    return "base_color", state.params


def _warn_second_colour(state: MaterialState, param: str, c: ast.Colour) -> None:
    if c.base is None:
        return
    for step in reversed(state.provenance.get(param, ())):  # the last colour step, if any
        if step.rule.startswith("colours: "):
            if step.words and step.words[-1].span.line != c.span.line:
                return  # a colour of a line above: 'make it blue' below 'red leather' changes it
            state.diagnostics.append(
                warning(
                    c.span,
                    "W105",
                    f"a second colour for the {param.replace('_', ' ')}: "
                    f"'{step.words[-1].text}' is replaced by '{colour_text(c)}'",
                    ("use 'or' for alternatives: 'red or blue plastic'",),
                )
            )
            return


def apply_adjective(
    state: MaterialState, ctx: Context, adjective: Entry, group: ast.Group, weight: float, target: str
) -> None:
    word = group.adjectives[0]
    if not group.colours and target == "base" and _survey_colour_instead(state, adjective, word, weight):
        return
    if not _applies(state, adjective, word, target):
        for c in group.colours:  # "pale honed maple": the colour still holds, on the base
            apply_colour(state, ctx, c, group.adverbs, "base", weight, ageing=False)
        return
    if already_not(state, ctx, word):
        return  # 'glossy paint but not mirror': glossy is not mirror already
    if state.applied:
        _check_opposition(state, ctx, adjective, word)
    _check_noun_name(state, ctx, adjective, word)
    state.applied.append((adjective.key, word))
    words = (*group.adverbs, word)
    colour_weight = 1.0
    if group.colours:  # "very dark brushed": the adverb stands before, and modifies, the colour
        weight, colour_weight = 1.0, weight
        words = (word,)
    plan, data = adjective_plan(adjective, noun_of(state), ctx.lexicon.caches), adjective.data
    holder, effects = state.params, plan.on_base
    if target == "coat" and state.coat is not None:
        holder, effects = state.coat, plan.on_coat
    if plan.changes_nothing and not group.colours:
        _note_unchanged_look(state, word)
    for effect in effects:
        _apply_effect(state, ctx, holder, effect, weight, words)
    if data.get("material"):
        _apply_material(state, ctx, adjective, words)
    if data.get("hides"):
        _hide_maps(state, adjective, words)
    if data.get("maps"):
        _apply_maps(state, ctx, adjective, weight, words)
    if data.get("coat"):
        _apply_adjective_coat(state, ctx, adjective, words)
    if data.get("features_on"):
        _draw_feature_on(state, ctx, adjective, weight, words)
    for c in group.colours:
        _apply_qualifier(state, ctx, adjective, c, group.adverbs, colour_weight)


def _draw_feature_on(state: MaterialState, ctx: Context, adjective: Entry, weight: float, words: Words) -> None:
    """The feature the adjective draws on this noun or its class ('weathered copper': a patina)."""
    noun = noun_of(state)
    table = adjective.get("features_on")
    key = table.get(noun.key) or table.get(noun.data.get("class"))
    if key is None:
        return
    draw_feature(state, ctx, ctx.lexicon.require("features", key), weight, words)


def draw_feature(state: MaterialState, ctx: Context, entry: Entry, weight: float, words: Words) -> None:
    """A feature's maps at the weight: its own, or those of the adjective it stands for ('rust
    spots': what 'rusty' draws, at the feature's own weight)."""
    if entry.get("maps"):
        draw_feature_maps(state, ctx, entry, weight, words)
    elif entry.get("adjective"):
        drawn = ctx.lexicon.require("adjectives", str(entry.get("adjective")))
        _apply_maps(state, ctx, drawn, weight * float(entry.get("weight", 1.0)), words)


def _note_unchanged_look(state: MaterialState, word: ast.Word) -> None:
    """A word of how a thing is made ('tempered', 'laminated', 'raw') that changes no surface parameter."""
    message = f"'{word.text}' does not change how {noun_of(state).key} looks: no surface parameter changes"
    state.diagnostics.append(Diagnostic(word.span, Severity.NOTE, UNCHANGED_LOOK, message, ()))


UNCHANGED_LOOK = "N141"  # a describing word with no effect on the look


def effects_for(adjective: Entry, state: MaterialState) -> list[Effect]:
    """The per-noun formula, else the per-class one, else the default (paper: brushed wood)."""
    return effect_source(adjective, state)[1]


def effect_source(adjective: Entry, state: MaterialState) -> tuple[str, list[Effect]]:
    """effects_for, with where in the entry the list is ('on.<noun>', 'on.<class>' or 'effects'); a
    transparent noun of another class (plexiglass: a plastic whose model is glass) takes 'on.glass'."""
    return _effect_list(adjective, noun_of(state))


def _effect_list(adjective: Entry, noun: Entry) -> tuple[str, list[Effect]]:
    data = adjective.data
    on = data.get("on")
    if on:
        for name in (noun.key, noun.data.get("class"), noun.data.get("model")):
            if on.get(name):
                return f"on.{name}", on[name]
    return "effects", data.get("effects", [])


COAT_CLASS = "plastic"  # a coat is a clear polymer film (coats.toml: PMMA lacquer, polyurethane varnish)


def _survey_colour_instead(state: MaterialState, adjective: Entry, word: ast.Word, weight: float) -> bool:
    """'rust linen', 'rust corduroy': a describing word of one class of material ('rust' = rusty:
    metal only) that the colour survey also names a colour is that colour on any other material,
    applied as a colour word is (a share of the way at a softening degree: 'slightly rust linen';
    W105 after another colour), with a note, not ignored (W102); False where the word applies or the
    survey has no such colour."""
    from ..colour import hex_to_linear, mix_oklab
    from ..lexicon_load import survey_hex

    noun = noun_of(state)
    hex_code = survey_hex(word.text.lower()) if not applies_to(noun, adjective) else None
    if hex_code is None:
        return False
    rgb, current = hex_to_linear(hex_code), state.params.get("base_color")
    if weight < 1.0 and current is not None:
        rgb = mix_oklab(current, rgb, weight)
    said = ast.Colour((), ast.Word(word.text, word.text.lower(), "colours", word.span), word.span)
    if weight >= 1.0:
        _warn_second_colour(state, "base_color", said)
    state.params["base_color"] = rgb
    state.note("base_color", rgb, f"colours: {word.text} (survey)", (word,))
    message = f"read '{word.text}' as the colour {word.text.lower()} ({hex_code}): '{adjective.key}' does not apply to {noun.key}"
    state.diagnostics.append(Diagnostic(word.span, Severity.NOTE, SURVEY_COLOUR, message, ()))
    return True


SURVEY_COLOUR = "N101"  # a word read by a rule: here, as the survey's colour of its name


def _applies(state: MaterialState, adjective: Entry, word: ast.Word, target: str = "base") -> bool:
    """Whether the adjective applies to its material; in a coat clause, to the coat ('a clear lacquer')."""
    classes = adjective.data.get("applies_to")
    if not classes or (target == "coat" and COAT_CLASS in classes):
        return True
    noun = noun_of(state)
    if target != "coat" and applies_to(noun, adjective):
        return True
    note = adjective.get("applies_note", f"it applies to {', '.join(classes)}")
    state.diagnostics.append(
        warning(word.span, "W102", f"'{word.text}' does not apply to {noun.key}: {note}", ("the word is ignored",))
    )
    return False


def _opposed(first: Entry, then: Entry) -> bool:
    """Whether two adjectives contradict: one `opposes` the other, or one is the other's declared
    `opposite` (the antonym 'not X' is read as: 'clear' and 'frosted', 'transparent opaque'), or
    both are finishes that set one parameter far apart ('satin high-gloss')."""
    return (
        first.key in then.get("opposes", [])
        or then.key in first.get("opposes", [])
        or then.get("opposite") == first.key
        or first.get("opposite") == then.key
        or _set_apart(first, then)
    )


SET_APART = 0.2  # our choice: two finish words that set one parameter this far apart name two finishes


def _set_apart(first: Entry, then: Entry) -> bool:
    """Two finish words that each set the same parameter, to values more than SET_APART apart
    ('satin high-gloss': roughness 0.35 and 0.08): the later replaces the earlier, so they contradict."""
    if stage_of(first) != "finish" or stage_of(then) != "finish" or first.key == then.key:
        return False
    earlier = {e["param"]: e["value"] for e in first.get("effects", []) if e.get("op") == "set"}
    return any(
        e["param"] in earlier
        and isinstance(e["value"], (int, float))
        and isinstance(earlier[e["param"]], (int, float))
        and abs(e["value"] - earlier[e["param"]]) > SET_APART
        for e in then.get("effects", [])
        if e.get("op") == "set"
    )


def _check_opposition(state: MaterialState, ctx: Context, adjective: Entry, word: ast.Word) -> None:
    for earlier_key, earlier in state.applied:
        if earlier.span.line != word.span.line:
            continue  # a word of a line above: 'go matte' below 'shiny red plastic' changes it
        first = ctx.lexicon.require("adjectives", earlier_key)
        if _opposed(first, adjective):
            state.diagnostics.append(
                warning(
                    word.span,
                    "W101",
                    f"'{word.text}' contradicts '{earlier.text}': '{word.text}' wins",
                    (_why_it_wins(stage_of(first), stage_of(adjective), earlier.text, word.text),),
                )
            )


def _check_noun_name(state: MaterialState, ctx: Context, adjective: Entry, word: ast.Word) -> None:
    """A describing word against a word of the noun's own name ('shiny chalky paint': chalk paint is
    matte by what it is, 'chalky' an alias of 'matte'): W101 as for two describing words; the
    describing word applies over the noun's own finish, so it wins."""
    nouns = getattr(state.selection, "nouns", ())
    if not nouns or nouns[0].span.line != word.span.line:
        return
    for part in nouns[0].text.lower().split()[:-1]:  # the last word names the thing ('paint')
        for found in ctx.lexicon.lookup((part,)):
            if found.category == "adjectives" and _opposed(ctx.lexicon.require("adjectives", found.key), adjective):
                state.diagnostics.append(
                    warning(
                        word.span,
                        "W101",
                        f"'{word.text}' contradicts '{part}' in '{nouns[0].text}': '{word.text}' wins",
                        (f"'{nouns[0].text}' is {found.key} by what it is; drop the one you do not mean",),
                    )
                )
                return


def _why_it_wins(first_stage: str, last_stage: str, first: str, last: str) -> str:
    if first_stage == last_stage:
        return f"both apply and the later word of the two, '{last}', applies last; drop the one you do not mean"
    return (
        f"both apply: '{first}' is a {first_stage} word and applies before '{last}', a {last_stage} word "
        "(docs/language.md: Degrees and order); drop the one you do not mean"
    )


def _apply_effect(
    state: MaterialState, ctx: Context, holder: Holder, effect: EffectPlan, weight: float, words: Words
) -> None:
    if effect.param == "model":
        _switch_kind(state, effect.effect["value"], effect.place[0], words)
        return
    if effect.param == "base_color" and holder is state.params:
        colour_seen_through(state, words)
    current = holder.get(effect.param, effect.default)
    value = weighted_formula(effect.op, current, effect.value, weight, effect.amount, effect.bounds, effect.degree)
    holder[effect.param] = value
    rule = _effect_rule(effect, weight)
    state.note(effect.name, value, rule, words)
    if effect.moves_sigma:
        move_sigma(state, ctx, effect.effect, weight, rule, words, (current, value))


EffectPlace = tuple[str, str, int]  # (rule, where the effect list is in the entry, index in it)


class EffectPlan(NamedTuple):
    """One formula of an adjective's effect list for one holder (the material's parameters or its
    coat's), read once per lexicon: what _apply_effect would otherwise look up for every phrase."""

    effect: Effect  # the lexicon's formula itself (move_sigma and the rule text read it)
    param: str
    op: Any
    value: Any
    amount: Any
    default: Any  # what the formula starts from when the holder lacks the parameter
    bounds: tuple[float, float] | None  # where the weighted formula saturates
    degree: bool  # a degree scale, whose set levels intensify ("very glossy")
    name: str  # the provenance name: the parameter, or 'coat.<parameter>' on a coat
    place: EffectPlace
    moves_sigma: bool  # a roughness formula on the material moves the Oren-Nayar sigma too
    rules: dict[float, str]  # adverb weight -> the provenance text (_effect_rule)


class AdjectivePlan(NamedTuple):
    """What apply_adjective reads from one adjective on one noun, once per lexicon
    (LexiconCaches.adjective_plans): the effect list effect_source picks, planned for each holder."""

    adjective: Entry  # the entries it was read from
    noun: Entry
    on_base: tuple[EffectPlan, ...]
    on_coat: tuple[EffectPlan, ...]
    changes_nothing: bool  # no formula, map, coat, material, hidden map or medium: _note_unchanged_look


def adjective_plan(adjective: Entry, noun: Entry, caches: LexiconCaches) -> AdjectivePlan:
    plans = caches.adjective_plans
    plan: AdjectivePlan | None = plans.get((adjective.key, noun.key))
    if plan is None or plan.adjective is not adjective or plan.noun is not noun:
        where, effects = _effect_list(adjective, noun)
        rule, data = f"adjectives.{adjective.key}", adjective.data
        if len(plans) >= LexiconCaches.MAX_ENTRIES:
            plans.clear()
        plan = plans[(adjective.key, noun.key)] = AdjectivePlan(
            adjective,
            noun,
            tuple(_effect_plan(effect, (rule, where, i), on_coat=False) for i, effect in enumerate(effects)),
            tuple(_effect_plan(effect, (rule, where, i), on_coat=True) for i, effect in enumerate(effects)),
            not effects and not any(data.get(k) for k in ("maps", "coat", "material", "hides", "subsurface")),
        )
    return plan


def _effect_plan(effect: Effect, place: EffectPlace, on_coat: bool) -> EffectPlan:
    param = effect["param"]
    if param == "model":  # a switch of kind: _switch_kind reads the value and the rule only
        return EffectPlan(effect, param, None, None, None, None, None, False, param, place, False, {})
    return EffectPlan(
        effect,
        param,
        effect["op"],
        effect.get("value"),
        effect.get("amount"),
        PARAM_DEFAULTS.get(param, 0.0),
        (COAT_BOUNDS if on_coat else PARAM_BOUNDS).get(param),
        param in DEGREE_PARAMS,
        f"coat.{param}" if on_coat else param,
        place,
        param == "roughness" and not on_coat,
        {},
    )


def _effect_rule(effect: EffectPlan, weight: float) -> str:
    """'adjectives.brushed: roughness *= 1.2 (weight 0.5)', made once per lexicon effect and weight."""
    if not weight > 0:  # -0.0 would share 0.0's entry but prints differently; NaN never matches
        return f"{effect.place[0]}: {describe(effect.effect, weight)}"
    memo = effect.rules
    found = memo.get(weight)
    if found is None:
        if len(memo) >= LexiconCaches.MAX_ENTRIES:
            memo.clear()
        found = memo[weight] = f"{effect.place[0]}: {describe(effect.effect, weight)}"
    return found


def _switch_kind(state: MaterialState, kind: str, rule: str, words: Words) -> None:
    if state.kind == kind:
        return
    state.kind = kind
    if kind != "conductor":
        for param in ("eta", "k", "f0", "f82"):
            state.params.pop(param, None)
        if noun_of(state).get("model") == "conductor":
            state.params["base_color"] = [0.8, 0.8, 0.8]
    state.note("model", kind, f"{rule}: model = {kind}", words)


def _apply_material(state: MaterialState, ctx: Context, adjective: Entry, words: Words) -> None:
    if adjective.get("material"):
        copy_optics(state, ctx, adjective.get("material"), f"adjectives.{adjective.key}.material", words)


def copy_optics(state: MaterialState, ctx: Context, noun_key: str, rule: str, words: Words) -> bool:
    """The surface of the material named by a plating or coating word: a metal's measured optics
    ('gold plated', 'zinc coated'); a non-metal's own surface, opaque ('rubber coated')."""
    entry = ctx.lexicon.entry("nouns", noun_key)
    if entry is None:
        return False
    if entry.get("model") != "conductor":
        _copy_dielectric_surface(state, entry, rule, words)
        return True
    state.kind = "conductor"
    for param in ("eta", "k", "f0", "f82", "base_color"):
        state.record(param, entry.get(param), f"{rule}: optics of {entry.key}", words, source=entry.get("source"))
    _plating_brightness(state, entry, rule, words)
    return True


def _plating_brightness(state: MaterialState, entry: Entry, rule: str, words: Words) -> None:
    """A metal plated or coated with another ('chrome plated steel', 'gold plated brass', 'zinc
    coated steel': every metal named before a `colour_target = "material"` word) is as smooth as
    the plating metal's own noun when that is smoother: decorative plating is deposited bright and
    levels fine roughness (our choice). A roughness a describing word of the phrase set stays
    ('polished', 'matte'); the base's relief maps stay too (a plating microns thick follows a cast
    or hammered surface)."""
    plating = entry.get("roughness")
    current = state.params.get("roughness")
    if plating is None or current is None or plating >= current:
        return
    if any(step.rule.startswith("adjectives.") for step in state.provenance.get("roughness", ())):
        return
    state.record("roughness", plating, f"{rule}: as bright as plated {entry.key} (its noun's roughness)", words)


SURFACE_PARAMS = ("base_color", "roughness", "ior", DIFFUSE_SIGMA)  # what a non-metal coating brings


def _copy_dielectric_surface(state: MaterialState, entry: Entry, rule: str, words: Words) -> None:
    """A coating of a non-metal is opaque: the surface is that material's (a glass becomes an opaque
    glassy layer), whatever was under it, except what a describing word of the phrase set."""
    state.kind = "dielectric"
    for param in ("eta", "k", "f0", "f82"):
        state.params.pop(param, None)
    for param in SURFACE_PARAMS:
        if any(step.rule.startswith("adjectives.") for step in state.provenance.get(param, ())):
            continue  # a describing word said it ('rubber coated matte steel' is a matte coating)
        value = entry.get(param, PARAM_DEFAULTS.get(param))
        state.record(param, value, f"{rule}: surface of {entry.key}", words, source=entry.get("source"))


def _hide_maps(state: MaterialState, adjective: Entry, words: Words) -> None:
    """An opaque layer (paint, powder coat, enamel) covers the material's own maps of these roles."""
    for role in adjective.get("hides", []):
        if state.maps.pop(role, None) is not None:
            state.note(f"maps.{role}", None, f"adjectives.{adjective.key}.hides: covered by the layer", words)


def _apply_maps(state: MaterialState, ctx: Context, adjective: Entry, weight: float, words: Words) -> None:
    maps = adjective.get("maps", {})
    for role, ref in maps.items():
        if role == "normal" and len(maps) > 1 and _keeps_own_relief(state, ref):
            continue
        drawn = _map_ref(weighted_map(ref, weight), ctx)
        state.maps[role] = _kept_params(state.maps.get(role), drawn, ref.get("weighted", ()))
        state.note(f"maps.{role}", ref["graph"], f"adjectives.{adjective.key}.maps (weight {weight:g})", words)


def _keeps_own_relief(state: MaterialState, ref: dict[str, Any]) -> bool:
    """Whether the noun's own relief stays ('distressed leather' keeps the leather grain): a material
    shows one pattern per map, and a word drawing another relief over the pattern that names the
    material (its noun's normal map) would leave scratched plastic, not leather. The word's other
    maps still draw it (the scratches in the roughness); the provenance shows which map is whose."""
    current = state.maps.get("normal")
    steps = state.provenance.get("maps.normal")
    return (
        current is not None
        and current.get("graph") != ref["graph"]
        and bool(steps)
        and steps is not None
        and steps[-1].rule.startswith("nouns.")
    )


def _kept_params(before: dict[str, Any] | None, drawn: dict[str, Any], degrees: Sequence[str] = ()) -> dict[str, Any]:
    """A describing word's map over the same graph and output as the map already there keeps that
    map's own parameters and sets its own ('fine-grained oak' is oak's grain, finer). A parameter
    that is the word's degree (its `weighted` ones: rust coverage, scratch strength) never drops
    below the map's own: 'rusty' on weathering steel, rusted all over, adds no clean steel."""
    if before is None or (before.get("graph"), before.get("output")) != (drawn.get("graph"), drawn.get("output")):
        return drawn
    own = before.get("params", {})
    params = {**own, **drawn.get("params", {})}
    for name in degrees:
        if isinstance(own.get(name), (int, float)) and isinstance(params.get(name), (int, float)):
            params[name] = max(own[name], params[name])
    return {**drawn, "params": params}


def _apply_adjective_coat(state: MaterialState, ctx: Context, adjective: Entry, words: Words) -> None:
    if adjective.get("coat"):
        apply_coat_entry(state, ctx, adjective.get("coat"), f"adjectives.{adjective.key}.coat", words)


def apply_coat_entry(state: MaterialState, ctx: Context, coat_key: str, rule: str, words: Words) -> None:
    entry = ctx.lexicon.require("coats", coat_key)
    fields = ctx.lexicon.caches.coat_fields.get(coat_key)
    if fields is None or fields[0] is not entry:
        fields = _coat_fields(coat_key, entry, ctx.lexicon.caches)
    state.coat = dict(fields[1])  # the material's own copy: passes change its values
    state.note("coat", coat_key, rule, words)


def _coat_fields(coat_key: str, entry: Entry, caches: LexiconCaches) -> tuple[Entry, dict[str, Any]]:
    """The coat's fields as a material holds them (its entry's, but for aliases, doc and example,
    with its name), read once per lexicon (LexiconCaches.coat_fields)."""
    fields = {k: v for k, v in entry.data.items() if k not in ("aliases", "doc", "example")}
    fields["name"] = coat_key
    if len(caches.coat_fields) >= LexiconCaches.MAX_ENTRIES:
        caches.coat_fields.clear()
    caches.coat_fields[coat_key] = (entry, fields)
    return entry, fields


def _apply_qualifier(
    state: MaterialState, ctx: Context, adjective: Entry, c: ast.Colour, adverbs: Words, weight: float = 1.0
) -> None:
    """Where 'blue' in 'blue anodized' goes: base colour, coat colour, or a plating metal."""
    target = adjective.get("colour_target", "base")
    if target == "material" and c.base is not None and not c.shades:
        if copy_optics(state, ctx, c.base.key, f"adjectives.{adjective.key}: {c.base.text}", (*adverbs, *c.words)):
            return
    if target == "coat" and state.coat is not None:
        apply_colour(state, ctx, c, adverbs, "coat", weight)
        pigment_base(state, ctx)
        return
    apply_colour(state, ctx, c, adverbs, "base", weight, ageing=False)  # 'green tinted copper': a film


def pigment_base(state: MaterialState, ctx: Context) -> None:
    """A coloured coat also tints what shows through it by the coat's pigment amount."""
    coat = state.coat
    assert coat is not None, "called once a coat is applied"
    pigment = coat.get("pigment", 0.0)
    if pigment > 0 and "base_color" in state.params:
        value = apply_op("blend", state.params["base_color"], coat["color"], 1.0, pigment)
        words = [w for s in state.provenance.get("coat.color", [])[-1:] for w in s.words]
        state.record("base_color", value, f"coats.{coat['name']}: pigment {pigment} of the coat colour", words)


def _hedges_before_a_noun() -> frozenset[str]:
    """teaching.toml [hedges] `before_a_noun`: degree words that hedge the noun after them."""
    from ..suggest import teaching

    return frozenset(teaching()["hedges"]["before_a_noun"])
