"""Feature clauses: "marble with grey veins", "steel with a few rust spots", "ceramic with a matte finish".

A clause is `with [a] [degree] [colour] FEATURE`; the feature's lexicon entry (features.toml)
says what draws it: an adjective (its effects and maps), maps of its own, a coat, or for a
finish the clause's own adjectives. Degree words are adverbs: their weights multiply, as for an
adjective ('a few' 0.4 x the feature). A colour goes where the entry's `colour` says: the
feature map's named colour (graph params color_r/g/b, color_amount) or the base colour.
Words the feature cannot use, and features nothing can draw yet, are reported.
"""

from __future__ import annotations

from typing import Any

from .. import ast
from ..colour import linear_to_oklab
from ..diagnostics import Diagnostic, Severity, warning
from ..flake_params import OWN_FLAKE_COLOUR
from ..formulas import apply_op
from ..graphs import graph_params
from ..lexicon import Entry
from ..lexicon_model import normalise
from ..state import Context, MaterialState
from ..tagged import NOTE_CODE
from .base import noun_of
from .coat_layer import apply_coat
from .colours import colour_text, resolve_colour
from .feature_colour import meet, plain_colour, with_shades
from .feature_maps import draw_feature_maps, graphs_of, roles_of
from .noun_words import apply_noun_colour, noun_colour
from .textured_colour import keep_pattern_visible
from .words import COAT_CLASS, apply_adjective, apply_coat_entry, apply_group, group_weight

MISSING = "W120"  # a feature nothing in the stdlib draws yet
SECOND_COAT = "W121"  # a second coat clause
UNUSED = "N121"  # a word of a clause the feature has no use for
AS_COAT = "N123"  # a finish read as a coat
SHADE_DEGREE = "N124"  # a shade before a feature without a colour, read as a degree
OWN_COLOUR = "N125"  # a named colour met the feature's own colour
COLOUR_PARAMS = ("color_r", "color_g", "color_b")


def apply_features(state: MaterialState, ctx: Context, clauses: tuple[ast.Feature, ...]) -> None:
    for clause in clauses:
        if clause.word.unknown or _has_unknown(clause):
            continue  # already reported as an unknown word
        if clause.word.category == "coats":
            _warn_second_coat(state, clause)
            continue
        entry = _by_class(state, ctx, ctx.lexicon.require("features", clause.word.key), clause)
        entry, share = _of_metal(state, ctx, entry, clause)
        apply_feature(state, ctx, entry, clause, share)


def _by_class(state: MaterialState, ctx: Context, entry: Entry, clause: ast.Feature) -> Entry:
    """'olive wood with dark lines' = grain, 'marble with grey lines' = veins: a word that names
    another feature on each class of material (the entry's `by_class`; its `any` on every other
    class), with a note; the entry itself where it names none."""
    by_class = entry.get("by_class", {})
    kind = noun_of(state).get("class")
    other = by_class.get(kind, by_class.get("any"))
    if other is None:
        return entry
    note = f"read '{clause.word.text}' as {other} (on {kind})"
    state.diagnostics.append(Diagnostic(clause.word.span, Severity.NOTE, FEATURE_READING, note))
    return ctx.lexicon.require("features", other)


FEATURE_READING = "N126"  # a feature read as another: flecks of a metal, lines on stone or wood


def _of_metal(state: MaterialState, ctx: Context, entry: Entry, clause: ast.Feature) -> tuple[Entry, float]:
    """'black lacquer with gold flecks': flecks of a metal are flakes of it, not mineral speckles
    (the entry's `of_metal`, at its `of_metal_share` of the clause's weight: flecks are sparse),
    when the clause's colour is a metal's name (a conductor noun of the lexicon: gold, silver,
    copper), with a note; any other clause keeps its entry at its own weight."""
    colour = _colour_of(clause)
    other = entry.get("of_metal")
    if other is None or colour is None or colour.base is None:
        return entry, 1.0
    metal = ctx.lexicon.entry("nouns", colour.base.key)
    if metal is None or metal.get("model") != "conductor" or not _takes(state, ctx, other):
        return entry, 1.0  # 'quartzite with flecks of silver': mica, drawn as speckles
    text = f"{colour_text(colour)} {clause.word.text}"
    state.diagnostics.append(
        Diagnostic(clause.span, Severity.NOTE, FEATURE_READING, f"read '{text}' as {other} of {colour.base.text}")
    )
    return ctx.lexicon.require("features", other), float(entry.get("of_metal_share", 1.0))


