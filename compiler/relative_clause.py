"""'teak that has silvered with age', 'oak that's been limed', 'a brass that has gone dull': a
material named first and then described by a relative clause is the material with those describing
words before it ('silvered teak'). The relative openers and the time or place phrases after the
describing words ('with age', 'over time', read past) are data (teaching.toml [hedges] `relative`,
`relative_tails`); runs only for a line that does not parse."""

from __future__ import annotations

import re
from collections.abc import Sequence

from . import ast
from .diagnostics import Diagnostic, Severity
from .joins import DESCRIBING
from .lexicon import Lexicon
from .on_clause import implied_with
from .parser import parsed_material
from .phrase_patterns import alternatives
from .suggest import teaching
from .tagged import NOTE_CODE, Tagged, written_span, written_words
from .tagger import Tagger

__all__ = ["clause_after", "describing_after", "participle_after", "relative_material"]


def relative_material(words: Sequence[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """The material with the clause's describing words before it, and the note; None when the line
    has no relative opener, or its sides are not a material and describing words. A negated opener
    ('brass that isn't shiny', 'leather that doesn't look plasticky': teaching.toml [hedges]
    `relative_negated`) is read as the plain one with 'not' before the describing words."""
    if not words:
        return None
    table = teaching()["hedges"]
    low = text.lower()
    negated = re.search(r"\s(?:" + alternatives(table["relative_negated"]) + r")\s", low)
    if negated is not None:
        return _negated_relative(words, text, negated.start(), negated.end(), lexicon)
    opener = re.search(r"\s(?:" + alternatives(table["relative"]) + r")\s", low)
    if opener is None:
        return None
    return _relative_reading(words, text, opener.start(), opener.end(), lexicon)


def _negated_relative(
    words: Sequence[Tagged], text: str, start: int, end: int, lexicon: Lexicon
) -> tuple[ast.Material, Diagnostic] | None:
    """The line tagged again with the negated opener blanked but for a 'not' at its end (every
    other word keeps its place), then read as a relative clause that opens there."""
    line, line_start = words[0].span.line, words[0].span.line_start
    said = text[:start] + " " * (end - start - 4) + "not " + text[end:]
    again, problems = Tagger.of(lexicon).tag_line(said, line, line_start)
    if any(d.is_error for d in problems) or not again:
        return None
    found = _relative_reading(again, said, start, end - 4, lexicon)
    if found is None and not [w for w in again if w.span.start - line_start >= start]:
        found = _read_as(again, list(again), said, lexicon, "what it is not leaves it as it is")  # 'not plasticky'
    if found is None:
        return None
    note = found[1].message.replace(f"'{said.strip()}'", f"'{text.strip()}'", 1)
    return found[0], Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, note)


def _relative_reading(
    words: Sequence[Tagged], text: str, start: int, end: int, lexicon: Lexicon
) -> tuple[ast.Material, Diagnostic] | None:
    """The words before text[start:end] (the opener, its spaces included) as the material, those
    after it (up to a tail read past) as describing it."""
    tail = re.search(
        r"\s(?:" + alternatives(teaching()["hedges"]["relative_tails"]) + r")[\s.!,]*$", text.lower()[end - 1 :]
    )
    stop = end - 1 + tail.start() if tail is not None else len(text)
    line_start = words[0].span.line_start
    before = [w for w in words if w.span.start - line_start < start]
    after = [w for w in words if end <= w.span.start - line_start < stop]
    if not before or not after or any(w.unknown for w in (*before, *after)):
        return None
    if not all(any(c.tag in ("ADJ", "COLOR", "SHADE", "ADV", "REFINE") for c in w.candidates) for w in after):
        return None
    article = _article(before)
    reading = [*article, *_describing(after), *before[len(article) :]]
    return _read_as(words, reading, text, lexicon, "the clause after the material describes it")


def _describing(words: Sequence[Tagged]) -> list[Tagged]:
    """The clause's words as describing words only ('silvered' is not the metal silver here)."""
    return [
        Tagged(w.text, w.span, tuple(c for c in w.candidates if c.tag != "NOUN") or w.candidates, w.unknown)
        for w in words
    ]


def participle_after(words: Sequence[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """'oak painted white', 'steel powder-coated in black', 'walls stained dark grey': a material, a
    describing word, then only a colour is the colour, the describing word and the material
    ('white painted oak'), with a note; None for any other line."""
    said = [w for w in words if w.text[:1].isalnum()]
    at = next((i for i, w in enumerate(said) if not any(c.tag in ("NOUN", "ARTICLE") for c in w.candidates)), 0)
    if at == 0 or at + 1 >= len(said) or not _only(said[at : at + 1], ("ADJ",)):
        return None
    rest = [w for w in said[at + 1 :] if not (_only([w], ("WITH",)) or _only([w], ("ARTICLE",)))]  # 'in a black'
    if not rest or not _only(rest, ("COLOR", "SHADE", "ADV")) or not any(_has(w, "COLOR") for w in rest):
        return None
    nouns = said[:at]
    article = _article(nouns)
    reading = [*article, *rest, said[at], *nouns[len(article) :]]
    return _read_as(words, reading, text, lexicon, "the colour after the describing word is the material's")


def _read_as(
    words: Sequence[Tagged], reading: list[Tagged], text: str, lexicon: Lexicon, why: str
) -> tuple[ast.Material, Diagnostic] | None:
    """The material the words read in another order make, with the note saying so; None when that
    order does not parse."""
    material = parsed_material(reading, text, lexicon.caches.shapes)
    if material is None:
        return None
    said = " ".join(written_words(reading))
    note = f"read '{text.strip()}' as '{said}': {why}"
    return material, Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, note)


def _article(words: Sequence[Tagged]) -> list[Tagged]:
    """The article the words open with, as a list of none or one."""
    return list(words[:1]) if words and _has(words[0], "ARTICLE") else []


def _has(word: Tagged, tag: str) -> bool:
    return any(c.tag == tag for c in word.candidates)


def _only(words: Sequence[Tagged], tags: tuple[str, ...]) -> bool:
    """Whether every word has one of the tags (and nothing else)."""
    return all(w.candidates and all(c.tag in tags for c in w.candidates) for w in words)


def described_colour_after(
    words: Sequence[Tagged], text: str, lexicon: Lexicon
) -> tuple[ast.Material, Diagnostic] | None:
    """'walls in a soft chalky green', 'the front door in a glossy oxblood red': a material, 'in'
    (or 'with') and an article, then describing words ending in a colour, is those words before the
    material ('soft chalky green walls'), with a note; None for any other line."""
    said = [w for w in words if w.text[:1].isalnum()]
    last = max((i for i, w in enumerate(said) if _has(w, "NOUN")), default=-1)
    tail = said[last + 1 :]
    if last < 0 or len(tail) < 3 or not _has(tail[0], "WITH") or not _has(tail[1], "ARTICLE"):
        return None
    described = tail[2:]
    if not _has(described[-1], "COLOR") or not any(_has(w, "ADJ") for w in described):
        return None
    if not all(any(c.tag in DESCRIBING for c in w.candidates) for w in described):
        return None
    head = said[: last + 1]
    article = _article(head)
    reading = [*article, *_describing(described), *head[len(article) :]]
    return _read_as(words, reading, text, lexicon, "the words after 'in' describe the material")


def describing_after(words: Sequence[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """'paint with no gloss', 'plastic without shine': a negated describing word said after the
    material (with or without 'with') is its describing word ('matte paint'), with a note; None when
    the words after the material are anything else ('aluminum brushed' keeps its error)."""
    said = [w for w in words if w.text[:1].isalnum()]
    last = max((i for i, w in enumerate(said) if _has(w, "NOUN")), default=-1)
    tail = said[last + 1 :]
    if last < 0 or not tail:
        return None
    if _has(tail[0], "WITH"):
        tail = tail[1:]
    negations = Tagger.of(lexicon).formation().rules.negation_words  # 'without shine' is one word read 'dull'
    negated = bool(tail) and tail[0].text.lower().split()[0] in negations
    if not negated or not _only(tail, ("ADJ", "ADV")) or not any(_has(w, "ADJ") for w in tail):
        return None  # 'aluminum brushed' keeps its error: describing words come before the noun
    head = said[: last + 1]
    article = _article(head)
    reading = [*article, *tail, *head[len(article) :]]
    return _read_as(words, reading, text, lexicon, "words after the material describe it")


def clause_after(words: Sequence[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """'a matte white stoneware glaze', 'glossy oak varnish': describing words, a material, then a
    coat or a feature last is the material with that clause, the describing words the clause's
    ('stoneware with a matte white glaze'), with a note; None for any other line."""
    said = [w for w in words if w.text[:1].isalnum()]
    if len(said) < 3 or not (_has(said[-1], "FEATURE") or _has(said[-1], "COAT")) or _has(said[-1], "NOUN"):
        return None
    if not _has(said[-2], "NOUN"):
        return None
    article = _article(said)
    describing = said[len(article) : -2]
    if not describing or not _only(describing, ("ADJ", "COLOR", "SHADE", "ADV")):
        return None
    noun, last = said[-2], said[-1]
    kept = tuple(c for c in last.candidates if c.tag in ("FEATURE", "COAT"))
    reading = [*article, noun, implied_with(noun), *describing, Tagged(last.text, last.span, kept, last.unknown)]
    return _read_as(words, reading, text, lexicon, f"the describing words go with the {last.text}")
