"""Refinement: "darker", "less diffuse", "stronger brushing" change the material above.

The bracket rule (docs/refinement.md, passes/bracket.py): each target keeps the interval the
user has narrowed it to. "less X" says the current value is too high (it becomes the upper
bound), "more X" that it is too low (the lower bound). With both bounds known the new value is
their midpoint; otherwise it moves one step. Paper §4.2: m 0.3 -less diffuse-> 0.2 -more
diffuse-> 0.25; blue (0,0,1) -darker-> (0,0,0.5).

Every target moves relative to where it is now, whether or not the phrase used the word the
refinement names ('less glossy' on any plastic is rougher); gloss and roughness act on the
surface one sees (the coat's, when there is one). Adverbs scale the step ('much rougher': two
steps, 'slightly darker': half of one). Colour refinements live in passes/refine_colour.py.
"""

from __future__ import annotations

import math

from .. import ast
from ..diagnostics import Diagnostic, Severity, warning
from ..removed import much_less
from ..state import Context, MaterialState
from ..tagged import NOTE_CODE
from .base import colour_seen_through
from .coats import apply_clauses
from .colours import colour_text, resolve_colour
from .finish_ladder import beyond_finish
from .refine_colour import refine_colour, refine_named_colour
from .refine_effects import brings_treatment, refine_adjective
from .refine_missing_map import add_missing_map
from .refine_property import acted_on, refine_property
from .refine_target import item_words, note, refine_weight
from .words import apply_described, apply_group

__all__ = ["apply_inline_refinements", "apply_refinement", "apply_refinement_line", "refine_property"]


def apply_inline_refinements(state: MaterialState, ctx: Context) -> MaterialState:
    """'shinier aluminum', 'lighter oak': a comparative written before the material is one
    refinement of the material the rest of the phrase names. A comparative whose target a
    comparison word follows ('more yellow than white plastic', 'dunkler als Eiche') moves the
    material named after that word as the refinement line would: its target is only what it
    changes. Otherwise the word after the comparative is part of the material too where the
    material needs it: any word after a comparative that names
    its own target ('brighter red plastic' = red plastic, then brighter), a colour after 'more'
    ('deeper blue velvet' = blue velvet, then more blue) and a treatment ('more brushed steel' =
    brushed steel, then more brushed). A colour after 'less' is what is taken from the material
    ('less yellow gold' is gold, less yellow) and a gloss word after 'more' / 'less' is only the
    refinement's target ('less glossy plastic' is plastic, a step less glossy)."""
    for item in state.selection.refinements:
        if beyond_finish(state, ctx, item):  # 'shinier than satin', 'red paint, shinier than satin'
            continue
        if item.target is not None and _said_after_material(state.selection, item.target):
            item = named_first(state, ctx, item)  # 'walnut, more red' moves walnut as the line 'more red'
        elif item.target is not None and _describes_material(state, ctx, item):
            apply_group(state, ctx, _as_group(item.target), target="base")
        if not add_missing_map(state, ctx, item):  # 'rustier iron' = slightly rusty iron
            mark = len(state.diagnostics)
            apply_refinement(state, ctx, item)
            _none_as_said(state, ctx, item, mark)
    return state


#: what a map refinement says when the material has no map for it (passes/refine_property.py)
NOTHING_TO_ACT_ON = "W106"


def _none_as_said(state: MaterialState, ctx: Context, item: ast.RefineItem, mark: int) -> None:
    """'steel without any scratches', 'oak, no knots': a removal said with the material of a map it
    has none of is already as said: a note, not the warning a change line gets ('less grain' under
    steel: W106). Only for the removal phrase's own reading (its word is no comparative)."""
    if item.word.key != "less" or any(e.key == "less" for e in ctx.lexicon.lookup((item.word.text.lower(),))):
        return  # the comparative said as such ('less', 'fewer'): a change, its warning stays
    for i in range(mark, len(state.diagnostics)):
        found = state.diagnostics[i]
        if found.code == NOTHING_TO_ACT_ON:
            has_none = found.message.split(": ", 1)[-1]
            message = f"{has_none}: none to take off, as '{item.word.text}' says"
            state.diagnostics[i] = Diagnostic(found.span, Severity.NOTE, NOTE_CODE, message)


def _said_after_material(material: ast.Material, target: ast.Word | ast.Colour) -> bool:
    """Whether a comparative's target comes after the material's nouns ('walnut, more red', the
    parts after the material that cnlmc.line_parts reads): it changes the material as the same
    change line would, and is not one of its describing words."""
    return bool(material.nouns) and target.span.start > max(noun.span.end for noun in material.nouns)


