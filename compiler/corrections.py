"""A correction said mid-line, as dictation and chat have them (issue #14): 'oak matt no wait
satin' is satin oak, 'red, sorry, blue velvet' is blue velvet. The marker
(teaching.toml [corrections] markers) and the word before it that the word after it replaces are
read past, with a note. Only a line that does not read otherwise comes here (cnlmc.document),
before any of its words is read past (cnlmc.read_past), one correction a line; and
the word before is dropped only when it is of a kind the word after is too (a colour for a colour,
a describing word for a describing word: the lexicon's readings of the two words alone).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

from .spans import blanked
from .suggest import teaching

__all__ = ["Correction", "correction"]


@dataclass(frozen=True)
class Correction:
    """The line with the corrected word and the marker blanked (columns kept), and what was said."""

    text: str
    dropped: str
    marker: str
    start: int
    end: int


def correction(text: str, kinds: Callable[[str], set[str]]) -> Correction | None:
    """The line's first correction, or None: a marker first on the line ('no actually a lot
    lighter': the change after it), else one mid-line. `kinds(word)`: the tags a word reads as alone."""
    markers = sorted(teaching()["corrections"]["markers"], key=len, reverse=True)
    alternatives = "|".join(re.escape(m) for m in markers)
    first = re.match(r"\s*(?:" + alternatives + r")[\s,]+", text.lower())
    if first is not None and text[first.end() :].strip():
        start = len(text) - len(text.lstrip())
        said = text[start : first.end()].strip(" ,")
        return Correction(blanked(text, [(0, first.end())]), "", said, start, first.end())
    pattern = r"[\s,]+(?:" + alternatives + r")[\s,]+"
    for found in re.finditer(pattern, text.lower()):
        before = re.search(r"([A-Za-z][\w'-]*)\s*$", text[: found.start()])
        after = re.match(r"\s*([A-Za-z][\w'-]*)", text[found.end() :])
        if before is None or after is None:
            continue
        if not kinds(before.group(1).lower()) & kinds(after.group(1).lower()):
            continue
        start, end = before.start(1), found.end()
        return Correction(
            blanked(text, [(start, end)]), before.group(1), text[found.start() : found.end()].strip(" ,"), start, end
        )
    return None