def _takes(state: MaterialState, ctx: Context, feature: str) -> bool:
    """Whether the material takes the feature: its adjective's `applies_to` names the material's
    class or noun, or it has none (flakes lie in paint and plastic, not in stone)."""
    adjective_key = ctx.lexicon.require("features", feature).get("adjective")
    classes = ctx.lexicon.require("adjectives", adjective_key).get("applies_to") if adjective_key else None
    noun = noun_of(state)
    return not classes or noun.get("class") in classes or noun.key in classes


def apply_feature(state: MaterialState, ctx: Context, entry: Entry, clause: ast.Feature, share: float = 1.0) -> None:
    if entry.get("missing"):
        state.diagnostics.append(
            warning(clause.span, MISSING, f"'{clause.word.text}': {entry.get('missing')}", (_drawable_hint(ctx),))
        )
    if entry.get("finish"):
        _apply_finish(state, ctx, clause)
        return
    weight = clause_weight(clause, ctx) * share
    colour = _colour_of(clause)
    if colour is not None and not entry.get("colour"):
        degree = _shade_degree(state, ctx, colour, clause)
        if degree is not None:  # 'light scratches', 'a deep grain': a shade is how strong, not a colour
            weight, colour = weight * degree, None
    if entry.get("share") is not None and colour is not None and colour.base is not None and not _see_through(state):
        _mix_in(state, ctx, entry, clause, weight, colour)  # 'grey with a blue tint': a bluish grey
        _report_other_colours(state, clause)
        return
    used_colour = False
    if entry.get("adjective"):
        used_colour = _apply_adjective(state, ctx, entry, clause, weight, colour)
        if entry.get("surface_words"):  # 'a matte glaze': the glaze, then its finish
            clause = _with_surface_words_applied(state, ctx, clause)
    if entry.get("maps"):
        used_colour = _draw_maps(state, ctx, entry, clause, weight, colour) or used_colour
    if entry.get("colour") == "flake" and colour is not None:
        used_colour = _colour_flakes(state, ctx, colour) or used_colour
    if entry.get("coat"):
        apply_coat_entry(state, ctx, entry.get("coat"), f"features.{entry.key}.coat", (clause.word,))
    _report_unused(state, entry, clause, colour if not used_colour else None)
    _report_other_colours(state, clause)


def _colour_flakes(state: MaterialState, ctx: Context, colour: ast.Colour) -> bool:
    """'with gold flakes': the flakes mirror as the named metal does (its measured F0 times its
    tint); another colour ('with red flakes') is their colour as named. False when the material has
    no flakes to colour."""
    if state.params.get("flake_color") is None:
        return False
    metal = ctx.lexicon.entry("nouns", colour.base.key) if colour.base is not None else None
    if metal is not None and metal.get("model") == "conductor" and not colour.shades:
        rgb = [b * f for b, f in zip(metal.get("base_color"), metal.get("f0"))]
        why = f"nouns.{metal.key}: the flakes mirror as {metal.key} does (F0)"
    else:
        rgb = resolve_colour(colour, ctx)
        why = f"colours: {colour_text(colour)} flakes"
    state.record("flake_color", rgb, why, colour.words, source=metal.get("source") if metal is not None else None)
    state.params[OWN_FLAKE_COLOUR] = True
    return True


def clause_weight(clause: ast.Feature, ctx: Context) -> float:
    """The product of the clause's degree words ('a few fine scratches': 0.4 x 0.6)."""
    weight = 1.0
    for group in clause.groups:
        weight *= group_weight(group, ctx)
    return weight


