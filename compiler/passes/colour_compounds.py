"""'chestnut brown', 'ruby red', 'ivory white': a particular colour followed by its own basic
colour term is one colour (the particular one), not a second colour replacing the first (W105).

Two basic terms ('red blue', 'white black') stay two colours: that is a real contradiction.
The rules are data: stdlib/data/colour_compounds.toml (Berlin and Kay's basic terms, the hue and
lightness agreement); each reading says so in a note (N131).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import replace
from functools import lru_cache
from types import MappingProxyType
from typing import Any

from .. import ast
from ..colour import linear_to_oklab
from ..diagnostics import Diagnostic, Severity
from ..lexicon import Lexicon
from ..package_data import package_folder

__all__ = ["NOTE_CODE", "colour_compounds"]

NOTE_CODE = "N131"  # two colour words read as one colour


@lru_cache(maxsize=1)
def rules() -> Mapping[str, Any]:
    """stdlib/data/colour_compounds.toml, read once per process (immutable package data)."""
    import tomllib

    text = (package_folder("cnlmc.stdlib") / "data" / "colour_compounds.toml").read_text("utf-8")
    return MappingProxyType(tomllib.loads(text))


def colour_compounds(groups: Sequence[ast.Group], lexicon: Lexicon, diags: list[Diagnostic]) -> Sequence[ast.Group]:
    """The groups with each 'particular colour + its basic term' pair read as the particular colour."""
    if len(groups) < 2 or [g.kind for g in groups].count("colour") < 2:
        return groups
    out: list[ast.Group] = []
    for group in groups:
        if out and _is_compound(out[-1], group, lexicon):
            first = out[-1].colours[0]
            second = group.colours[0]
            diags.append(_note(first, second))
            continue
        if out and _is_hedged_pair(out[-1], group, lexicon):  # 'blackish green': green, somewhat toward black
            diags.append(_hedged_note(out[-1], group))
            out[-1:] = [group, _as_share(out[-1])]
            continue
        out.append(group)
    return out


def _is_hedged_pair(first: ast.Group, second: ast.Group, lexicon: Lexicon) -> bool:
    """A hedged colour ('blackish', 'almost black', 'slightly grey') right before a plain colour:
    the second colour moved toward the first by the hedge's share (applied after it, as 'slightly
    red' moves the colour there), not a second colour replacing the first."""
    if not (_single_colour(first) and _single_colour(second)) or second.adverbs or first.colours[0].shades:
        return False
    return second.span.start - first.span.end <= 1 and (_softened(first, lexicon) or _hedged_word(first.colours[0]))


def _softened(group: ast.Group, lexicon: Lexicon) -> bool:
    """Adverbs that soften ('slightly', 'almost': weight below 1), not ones that strengthen ('very')."""
    weights = [lexicon.entry("adverbs", a.key) for a in group.adverbs]
    return bool(weights) and all(e is not None and float(e.get("weight", 1.0)) < 1.0 for e in weights)


def _hedged_word(c: ast.Colour) -> bool:
    """A colour word that hedges itself: an X-ish ('blackish') or 'almost X' ('almost black')."""
    table = rules()["hedged"]
    assert c.base is not None  # _single_colour
    written = c.words[-1].text.lower()
    return written.endswith(tuple(table["suffixes"])) or c.base.key.startswith(tuple(f"{w} " for w in table["leads"]))


def _as_share(group: ast.Group) -> ast.Group:
    """The hedged colour at the hedge's share ('blackish green', 'nearly black navy': the navy leans
    toward black and stays a navy), whatever its own degree."""
    adverb = ast.Word(
        group.colours[0].words[0].text, rules()["hedged"]["adverb"], "adverbs", group.colours[0].words[0].span
    )
    return replace(group, adverbs=(adverb,))


def _is_compound(first: ast.Group, second: ast.Group, lexicon: Lexicon) -> bool:
    if not (_single_colour(first) and _single_colour(second)) or second.adverbs or second.colours[0].shades:
        return False
    if second.span.start - first.span.end > 1:  # a comma or 'and' between them
        return False
    a, b = first.colours[0].base, second.colours[0].base
    assert a is not None and b is not None  # _single_colour
    basic = rules()["basic_terms"]
    if a.key in basic or b.key not in basic:
        return False
    rgb_a, rgb_b = _rgb(lexicon, a.key), _rgb(lexicon, b.key)
    return rgb_a is not None and rgb_b is not None and _agrees(rgb_a, rgb_b, b.key)


def _single_colour(group: ast.Group) -> bool:
    return group.kind == "colour" and len(group.colours) == 1 and group.colours[0].base is not None


def _rgb(lexicon: Lexicon, key: str) -> list[float] | None:
    entry = lexicon.entry("colours", key)
    rgb = entry.get("rgb") if entry is not None else None
    return list(rgb) if rgb else None


def _agrees(particular: Sequence[float], basic: Sequence[float], basic_key: str) -> bool:
    """The particular colour is a kind of the basic one: the same neutral band, or the same hue."""
    lightness, a, b = linear_to_oklab(particular)
    chroma = math.hypot(a, b)
    band = rules()["neutral_lightness"].get(basic_key)
    if band is not None:
        return chroma < float(rules()["neutral_chroma"]) and float(band[0]) <= lightness <= float(band[1])
    _l, a2, b2 = linear_to_oklab(basic)
    if chroma < float(rules()["hue"]["min_chroma"]):
        return False
    difference = abs(math.degrees(math.atan2(b, a) - math.atan2(b2, a2))) % 360.0
    return min(difference, 360.0 - difference) <= float(rules()["hue"]["max_degrees"])


def _hedged_note(first: ast.Group, second: ast.Group) -> Diagnostic:
    said = " ".join(w.text for w in (*first.adverbs, *first.colours[0].words))
    toward, colour = first.colours[0].words[-1].key, " ".join(w.text for w in second.colours[0].words)
    return Diagnostic(
        first.span.to(second.span),
        Severity.NOTE,
        NOTE_CODE,
        f"read '{said} {colour}' as '{colour}' moved toward {toward}, not two colours",
    )


def _note(first: ast.Colour, second: ast.Colour) -> Diagnostic:
    a, b = first.words[-1].text, second.words[-1].text
    span = first.span.to(second.span)
    article = "an" if b[:1].lower() in "aeiou" else "a"  # 'an orange', 'a grey'
    return Diagnostic(
        span, Severity.NOTE, NOTE_CODE, f"read '{a} {b}' as the colour '{a}' ({article} {b}), not two colours"
    )
