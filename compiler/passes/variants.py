"""Expand "or" into variants: "red or blue anodized aluminum" -> two selections.

Every choice point (colours, adjectives, nouns, in phrase order) is expanded as a
cartesian product; each selection is a Material with exactly one word per choice.
"""

from __future__ import annotations

import hashlib
import itertools
import re
import unicodedata
from typing import Any

from .. import ast
from ..diagnostics import Diagnostic, error

MAX_VARIANTS = 64
NON_WORD = re.compile(r"\W+", re.ASCII)


#: Latin letters NFKD leaves whole (no accent to drop): their usual ASCII spelling
LATIN = str.maketrans(
    {
        **dict(zip("øØłŁđĐðÐıħĦ", "oOlLdDdDihH")),
        "ß": "ss",
        "æ": "ae",
        "Æ": "AE",
        "œ": "oe",
        "Œ": "OE",
        "þ": "th",
        "Þ": "Th",
    }
)


def ascii_fold(text: str) -> str:
    """'gebürstetes Weiß' -> 'geburstetes Weiss', 'ünïcødé' -> 'unicode': accents dropped, ß as ss."""
    if text.isascii():
        return text
    decomposed = unicodedata.normalize("NFKD", text.translate(LATIN))
    return "".join(c for c in decomposed if not unicodedata.combining(c))


def identifier(text: str) -> str:
    """A safe identifier from any text: letters, digits and '_', not starting with a digit."""
    simple = text.strip().lower().replace(" ", "_")
    if simple.isascii() and simple.isidentifier() and "__" not in simple and simple.strip("_") == simple:
        return simple  # "Anodized aluminum": what the general rule below gives, in a fifth of the time
    name = NON_WORD.sub("_", ascii_fold(text).strip().lower()).strip("_") or _nothing_ascii(text)
    return "m_" + name if name[0].isdigit() else name


def _nothing_ascii(text: str) -> str:
    """The name of a text with no ASCII letter or digit left: a short hash of it ('名前' -> 'm_1f0e3dad'),
    so two such names never collide; 'material' for a text of punctuation only."""
    if text.isascii():
        return "material"
    return "m_" + hashlib.sha256(text.strip().encode("utf-8", "surrogatepass")).hexdigest()[:8]


Choice = ast.Colour | ast.Word
ChoicePoint = tuple[ast.Colour, ...] | tuple[ast.Word, ...]


def choice_points(material: ast.Material) -> list[ChoicePoint]:
    """The alternatives of a phrase in phrase order: each group's colours then adjectives, then nouns."""
    points: list[ChoicePoint] = []
    groups = material.groups
    if material.coat:
        groups += material.coat.groups
    if material.features:  # 'with grey or white veins'
        groups += tuple([g for f in material.features for g in f.groups])
    for group in groups:
        for options in (group.colours, group.adjectives):
            if len(options) > 1:
                points.append(options)
    if len(material.nouns) > 1:
        points.append(material.nouns)
    return points


class _Picks:
    """One combination's choices, handed out in the order choice_points found the alternatives."""

    def __init__(self, combo: tuple[Choice, ...]) -> None:
        self._next = iter(combo).__next__

    def colours(self, options: tuple[ast.Colour, ...]) -> tuple[ast.Colour, ...]:
        if len(options) < 2:
            return options
        choice = self._next()
        assert isinstance(choice, ast.Colour)
        return (choice,)

    def words(self, options: tuple[ast.Word, ...]) -> tuple[ast.Word, ...]:
        if len(options) < 2:
            return options
        choice = self._next()
        assert isinstance(choice, ast.Word)
        return (choice,)

    def group(self, group: ast.Group) -> ast.Group:
        colours = self.colours(group.colours)
        adjectives = self.words(group.adjectives)
        return ast.Group(group.kind, group.adverbs, colours, adjectives, group.span)


def _select(material: ast.Material, combo: tuple[Choice, ...]) -> ast.Material:
    picks = _Picks(combo)
    groups = tuple([picks.group(g) for g in material.groups])
    coat = material.coat
    if coat:
        coat = ast.Coat(tuple([picks.group(g) for g in coat.groups]), coat.coat, coat.span)
    features = tuple(
        [ast.Feature(tuple([picks.group(g) for g in f.groups]), f.word, f.span) for f in material.features]
    )
    nouns = picks.words(material.nouns)
    return ast.Material(
        material.name, groups, nouns, coat, material.span, material.text, material.refinements, features
    )


def _choice_text(choice: Choice) -> str:
    if isinstance(choice, ast.Colour):
        return " ".join(w.text for w in choice.words)
    return choice.text


def expand(
    material: ast.Material, base_name: str, diags: list[Diagnostic]
) -> list[tuple[ast.Material, dict[str, Any] | None]]:
    """(selection, variant info or None) for every combination of the alternatives."""
    points = choice_points(material)
    if not points:
        return [(material, None)]
    combos: list[tuple[Choice, ...]] = list(itertools.islice(itertools.product(*points), MAX_VARIANTS + 1))
    if len(combos) > MAX_VARIANTS:
        diags.append(
            error(
                material.span,
                "E005",
                f"too many alternatives: more than {MAX_VARIANTS} variants",
                ("split the phrase into several lines",),
            )
        )
        combos = combos[:MAX_VARIANTS]
    out: list[tuple[ast.Material, dict[str, Any] | None]] = []
    for combo in combos:
        words = [_choice_text(c) for c in combo]
        info = {"group": base_name, "name": identifier("_".join(words)), "choices": words}
        out.append((_select(material, combo), info))
    return out