def _shade_degree(state: MaterialState, ctx: Context, colour: ast.Colour, clause: ast.Feature) -> float | None:
    """A shade alone before a feature without a colour is a degree: lighter reads as the adverb
    'slightly', darker as 'very' (their adverbs.toml weights), with a note."""
    if colour.base is not None or colour.noun is not None or not colour.shades:
        return None
    grey = [0.18, 0.18, 0.18]
    lightness = linear_to_oklab(resolve_colour(colour, ctx, start=grey))[0] - linear_to_oklab(grey)[0]
    if abs(lightness) < 1e-6:
        return None
    adverb = "slightly" if lightness > 0 else "very"
    text = colour_text(colour)
    state.diagnostics.append(
        Diagnostic(
            colour.span,
            Severity.NOTE,
            SHADE_DEGREE,
            f"read '{text}' in '{text} {clause.word.text}' as '{adverb}': how strong, not a colour",
        )
    )
    return float(ctx.lexicon.require("adverbs", adverb).get("weight"))


def _has_unknown(clause: ast.Feature) -> bool:
    return any(w.unknown for g in clause.groups for w in (*g.adverbs, *g.adjectives, *_colour_words(g)))


def _colour_words(group: ast.Group) -> tuple[ast.Word, ...]:
    return tuple(w for c in group.colours for w in c.words)


def _colour_of(clause: ast.Feature) -> ast.Colour | None:
    for group in clause.groups:
        if group.colours:
            return group.colours[0]
    return None


def _adverbs_of(clause: ast.Feature) -> tuple[ast.Word, ...]:
    return tuple(w for g in clause.groups for w in g.adverbs)


# ---------------------------------------------------------------- finish: the clause's words are the surface


def _apply_finish(state: MaterialState, ctx: Context, clause: ast.Feature) -> None:
    """'with a matte finish' = matte; 'with a mirror finish' or 'a high polish' (a word that is also an
    adjective, alone with its degree words) = mirror, polished;
    'with a clear finish' on oak = a clear coat ('clear' is said of a coat, not of oak)."""
    coat = _as_coat(state, ctx, clause)
    if coat is not None:
        apply_coat(state, ctx, coat)
        return
    looked = _looked_noun(clause)
    if looked is not None:  # 'with a marble effect': marble's colour and the feature of its pattern
        _draw_look(state, ctx, clause, looked)
        return
    own = None if _describes(clause) else _adjective_named_by(ctx, clause.word)
    if own is not None:
        word = ast.Word(clause.word.text, own.key, "adjectives", clause.word.span)
        group = ast.Group("adjective", _adverbs_of(clause), (), (word,), clause.span)
        apply_adjective(state, ctx, own, group, clause_weight(clause, ctx), "base")
        for said in clause.groups:  # 'white gloss': the colour is the surface's, the gloss is glossy
            if said.colours:
                apply_group(state, ctx, ast.Group("colour", (), said.colours, (), said.span), target="base")
        return
    for group in clause.groups:
        apply_group(state, ctx, group, target="base")


def _looked_noun(clause: ast.Feature) -> ast.Colour | None:
    """The material noun said alone before a finish word ('a marble effect', 'an oak look'), or None."""
    colours = [c for g in clause.groups for c in g.colours]
    if len(colours) != 1 or any(g.adjectives for g in clause.groups):
        return None
    colour = colours[0]
    return colour if colour.noun is not None and colour.base is None and not colour.shades else None


