"""Describing words after the noun with no comma (issue #14): 'steel brushed', 'plastic charcoal
grey', 'oak a bit darker', 'paint dark green with satin finish'.

The grammar writes describing words before the noun, or after it behind a comma ('oak, oiled').
People who list the thing first (a listing's habit, and the order of many languages) leave the
comma out. When nothing else reads such a line, it is read as if the comma were there, and a note
shows the order the grammar writes. A line of colour words only is a colour's name ('terracotta
red', 'slate grey'), never a material followed by its colour; a comma before the noun keeps the
line's own reading, one after its describing words may open a clause ('paint mostly matte, a little
sheen').
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from itertools import takewhile

from .diagnostics import Diagnostic, Severity
from .joins import implied_comma, of_tag
from .tagged import NOTE_CODE, Tagged, written_span

__all__ = ["noun_first_note", "noun_first_readings"]

#: The readings of a word that may be a colour's name, or part of one ('terracotta red', 'pale slate').
_COLOUR_WORDS = frozenset(("COLOR", "SHADE"))
#: The readings that end a run of describing words after the noun: a clause, or another list.
_NOT_DESCRIBING = frozenset(("WITH", "COMMA", "AND", "OR", "COLON"))


def noun_first_readings(words: Sequence[Tagged]) -> Iterator[tuple[list[Tagged], int]]:
    """The line with a comma implied where its noun group ends and describing words follow, one
    place at a time from the left, each with the index of the word after the comma; nothing for a
    line that has a comma, whose words could all name a colour, or with a word read as two."""
    said = [w for w in words if w.text[:1].isalnum()]
    if len(said) < 2 or _a_colour_name(said) or _split(said):
        return
    for k in range(1, len(words)):
        if of_tag(words[k - 1], "COMMA"):
            return  # the line's own comma comes first: 'oak, satin' reads as written
        if _noun_group_ends(words[k - 1], words[k]) and _may_describe(words[k:]):
            yield [*words[:k], implied_comma(words[k]), *words[k:]], k


def _noun_group_ends(before: Tagged, word: Tagged) -> bool:
    if before.unknown or word.unknown or not (of_tag(before, "NOUN") or of_tag(before, "OBJECT")):
        return False
    if any(c.tag in _NOT_DESCRIBING for c in word.candidates):
        return False
    return not all(c.tag in ("NOUN", "OBJECT") for c in word.candidates)


def _may_describe(run: Sequence[Tagged]) -> bool:
    """Words after the noun, up to a clause, that may describe it: no coat among them (a coat after the noun has
    readings of its own: 'oak varnish', 'satin varnish varnish'), and not ending in an adverb."""
    said = list(takewhile(lambda w: not of_tag(w, "WITH"), takewhile(lambda w: not of_tag(w, "COMMA"), run)))
    said = [w for w in said if w.text[:1].isalnum()]
    if any(of_tag(w, "COAT") for w in said):
        return False
    return bool(said) and not all(c.tag == "ADV" for c in said[-1].candidates)


def _split(said: Sequence[Tagged]) -> bool:
    """Whether a word was read as two ('peanut' as 'pea nut'): a guess, not what was written."""
    return any(a.span.end == b.span.start for a, b in zip(said, said[1:], strict=False))


def _a_colour_name(said: Sequence[Tagged]) -> bool:
    """Whether the words may all name one colour ('terracotta red', 'pale slate'); a colour's name
    ends in a colour, never in a shade alone ('walnut dark' is walnut, dark)."""
    ends = any(c.tag == "COLOR" for c in said[-1].candidates)
    return ends and all(any(c.tag in _COLOUR_WORDS for c in w.candidates) for w in said)


def noun_first_note(words: Sequence[Tagged], k: int, comparatives: bool = False) -> Diagnostic:
    """'read 'steel brushed' as 'brushed steel' (describing words go before the noun)'; for
    comparatives, which follow the material: 'read 'oak a bit darker' as 'oak, a bit darker''."""
    end = next((j for j in range(k, len(words)) if of_tag(words[j], "WITH") or of_tag(words[j], "COMMA")), len(words))
    lead = 0  # 'the steel brushed' = 'the brushed steel': an article stays first
    while lead < k - 1 and (words[lead].unknown or all(c.tag == "ARTICLE" for c in words[lead].candidates)):
        lead += 1
    head, after, clause = _text(words[:k]), _text(words[k:end]), _text(words[end:])
    if comparatives:
        message = f"read '{_text(words)}' as '{head}, {_text(words[k:])}' (a comma after the material)"
    else:
        parts = (_text(words[:lead]), after, _text(words[lead:k]), clause)
        reordered = " ".join(part for part in parts if part).replace(" ,", ",")
        message = f"read '{_text(words)}' as '{reordered}' (describing words go before the noun)"
    return Diagnostic(written_span(words), Severity.NOTE, NOTE_CODE, message)


def _text(words: Sequence[Tagged]) -> str:
    return " ".join(w.text for w in words if w.implied_by is None).replace(" ,", ",")
