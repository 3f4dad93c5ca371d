"""A comparative said against a named finish ('shinier than satin', 'glossier than matte', 'duller
than gloss', issue #14): a finish past that one, toward the next finish of the lexicon in the
comparative's direction, not a step from it. The finishes are settings.toml `finish_ladder`
(mirror 0.01, glossy 0.08, satin 0.35, matte 0.8: the roughness each adjective sets), with 0 and 1
at the ends; 'shinier than satin' lies halfway from satin to the next glossier finish (0.35 ->
glossy 0.08: 0.215, a glossy surface, as a person comparing with satin means), 'a bit shinier than
satin' a quarter of the way (the adverbs' weight scales the half, at most the whole way), 'glossier
than mirror' halfway to 0. Any finish word may be compared with ('than eggshell': satin's value). The tagger reads the finish after 'than' as the finish alone
(cnlmc.tagger Tagger._compared_finish: not the cloth 'satin').
"""

from __future__ import annotations

from .. import ast
from ..lexicon import Entry
from ..state import Context, MaterialState
from .bracket import Move
from .refine_target import item_words, move_sigma_too, refine_weight, surface

ROUGHNESS = "roughness"
HALF = 0.5  # of the way to the next finish, for a comparative said plainly


def beyond_finish(
    state: MaterialState, ctx: Context, item: ast.RefineItem, said: ast.Material | ast.Refinement | None = None
) -> bool:
    """Set roughness past the finish the comparative is said against (see the module doc); False
    when the item is no roughness comparative or no finish follows its 'than'. `said`: the line the
    item stands in (the material's own line when None)."""
    entry = ctx.lexicon.require("refinements", item.word.key)
    if entry.get("target") != ROUGHNESS:
        return False
    finish = _finish_after_than(said if said is not None else state.selection, ctx, item)
    if finish is None:
        return False
    value = float(ctx.lexicon.require("adjectives", finish.key).set_value(ROUGHNESS))
    direction = int(entry.get("direction"))
    past = [v for v in finishes(ctx) if (v - value) * direction > 1e-9]
    end = (min(past) if direction > 0 else max(past)) if past else (1.0 if direction > 0 else 0.0)
    share = min(HALF * refine_weight(item, ctx), 1.0)
    new = round(value + (end - value) * share, 4)
    holder, key, limits = surface(state, ROUGHNESS)
    holder[ROUGHNESS] = new
    rule = (
        f"refinements.{item.word.key} than '{finish.text}': {share:g} of the way from {value} to the next finish, {end}"
    )
    state.note(key, new, rule, item_words(item))
    move_sigma_too(state, key, Move(direction, lambda _x: new, 1.0, limits), item_words(item), rule)
    return True


def _finish_after_than(said: ast.Material | ast.Refinement, ctx: Context, item: ast.RefineItem) -> ast.Word | None:
    """The finish adjective right after the item's comparison word ('shinier than satin': the
    item's target, or a describing word of the line), or None."""
    formation = ctx.lexicon.caches.word_formation
    if formation is None:
        return None
    line_start = said.span.start - said.span.col + 1
    target = [item.target] if isinstance(item.target, ast.Word) and item.target.category == "adjectives" else []
    nouns = said.nouns if isinstance(said, ast.Material) else ()
    for word in [*target, *(w for group in said.groups for w in group.adjectives)]:
        if any(noun.span.start >= word.span.end for noun in nouns):
            continue  # 'glossier than a satin black plastic': compared with a material, not a finish
        between = said.text[item.word.span.end - line_start : word.span.start - line_start].lower().split()
        if between and between[0] in formation.rules.comparison and len(between) <= 2:
            if ctx.lexicon.require("adjectives", word.key).set_value(ROUGHNESS) is not None:
                return word
    return None


def finishes(ctx: Context) -> tuple[float, ...]:
    """The roughness values the ladder's finish words set (settings.toml finish_ladder), ascending."""
    values = []
    for key in ctx.settings.get("finish_ladder", ()):
        value = finish_roughness(ctx.lexicon.entry("adjectives", key))
        if value is not None:
            values.append(value)
    return tuple(sorted(set(values)))


def finish_roughness(entry: Entry | None) -> float | None:
    """The roughness a finish adjective sets for any surface ('satin': 0.35), or None for any other
    entry (a word that only adds to roughness, or one that applies to some materials only)."""
    if entry is None or entry.category != "adjectives" or entry.get("applies_to"):
        return None
    value = entry.set_value(ROUGHNESS)
    return None if value is None else float(value)