def _draw_look(state: MaterialState, ctx: Context, clause: ast.Feature, colour: ast.Colour) -> None:
    """The look of a noun on this material: its colour, and the feature that draws its pattern (the
    feature whose colour map is the noun's own graph: marble's veins, oak's grain), noted."""
    assert colour.noun is not None
    named = tuple(w for step in state.provenance.get("base_color", []) for w in step.words if w.category == "colours")
    rgb = None if named else noun_colour(ctx, colour)  # 'black marble-effect laminate': black
    if rgb is not None:
        state.record("base_color", rgb, f"nouns.{colour.noun.key}: the look of {colour.noun.text}", (colour.noun,))
    graph = _colour_graph(ctx.lexicon.entry("nouns", colour.noun.key))
    feature = _feature_drawing(ctx, graph) if graph else None
    if feature is not None:
        word = ast.Word(clause.word.text, feature.key, "features", clause.word.span)
        apply_feature(state, ctx, feature, ast.Feature((), word, clause.span))
        if named:  # 'black marble-effect laminate': the named colour as the drawn pattern can carry it
            state.params["base_color"] = keep_pattern_visible(
                state, ctx, state.params["base_color"], named, noun_of(state).key
            )
    drawn = (["its colour"] if rgb is not None else []) + ([f"its {feature.key}"] if feature is not None else [])
    said = " and ".join(drawn) or "nothing of it (the line names the colour; no pattern to draw)"
    message = f"read '{colour.noun.text} {clause.word.text}' as the look of {colour.noun.key}: {said}"
    state.diagnostics.append(Diagnostic(clause.span, Severity.NOTE, NOTE_CODE, message))


def _feature_drawing(ctx: Context, graph: str) -> Entry | None:
    """The feature whose colour map this graph draws ('marble' -> veins), or None."""
    return next((e for e in ctx.lexicon.all_of("features").values() if _colour_graph(e) == graph), None)


def _colour_graph(entry: Entry | None) -> str | None:
    """The graph an entry's base colour map is drawn by, or None."""
    ref = ((entry.get("maps") or {}).get("base_color") or {}) if entry is not None else {}
    graph = ref.get("graph")
    return str(graph) if graph else None


def _describes(clause: ast.Feature) -> bool:
    """Whether the clause has describing words of its own: they are the surface ('a satin polish' =
    satin), else a finish word that is also an adjective is ('a high polish' = polished; a colour
    beside it is the surface's colour: 'a white gloss' = white and glossy)."""
    return any(g.adjectives for g in clause.groups)


def _as_coat(state: MaterialState, ctx: Context, clause: ast.Feature) -> ast.Coat | None:
    """The clause as a coat clause when its finish word is also a coat and an adjective of it is
    said of a coat but not of this material ('a clear finish' on oak), with a note."""
    coat_entry = _entry_named_by(ctx, clause.word, "coats")
    if coat_entry is None:
        return None
    material = noun_of(state)
    for word in (w for g in clause.groups for w in g.adjectives):
        classes = ctx.lexicon.require("adjectives", word.key).get("applies_to") or []
        if COAT_CLASS in classes and material.get("class") not in classes and material.key not in classes:
            state.diagnostics.append(
                Diagnostic(
                    clause.span,
                    Severity.NOTE,
                    AS_COAT,
                    f"read '{_clause_text(clause)}' as a coat: '{word.text}' is said of a coat, not of {material.key}",
                )
            )
            return ast.Coat(
                clause.groups, ast.Word(clause.word.text, coat_entry.key, "coats", clause.word.span), clause.span
            )
    return None


def _clause_text(clause: ast.Feature) -> str:
    words = [w for g in clause.groups for w in (*g.adverbs, *_colour_words(g), *g.adjectives)]
    return " ".join(w.text for w in (*words, clause.word))


def _entry_named_by(ctx: Context, word: ast.Word, category: str) -> Entry | None:
    for entry in ctx.lexicon.lookup(normalise(word.text)):
        if entry.category == category:
            return entry
    return None


def _adjective_named_by(ctx: Context, word: ast.Word) -> Entry | None:
    return _entry_named_by(ctx, word, "adjectives")


# ---------------------------------------------------------------- a colour mixed in


