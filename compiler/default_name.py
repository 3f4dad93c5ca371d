"""A material's default name: every word the phrase describes it with, in phrase order.

'oak with a glossy white varnish' -> oak_with_glossy_white_varnish (not 'oak');
'heavily rusted iron' -> heavily_rusted_iron; 'lightly brushed, blue anodized aluminum' ->
lightly_brushed_blue_anodized_aluminum. Of alternatives ('red or blue') the first is named: the
variant suffix (__red, __blue) names each choice. Articles and punctuation are not words of it.
"""

from __future__ import annotations

from collections.abc import Iterable

from . import ast

__all__ = ["name_words"]


def name_words(material: ast.Material) -> list[str]:
    """The words of a material's default name (before cnlmc.passes.variants.identifier)."""
    words = _refinement_words(material.refinements) if material.refinements else []
    words += _group_words(material.groups)
    words.append(material.nouns[0].text)
    if material.coat is not None or material.features:  # most phrases have no 'with' clause
        words += _clause_words(material)
    return words


def _clause_words(material: ast.Material) -> list[str]:
    """'with' then each clause's words in phrase order, the later ones after 'and'."""
    clauses = [(c.span.start, c.groups, c.coat) for c in (material.coat,) if c is not None]
    clauses += [(f.span.start, f.groups, f.word) for f in material.features]  # 'marble with grey veins'
    words: list[str] = []
    for index, (_start, groups, word) in enumerate(sorted(clauses, key=lambda c: c[0])):
        words += ["with" if index == 0 else "and", *_group_words(groups), word.text]
    return words


def _group_words(groups: Iterable[ast.Group]) -> list[str]:
    """Each group's adverbs, its first colour (shades and all) and its first adjective."""
    words: list[str] = []
    for group in groups:  # loops, not comprehensions: in Python 3.11 each comprehension is a call
        for adverb in group.adverbs:
            words.append(adverb.text)
        if group.colours:
            for word in group.colours[0].words:
                words.append(word.text)
        if group.adjectives:
            words.append(group.adjectives[0].text)
    return words


def _refinement_words(items: Iterable[ast.RefineItem]) -> list[str]:
    """An inline comparative's words ('slightly darker oak' -> slightly, darker; 'more grain oak')."""
    words: list[str] = []
    for item in items:
        words += [w.text for w in item.adverbs]
        words.append(item.word.text)
        if isinstance(item.target, ast.Colour):
            words += [w.text for w in item.target.words]
        elif item.target is not None:
            words.append(item.target.text)
    return words
