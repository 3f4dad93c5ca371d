"""A material's default name: every word the phrase describes it with, in phrase order.

'oak with a glossy white varnish' -> oak_with_glossy_white_varnish (not 'oak');
'heavily rusted iron' -> heavily_rusted_iron; 'lightly brushed, blue anodized aluminum' ->
lightly_brushed_blue_anodized_aluminum. Of alternatives ('red or blue') the first is named: the
variant suffix (__red, __blue) names each choice. Articles and punctuation are not words of it.
"""

from __future__ import annotations

from collections.abc import Iterable

from . import ast
from .spans import Span
from .tagged import written_words

__all__ = ["name_words"]


def name_words(material: ast.Material) -> list[str]:
    """The words of a material's default name (before cnlmc.passes.variants.identifier)."""
    words = _refinement_words(material.refinements) if material.refinements else []
    words += _group_words(material.groups)
    words.append(material.nouns[0])
    if material.coat is not None or material.features:  # most phrases have no 'with' clause
        words += _clause_words(material)
    return [word for word in written_words(words) if word]  # a word said by a phrase has no text


def _clause_words(material: ast.Material) -> list[ast.Word]:
    """'with' then each clause's words in phrase order, the later ones after 'and'."""
    clauses = [(c.span.start, c.groups, c.coat) for c in (material.coat,) if c is not None]
    clauses += [(f.span.start, f.groups, f.word) for f in material.features]  # 'marble with grey veins'
    words: list[ast.Word] = []
    for index, (start, groups, word) in enumerate(sorted(clauses, key=lambda c: c[0])):
        joining = ast.Word("with" if index == 0 else "and", "", "", Span(start, start, 0, 0))
        words += [joining, *_group_words(groups), word]
    return words


def _group_words(groups: Iterable[ast.Group]) -> list[ast.Word]:
    """Each group's adverbs, its first colour (shades and all) and its first adjective."""
    words: list[ast.Word] = []
    for group in groups:  # loops, not comprehensions: in Python 3.11 each comprehension is a call
        words += group.adverbs
        if group.colours:
            words += group.colours[0].words
        if group.adjectives:
            words.append(group.adjectives[0])
    return words


def _refinement_words(items: Iterable[ast.RefineItem]) -> list[ast.Word]:
    """An inline comparative's words ('slightly darker oak' -> slightly, darker; 'more grain oak')."""
    words: list[ast.Word] = []
    for item in items:
        words += item.adverbs
        words.append(item.word)
        if isinstance(item.target, ast.Colour):
            words += item.target.words
        elif item.target is not None:
            words.append(item.target)
    return words
