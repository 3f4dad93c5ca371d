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
from .lexicon import Lexicon
from .parser import parsed_material
from .phrase_patterns import alternatives
from .suggest import teaching
from .tagged import NOTE_CODE, Tagged, written_span, written_text

__all__ = ["relative_material"]


def relative_material(words: Sequence[Tagged], text: str, lexicon: Lexicon) -> tuple[ast.Material, Diagnostic] | None:
    """The material with the clause's describing words before it, and the note; None when the line
    has no relative opener, or its sides are not a material and describing words."""
    table = teaching()["hedges"]
    low = text.lower()
    opener = re.search(r"\s(?:" + alternatives(table["relative"]) + r")\s", low)
    if opener is None or not words:
        return None
    tail = re.search(r"\s(?:" + alternatives(table["relative_tails"]) + r")[\s.!,]*$", low[opener.end() - 1 :])
    end = opener.end() - 1 + tail.start() if tail is not None else len(text)
    line_start = words[0].span.start - (words[0].span.col - 1)
    before = [w for w in words if w.span.start - line_start < opener.start()]
    after = [w for w in words if opener.end() <= w.span.start - line_start < end]
    if not before or not after or any(w.unknown for w in (*before, *after)):
        return None
    if not all(any(c.tag in ("ADJ", "COLOR", "SHADE", "ADV", "REFINE") for c in w.candidates) for w in after):
        return None
    article = before[:1] if any(c.tag == "ARTICLE" for c in before[0].candidates) else []
    material = parsed_material([*article, *_describing(after), *before[len(article) :]], text, lexicon.caches.shapes)
    if material is None:
        return None
    said = " ".join(written_text(part) for part in (article, after, before[len(article) :]) if part)
    note = f"read '{text.strip()}' as '{said}': the clause after the material describes it"
    return material, Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, note)


def _describing(words: Sequence[Tagged]) -> list[Tagged]:
    """The clause's words as describing words only ('silvered' is not the metal silver here)."""
    return [
        Tagged(w.text, w.span, tuple(c for c in w.candidates if c.tag != "NOUN") or w.candidates, w.unknown)
        for w in words
    ]
