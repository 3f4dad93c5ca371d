"""Expand "or" into variants: "red or blue anodized aluminum" -> two selections.

Every choice point (colours, adjectives, nouns, in phrase order) is expanded as a
cartesian product; each selection is a Material with exactly one word per choice.
"""

from __future__ import annotations

import itertools
import re
import unicodedata

from .. import ast
from ..diagnostics import error

MAX_VARIANTS = 64
NON_WORD = re.compile(r"\W+", re.ASCII)


def ascii_fold(text: str) -> str:
    """'gebürstetes Weiß' -> 'geburstetes Weiss': accents dropped, ß as ss."""
    if text.isascii():
        return text
    decomposed = unicodedata.normalize("NFKD", text.replace("ß", "ss"))
    return "".join(c for c in decomposed if not unicodedata.combining(c))


def identifier(text: str) -> str:
    """A safe identifier from any text: letters, digits and '_', not starting with a digit."""
    name = NON_WORD.sub("_", ascii_fold(text).strip().lower()).strip("_") or "material"
    return "m_" + name if name[0].isdigit() else name


def choice_points(material: ast.Material) -> list[tuple]:
    points = []
    for group in material.groups + (material.coat.groups if material.coat else ()):
        for options in (group.colours, group.adjectives):
            if len(options) > 1:
                points.append(options)
    if len(material.nouns) > 1:
        points.append(material.nouns)
    return points


def _pick_group(group: ast.Group, picks: dict) -> ast.Group:
    colours = (picks[id(group.colours)],) if id(group.colours) in picks else group.colours
    adjectives = (picks[id(group.adjectives)],) if id(group.adjectives) in picks else group.adjectives
    return ast.Group(group.kind, group.adverbs, colours, adjectives, group.span)


def _select(material: ast.Material, picks: dict) -> ast.Material:
    groups = tuple([_pick_group(g, picks) for g in material.groups])
    coat = material.coat
    if coat:
        coat = ast.Coat(tuple([_pick_group(g, picks) for g in coat.groups]), coat.coat, coat.span)
    nouns = (picks[id(material.nouns)],) if id(material.nouns) in picks else material.nouns
    return ast.Material(material.name, groups, nouns, coat, material.span, material.text)


def _choice_text(choice) -> str:
    if isinstance(choice, ast.Colour):
        return " ".join(w.text for w in choice.words)
    return choice.text


def expand(material: ast.Material, base_name: str, diags: list) -> list[tuple[ast.Material, dict | None]]:
    """(selection, variant info or None) for every combination of the alternatives."""
    points = choice_points(material)
    if not points:
        return [(material, None)]
    combos = list(itertools.islice(itertools.product(*points), MAX_VARIANTS + 1))
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
    out = []
    for combo in combos:
        picks = {id(options): choice for options, choice in zip(points, combo)}
        words = [_choice_text(c) for c in combo]
        info = {"group": base_name, "name": identifier("_".join(words)), "choices": words}
        out.append((_select(material, picks), info))
    return out