def _mix_in(
    state: MaterialState, ctx: Context, entry: Entry, clause: ast.Feature, weight: float, colour: ast.Colour
) -> None:
    """The clause's colour mixed into an opaque material's base colour in OKLab by the feature's
    share at the clause's and the feature's weight ('a blue tint' moves grey 0.2 of the way to
    blue, 'a hint of' 0.1): the material keeps its own colour, tinted."""
    current = state.params.get("base_color")
    target = resolve_colour(colour, ctx, start=current)
    if not isinstance(current, list):
        current = target
    amount, weight = float(entry.get("share")), weight * entry.get("weight", 1.0)
    value = apply_op("mix", current, target, weight, amount)
    words = (*_adverbs_of(clause), *colour.words, clause.word)
    rule = f"features.{entry.key}: {min(1.0, amount * weight):.3g} of the way to '{colour_text(colour)}' in OKLab"
    state.record("base_color", value, rule, words)


def _see_through(state: MaterialState) -> bool:
    """A glass model's base colour is its transmittance: a tint is all the colour it has."""
    return bool(state.params.get("model", noun_of(state).get("model")) == "glass")


# ---------------------------------------------------------------- a feature an adjective draws


def _apply_adjective(
    state: MaterialState, ctx: Context, entry: Entry, clause: ast.Feature, weight: float, colour: ast.Colour | None
) -> bool:
    """Apply the adjective at the clause's weight; a colour qualifies it when the entry says "base"."""
    adjective = ctx.lexicon.require("adjectives", entry.get("adjective"))
    qualifier = (colour,) if colour is not None and entry.get("colour") == "base" else ()
    word = ast.Word(clause.word.text, adjective.key, "adjectives", clause.word.span)
    group = ast.Group("adjective", _adverbs_of(clause), qualifier, (word,), clause.span)
    applied = len(state.applied)
    apply_adjective(state, ctx, adjective, group, weight * entry.get("weight", 1.0), "base")
    if len(state.applied) == applied:  # it does not apply to this material (W102 says so)
        return bool(qualifier)
    if qualifier and colour is not None and colour.noun is not None and colour.base is None:
        apply_noun_colour(state, ctx, colour, "base_color")  # 'an amber tint': amber's own colour
    return bool(qualifier)


# ---------------------------------------------------------------- a feature with maps of its own


def _draw_maps(
    state: MaterialState, ctx: Context, entry: Entry, clause: ast.Feature, weight: float, colour: ast.Colour | None
) -> bool:
    """Draw the entry's maps; a graph the material already has keeps its map, scaled by the weight.
    Returns whether the clause's colour went to the maps."""
    draw_feature_maps(state, ctx, entry, weight, (*_adverbs_of(clause), clause.word))
    if colour is None or entry.get("colour") != "map":
        return False
    for graph in graphs_of(entry):
        _name_colour(state, ctx, entry, graph, colour, clause)
    return True


def _name_colour(
    state: MaterialState, ctx: Context, entry: Entry, graph: str, colour: ast.Colour, clause: ast.Feature
) -> None:
    """The clause's colour as the graph's named colour: 'grey' veins; 'dark' alone darkens the graph's
    own; a colour of the own colour's hue family keeps the own ('a green patina' is verdigris) and one
    of another hue keeps a share of its lightness and chroma ('gold veins'): passes/feature_colour.py."""
    ranges = graph_params(graph)
    if not all(name in ranges for name in COLOUR_PARAMS):
        return
    own = [ranges[name][2] for name in COLOUR_PARAMS]
    rule = f"features: {colour_text(colour)} {clause.word.text}"
    named = _met_colour(state, ctx, entry, own, colour, clause)
    if named is None:
        return  # the own colour as it is: the map keeps its texture
    rgb = [min(1.0, max(0.0, float(v))) for v in named]
    for role in roles_of(state, graph):
        params: dict[str, Any] = dict(state.maps[role].get("params", {}))
        params.update(zip(COLOUR_PARAMS, rgb, strict=True))
        params["color_amount"] = 1.0
        state.maps[role] = {**state.maps[role], "params": params}
        state.note(f"maps.{role}", graph, rule, colour.words)