def _describes_material(state: MaterialState, ctx: Context, item: ast.RefineItem) -> bool:
    target = item.target
    assert target is not None
    if _compared(state.selection, ctx, target.span.end):
        return False  # 'more yellow than white plastic': white plastic, then the line 'more yellow'
    entry = ctx.lexicon.require("refinements", item.word.key)
    if isinstance(target, ast.Colour):  # 'deeper blue velvet' is blue velvet; 'less yellow gold' is gold
        return bool(entry.get("target") != "any" or entry.get("direction") > 0)
    assert isinstance(target, ast.Word), item
    if target.category != "adjectives":
        return False  # a property ('more grain oak') is only what the comparative changes
    if entry.get("target") != "any":
        return True
    return brings_treatment(ctx.lexicon.require("adjectives", target.key))


def _compared(material: ast.Material, ctx: Context, end: int) -> bool:
    """Whether the word after offset `end` of the phrase is a comparison word ('than', 'als': the
    word formation rules; the tagger read it as the inline comparative and dropped it)."""
    formation = ctx.lexicon.caches.word_formation
    if formation is None:
        return False  # the tagger reads a comparison word by these rules, so none was read
    line_start = material.span.start - material.span.col + 1  # `text` is the whole line
    after = material.text[end - line_start :].split(None, 1)
    return bool(after) and after[0].lower() in formation.rules.comparison


def _as_group(target: ast.Word | ast.Colour) -> ast.Group:
    if isinstance(target, ast.Colour):
        return ast.Group("colour", (), (target,), (), target.span)
    return ast.Group("adjective", (), (), (target,), target.span)


def apply_refinement_line(state: MaterialState, ctx: Context, line: ast.Refinement) -> None:
    """A refinement line: its items in order ('darker, less glossy'), or its 'with' clauses
    ('with a glossy varnish' below 'walnut' adds the coat; passes/coats.py)."""
    if line.groups:  # 'make it blue': the describing words apply to the material as it is, then
        apply_described(state, ctx, line.groups)  # the comparatives said with them ('a bit darker, like cream')
    items = [item for item in line.items if not beyond_finish(state, ctx, item, line)]  # 'shinier than satin'
    if items and items[-1].target is not None:  # 'a darker, moodier green': the green first, then both steps
        items[-1] = named_first(state, ctx, items[-1])
    for item in items:
        apply_refinement(state, ctx, item)
    if line.removed:  # reached here only when the material above has none of them
        _nothing_removed(state, ctx, line)
    if line.coat is not None or line.features:
        apply_clauses(state, ctx, line.coat, line.features)


def named_first(state: MaterialState, ctx: Context, item: ast.RefineItem) -> ast.RefineItem:
    """A change line's comparative with a target it does not step toward, said as what the
    material becomes, then the step: 'a lighter blue' under red plastic is blue, then lighter (the
    paper's 'darker blue' under blue steps the blue, and 'a darker grey' under dark grey steps the
    dark grey: a colour of the same hue family, colour_rules.toml shade_hue_degrees, is only
    stepped); 'glossier satin' under oak (as 'somewhere between satin and gloss' reads) is satin,
    then glossier. Returns the item to apply (without its target when the target was applied)."""
    entry = ctx.lexicon.require("refinements", item.word.key)
    target = item.target
    if isinstance(target, ast.Colour) and entry.get("target") == "colour" and target.base is not None:
        if not _other_colour(state, ctx, target):
            return item
        apply_described(state, ctx, (ast.Group("colour", (), (target,), (), target.span),))
    elif isinstance(target, ast.Word) and target.category == "adjectives" and entry.get("target") == "roughness":
        if ctx.lexicon.require("adjectives", target.key).set_value("roughness") is None:
            return item
        apply_described(state, ctx, (ast.Group("adjective", (), (), (target,), target.span),))
    else:
        return item
    named = colour_text(target) if isinstance(target, ast.Colour) else target.text
    state.diagnostics.append(
        note(item.span, NOTE_CODE, f"read '{item.word.text} {named}' as {named}, then {item.word.text}")
    )
    return ast.RefineItem(item.word, None, item.span, item.adverbs)


def _other_colour(state: MaterialState, ctx: Context, target: ast.Colour) -> bool:
    """Whether the named colour is of another hue family than the material's (one of the two has a
    hue and the other none, or their OKLCh hues lie further apart than a shade moves one)."""
    from ..colour import hue_gap, linear_to_oklab
    from ..lexicon_load import colour_rules

    rules = colour_rules()
    current = state.params.get("base_color")
    if not isinstance(current, list):
        return False
    named, least = resolve_colour(target, ctx), float(rules["shade_hue_min_chroma"])
    gap = hue_gap(current, named, least)
    if gap is None:  # one of the two, or both, a grey: another family when only one has a hue
        chroma = [math.hypot(*linear_to_oklab(c)[1:]) for c in (current, named)]
        return (chroma[0] >= least) != (chroma[1] >= least)
    return gap > float(rules["shade_hue_degrees"])


