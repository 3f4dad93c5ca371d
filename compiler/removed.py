"""The material above with words taken off ('lose the brushed look': cnlmc.removal): its
describing words, features, coat and colours that the removed words name go, the rest stays. A
feature and the adjective it draws ('scratches' and 'scratched', features.toml `adjective`) are one
thing here: 'no scratches' takes 'scratched' off too."""

from __future__ import annotations

from . import ast
from .lexicon import Lexicon

__all__ = ["much_less", "step_away", "without_words"]


def without_words(material: ast.Material, removed: tuple[ast.Word, ...], lexicon: Lexicon) -> ast.Material | None:
    """The material without the removed words; None when it has none of them (the line then
    reaches the refinement pass, which says so: W122)."""
    keys = _named(removed, lexicon)
    groups = tuple(g for g in (_group_without(g, keys) for g in material.groups) if g is not None)
    features = tuple(f for f in material.features if not _feature_named(f, keys, lexicon))
    coat = None if material.coat is not None and material.coat.coat.key in keys else material.coat
    if groups == material.groups and features == material.features and coat is material.coat:
        return None
    return ast.Material(
        material.name, groups, material.nouns, coat, material.span, material.text, material.refinements, features
    )


def _named(removed: tuple[ast.Word, ...], lexicon: Lexicon) -> frozenset[str]:
    """The keys the removed words name, with the adjective each removed feature draws."""
    keys = {w.key for w in removed}
    for word in removed:
        entry = lexicon.entry("features", word.key) if word.category == "features" else None
        if entry is not None and entry.get("adjective"):
            keys.add(str(entry.get("adjective")))
    return frozenset(keys)


def _group_without(group: ast.Group, keys: frozenset[str]) -> ast.Group | None:
    """The group without the named adjectives and colours; None when nothing of it is left (its
    adverbs went with its words: 'lightly' of 'lightly brushed')."""
    adjectives = tuple(w for w in group.adjectives if w.key not in keys)
    colours = tuple(c for c in group.colours if c.base is None or c.base.key not in keys)
    if adjectives == group.adjectives and colours == group.colours:
        return group
    if not adjectives and not colours:
        return None
    kind = "adjective" if adjectives else "colour"
    return ast.Group(kind, group.adverbs if adjectives else (), colours, adjectives, group.span)


def _feature_named(feature: ast.Feature, keys: frozenset[str], lexicon: Lexicon) -> bool:
    if feature.word.key in keys:
        return True
    entry = lexicon.entry(feature.word.category, feature.word.key)
    return entry is not None and str(entry.get("adjective", "")) in keys


def much_less(word: ast.Word, said: ast.Word | None = None) -> ast.RefineItem:
    """'much less <property>', said by the removal's word (its span and text), or by the removal
    phrase `said` ('no' of 'oak, no grain', whose words name the material: oak_no_grain): what
    taking off a property the material's noun brings means ('no veins' under marble); of a colour,
    its hue moved away ('oak, not orange')."""
    target: ast.Word | ast.Colour = ast.Colour((), word, word.span) if word.category == "colours" else word
    if said is None:
        less = ast.Word(word.text, "less", "refinements", word.span)
        return ast.RefineItem(less, target, word.span, (ast.Word(word.text, "much", "adverbs", word.span),))
    much = ast.Word("", "much", "adverbs", said.span)  # said by the phrase: no word of the name
    return ast.RefineItem(said, target, said.span.to(word.span), (much,))


def step_away(word: ast.Word, said: ast.Word | None = None) -> ast.RefineItem:
    """'less <colour>', said by the removal phrase `said` ('not' of 'not jet black' after 'black':
    a step away from the extreme the colour already is, cnlmc.line_parts), or by the colour word."""
    target = ast.Colour((), word, word.span)
    if said is None:
        return ast.RefineItem(ast.Word(word.text, "less", "refinements", word.span), target, word.span)
    return ast.RefineItem(said, target, said.span.to(word.span))