def _met_colour(
    state: MaterialState, ctx: Context, entry: Entry, own: list[float], colour: ast.Colour, clause: ast.Feature
) -> list[float] | None:
    """The clause's colour after its colour word met the map's own colour, then its shades; None when
    the own colour stays as it is."""
    named = noun_colour(ctx, colour) or resolve_colour(colour, ctx, start=own)
    hue_family, keep_own = entry.get("hue_family"), entry.get("keep_own")
    plain = plain_colour(ctx, colour)
    if hue_family is None or keep_own is None or plain is None:
        return named  # no colour word ('a dark patina'), or a feature without the rule
    meeting = meet(own, plain.rgb, float(hue_family), float(keep_own))
    if meeting.how == "named":
        return named
    said, feature = _said(colour, clause), clause.word.text
    made = f", made {' '.join(plain.shades)}" if plain.shades else ""
    if meeting.how == "mixed":
        message = (
            f"read '{said}' as {plain.word}'s hue, keeping {keep_own:g} of the own lightness and chroma "
            f"of the {feature}{made}"
        )
    else:
        message = f"read '{said}' as the own colour of the {feature} ({plain.word} is its hue family){made}"
    state.diagnostics.append(Diagnostic(colour.span, Severity.NOTE, OWN_COLOUR, message))
    if meeting.how == "own" and not plain.shades:
        return None
    return with_shades(ctx, meeting.rgb, plain.shades)


def _said(colour: ast.Colour, clause: ast.Feature) -> str:
    """The colour and the feature as written: 'gold veins', 'veins of gold'."""
    text = colour_text(colour)
    if colour.span.start > clause.word.span.start:
        return f"{clause.word.text} of {text}"
    return f"{text} {clause.word.text}"


# ---------------------------------------------------------------- what the clause said that nothing used


def _with_surface_words_applied(state: MaterialState, ctx: Context, clause: ast.Feature) -> ast.Feature:
    """The clause's adjectives applied to the surface (after the feature's own adjective), and the
    clause without them (they are used: no N121)."""
    kept = []
    for group in clause.groups:
        if group.adjectives:
            said = ast.Group("adjective", group.adverbs, (), group.adjectives, group.span)
            apply_group(state, ctx, said, target="base")
        kept.append(ast.Group(group.kind, group.adverbs, group.colours, (), group.span))
    return ast.Feature(tuple(kept), clause.word, clause.span)


def _report_unused(state: MaterialState, entry: Entry, clause: ast.Feature, colour: ast.Colour | None) -> None:
    unused = [w for g in clause.groups for w in g.adjectives]
    if colour is not None:
        unused += list(colour.words)
    if unused:
        text = " ".join(w.text for w in unused)
        state.diagnostics.append(
            Diagnostic(
                unused[0].span.to(unused[-1].span),
                Severity.NOTE,
                UNUSED,
                f"'{text}' says nothing the {clause.word.text} can show: left out",
                (f"features.{entry.key} takes degree words ('a few', 'fine', 'strong'){_colour_hint(entry)}",),
            )
        )


def _report_other_colours(state: MaterialState, clause: ast.Feature) -> None:
    """'red and black speckles': a feature is drawn in one colour, the first; the others are left out, noted."""
    others = [c for g in clause.groups for c in g.colours][1:]
    if not others:
        return
    text = ", ".join(" ".join(w.text for w in c.words) for c in others)
    span = others[0].span.to(others[-1].span)
    message = f"one colour is drawn for the {clause.word.text}, the first: '{text}' left out"
    state.diagnostics.append(Diagnostic(span, Severity.NOTE, UNUSED, message))


def _colour_hint(entry: Entry) -> str:
    return " and a colour" if entry.get("colour") else ""


def _drawable_hint(ctx: Context) -> str:
    drawable = sorted(e.key for e in ctx.lexicon.all_of("features").values() if not e.get("missing"))
    return "features drawn today: " + ", ".join(drawable)


def _warn_second_coat(state: MaterialState, clause: ast.Feature) -> None:
    first = state.selection.coat
    kept = f"'{first.coat.text}'" if first is not None else "the first coat"
    state.diagnostics.append(
        warning(
            clause.span,
            SECOND_COAT,
            f"a second coat '{clause.word.text}': a material has one coat, {kept} is kept",
            ("give the other coat its own material line, or use 'or' for alternatives",),
        )
    )