def _nothing_removed(state: MaterialState, ctx: Context, line: ast.Refinement) -> None:
    """'lose the shine' under a material without 'shiny': its comparatives applied (less gloss), a
    note; a property its noun brings ('no veins' under marble), or a colour whose hue the material
    has ('not orange' under oak): much less of it, a note; with neither ('no rust' under clean
    steel), W122."""
    listed = ", ".join(dict.fromkeys(f"'{w.text}'" for w in line.removed))
    properties = [w for w in line.removed if w.category == "properties" and _acts(state, ctx, w)]
    properties += [w for w in line.removed if w.category == "colours" and _has_hue_of(state, ctx, w)]
    if not line.items and properties:
        for word in properties:
            apply_refinement(state, ctx, much_less(word))
        message = f"no word of the material above says {listed}, its material does: read as much less of it"
        state.diagnostics.append(Diagnostic(line.span, Severity.NOTE, NOTE_CODE, message))
        return
    if line.items:
        message = f"the material above has no {listed} to take off: read as less of it"
        state.diagnostics.append(Diagnostic(line.span, Severity.NOTE, NOTE_CODE, message))
        return
    hint = "name what the material has, e.g. 'lose the brushing' under 'brushed steel'"
    state.diagnostics.append(warning(line.span, "W122", f"the material above has no {listed} to take off", (hint,)))


def _has_hue_of(state: MaterialState, ctx: Context, word: ast.Word) -> bool:
    """Whether the material's colour has some of the named colour's hue ('not orange' under oak:
    its hue moves away; under navy there is none to take off)."""
    from ..colour import linear_to_oklab
    from .colour_steps import hue_share

    current = state.params.get("base_color")
    if not isinstance(current, list):
        return False
    _l, a, b = linear_to_oklab(resolve_colour(ast.Colour((), word, word.span), ctx))
    return math.hypot(a, b) > NO_HUE and hue_share(current, (a, b)) > NO_HUE


NO_HUE = 0.02  # OKLab chroma (or share of a hue) below which a colour has none of it (our choice)


def _acts(state: MaterialState, ctx: Context, word: ast.Word) -> bool:
    """Whether the property has something to act on: a parameter, or a map of the material."""
    prop = ctx.lexicon.require("properties", word.key)
    return prop.get("map_param") is None or bool(acted_on(state, prop))


def apply_refinement(state: MaterialState, ctx: Context, item: ast.RefineItem) -> None:
    entry = ctx.lexicon.require("refinements", item.word.key)
    direction, target = entry.get("direction"), entry.get("target")
    if item.word.unknown or (item.target is not None and _is_unknown(item.target)):
        return
    weight = refine_weight(item, ctx)
    if _moves_colour(ctx, target, item):  # a glass's colour, restated as seen through 5 cm first
        colour_seen_through(state, item_words(item))
    if target == "colour":
        refine_colour(state, entry, item, direction, weight)
    elif target != "any":
        refine_property(state, ctx, ctx.lexicon.require("properties", target), item, direction, weight)
    elif item.target is None:
        state.diagnostics.append(
            warning(
                item.span,
                "W104",
                f"'{item.word.text}' of what?",
                ("name what to change, e.g. 'more grain' or 'less diffuse'",),
            )
        )
    else:
        _refine_named(state, ctx, item, direction, weight)


def _moves_colour(ctx: Context, target: str | None, item: ast.RefineItem) -> bool:
    """Whether the refinement moves the base colour: a colour comparative ('darker'), a colour named
    ('more red') or the colour property ('more saturated')."""
    if target == "colour" or isinstance(item.target, ast.Colour):
        return True
    if target == "any":  # 'more <property>': the property it names
        named = item.target
        target = named.key if isinstance(named, ast.Word) and named.category == "properties" else None
    prop = ctx.lexicon.entry("properties", target) if target else None
    return prop is not None and prop.get("param") == "saturation"


def _is_unknown(target: ast.Word | ast.Colour) -> bool:
    words = target.words if isinstance(target, ast.Colour) else (target,)
    return any(w.unknown for w in words)


def _refine_named(state: MaterialState, ctx: Context, item: ast.RefineItem, direction: int, weight: float) -> None:
    target = item.target
    if isinstance(target, ast.Colour):
        refine_named_colour(state, ctx, item, direction, weight)
        return
    assert isinstance(target, ast.Word), item
    if target.category == "properties":
        refine_property(state, ctx, ctx.lexicon.require("properties", target.key), item, direction, weight)
    else:
        refine_adjective(state, ctx, ctx.lexicon.require("adjectives", target.key), item, direction, weight)
