"""Sizes, thicknesses and grades in a phrase ('honed Carrara marble, 2cm', '18k yellow gold',
'matt porcelain tile, 60x60', '3 mm brushed steel') are read past with a note.

A specification names a size or a grade beside the material; neither says how the surface looks,
and a number is not a word of the language. A measure is a number followed by one or more of the unit
words of stdlib/data/teaching.toml [measures] (mm, cm, in, k, ct, x, by, thick ...), more numbers
and a trailing dimension word; the separator that set it off goes with it. Runs only for a line
with a number (the unknown-word path of cnlmc.document), so ordinary lines pay nothing."""

from __future__ import annotations

import re
from collections.abc import Sequence

from .diagnostics import Diagnostic, Severity
from .spans import Span
from .suggest import teaching
from .tagged import NOTE_CODE, Tagged

__all__ = ["without_measures"]

NUMBER = re.compile(r"\d+(?:\.\d+)?%?")
BY_NUMBER = re.compile(r"[x×]\d+(?:\.\d+)?", re.IGNORECASE)  # '60x60' is tokenised '60', 'x60'
SEPARATORS = (",", ";", "-", "–", "—", "(", ")")


def without_measures(diags: list[Diagnostic], words: Sequence[Tagged]) -> tuple[list[Diagnostic], list[Tagged]]:
    """The line's words without its measures, and its diagnostics without theirs plus one note each."""
    runs = _measure_runs(words, frozenset(teaching()["measures"]["units"]))
    if not runs:
        return diags, list(words)
    dropped = {id(w) for start, end in runs for w in words[start:end]}
    spans = [words[start].span.to(words[end - 1].span) for start, end in runs]
    out = [d for d in diags if not any(_within(d.span, s) for s in spans)]
    for (start, end), span in zip(runs, spans):
        text = _written([w for w in words[start:end] if w.text not in SEPARATORS])
        note = f"read past '{text}': a size, thickness or grade says nothing of how the surface looks"
        out.append(Diagnostic(span, Severity.NOTE, NOTE_CODE, note))
    return out, [w for w in words if id(w) not in dropped]


def _written(words: Sequence[Tagged]) -> str:
    """The words as written: a space only where the line had one ('2cm', '60x60', '3 mm')."""
    text = words[0].text
    for before, word in zip(words, words[1:]):
        text += ("" if word.span.start == before.span.end else " ") + word.text
    return text


def _measure_runs(words: Sequence[Tagged], units: frozenset[str]) -> list[tuple[int, int]]:
    """(start, end) of each measure, with the separator before it at the line's end ('marble, 2cm'),
    after it at the line's start ('2cm, walnut') or between two ('porcelain, 300x600, matt')."""
    runs: list[tuple[int, int]] = []
    k = 0
    while k < len(words):
        if not NUMBER.fullmatch(words[k].text):
            k += 1
            continue
        end = k + 1
        while end < len(words) and _continues(words[end].text, units):
            end += 1
        if end == k + 1 and not _grade(words, k):  # a bare number ('50% rusty') is not a measure: it keeps its error
            k += 1
            continue
        start = k
        if end == len(words) and start > 0 and words[start - 1].text in SEPARATORS:
            start -= 1
        elif end < len(words) and words[end].text in SEPARATORS and (start == 0 or words[start - 1].text in SEPARATORS):
            end += 1  # '2cm, walnut'; 'porcelain, 300x600, matt': one of its two commas goes with it
        runs.append((start, end))
        k = end
    return runs if len(runs) and _leaves_words(words, runs) else []


def _grade(words: Sequence[Tagged], k: int) -> bool:
    """'316 stainless', '6061 aluminium': a number of three or four digits right before a metal
    (teaching.toml [measures] `graded`) is its alloy grade (read past like a size); '1950 oak' is not."""
    text = words[k].text
    nxt = words[k + 1] if k + 1 < len(words) else None
    return (
        text.isdigit()
        and 3 <= len(text) <= 4
        and nxt is not None
        and not nxt.unknown
        and nxt.text.lower() in teaching()["measures"]["graded"]
    )


def _continues(text: str, units: frozenset[str]) -> bool:
    return text.lower() in units or bool(NUMBER.fullmatch(text) or BY_NUMBER.fullmatch(text))


def _leaves_words(words: Sequence[Tagged], runs: list[tuple[int, int]]) -> bool:
    """Whether anything but measures is left (a line of numbers keeps its error)."""
    return sum(end - start for start, end in runs) < len(words)


def _within(at: Span | None, span: Span) -> bool:
    return at is not None and span.start <= at.start and at.end <= span.end
