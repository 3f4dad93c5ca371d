"""Taking a word off the material above (issue #14): 'lose the brushed look', 'no rust', 'get rid
of the varnish', 'can we drop the scratches?'. A line that opens with a removal phrase
(stdlib/data/teaching.toml [removal], after any politeness) and then names only describing words,
features, coats or colours is a change line whose `removed` words come off the material above
(cnlmc.analyze.changed_material). 'not X' and 'no X' of an adjective with a declared opposite stay
its opposite ('not glossy' = matte: cnlmc.word_formation). Any other line is None: it is read as
before ('lose the shine' = less shine).

Asked only of a line with an unknown or rule-read word or one that does not parse (cnlmc.document),
and then first a set lookup of its first word.
"""

from __future__ import annotations

import re
from dataclasses import replace
from functools import lru_cache
from typing import TYPE_CHECKING, Any

from . import ast
from .diagnostics import Diagnostic, Severity
from .phrase_patterns import alternatives
from .suggest import teaching
from .tagged import NOTE_CODE, Tagged

if TYPE_CHECKING:
    from .tagger import Tagger

__all__ = ["opens_removal", "removal_line", "removal_phrase"]

TAKEN_OFF_NOTE = "off the material above"  # the end of a removal's note (cnlmc.line_parts says it again as a step)

#: the word categories a removal takes off, by grammar terminal (a property: the words of its name)
REMOVABLE = ("ADJ", "FEATURE", "COAT", "COLOR", "PROP")
#: terminals that may stand between them ('the rust and the scratches')
JOINERS = ("ARTICLE", "AND", "COMMA")


@lru_cache(maxsize=1)
def _rules() -> tuple[frozenset[str], re.Pattern[str], re.Pattern[str], re.Pattern[str], frozenset[str]]:
    """The first words that may open a removal line, the opening and removal phrases and the
    trailing filler as patterns, and the negations that defer to a declared opposite."""
    table: dict[str, Any] = teaching()["removal"]
    openers = [*teaching()["politeness"]["leading"], *table["openers"]]
    phrases = table["leading"]
    firsts = frozenset(p.split()[0] for p in [*openers, *phrases])
    opener = re.compile(rf"(?:{alternatives(openers)})\s*[,!.:;]?\s+")
    removal = re.compile(rf"(?:{alternatives(phrases)})\s+")
    trailing = re.compile(rf"(?:[\s,.!?]+(?:{alternatives(table['trailing'])}))*[\s,.!?]*$")
    return firsts, opener, removal, trailing, frozenset(table["negations"])


def removal_line(text: str, number: int, offset: int, tagger: Tagger) -> tuple[ast.Refinement, Diagnostic] | None:
    """The line as a removal (its refinement and the note saying so), or None."""
    opening = _opening(text)
    if opening is None:
        return None
    start, _opened, lead, phrase = opening
    _firsts, _opener, _removal, trailing, negations = _rules()
    low = text.lower()
    end = lead + len(trailing.sub("", low[lead:]))
    masked = " " * lead + text[lead:end] + " " * (len(text) - end)  # columns stay the user's
    tagged, problems = tagger.tag_line(masked, number, offset)
    words = [w for w in tagged if w.implied_by is None]  # 'varnish' alone implies 'wood with': not here
    if not words or any(d.is_error for d in problems):
        return None
    if any(c.tag == "NOUN" for c in words[-1].candidates):
        return None  # 'not weathered copper', 'no gold': a material described
    removed = _removed_words(words)
    if not removed or (phrase in negations and _negated_reading(removed, tagger)):
        return None
    span = words[0].span.to(words[-1].span)
    shift = words[0].span.col - 1 - start  # the note spans the whole removal, its openers too ('can we lose the')
    said_span = replace(span, start=span.start - shift, col=start + 1)
    listed = ", ".join(dict.fromkeys(f"'{w.text}'" for w in removed))
    message = f"read '{text.strip()}' as taking {listed} {TAKEN_OFF_NOTE}"
    return ast.Refinement(None, (), span, text, removed=removed), Diagnostic(
        said_span, Severity.NOTE, NOTE_CODE, message
    )


def opens_removal(text: str) -> bool:
    """Whether the text opens with a removal phrase ('no grain', 'without the varnish', 'lose the
    shine'), past its openers."""
    return _opening(text) is not None


def removal_phrase(text: str) -> tuple[int, int] | None:
    """Where the removal phrase the text opens with starts and ends ('lose the' of 'can we lose
    the grain'), past its openers; None when it opens with none."""
    opening = _opening(text)
    return None if opening is None else (opening[1], opening[1] + len(text[opening[1] : opening[2]].rstrip()))


def _opening(text: str) -> tuple[int, int, int, str] | None:
    """Where the text's words start, where its removal phrase starts, where the removed words
    start, and the phrase said; None when it opens with no removal phrase (a set lookup first)."""
    firsts, opener, removal, _trailing, _negations = _rules()
    start = len(text) - len(text.lstrip())
    first = text[start:].split(maxsplit=1)[0].lower().rstrip(",!.:;?") if text.strip() else ""
    if first not in firsts:
        return None
    said = _removal_at(text.lower(), start, opener, removal)
    return None if said is None else (start, *said)


def _removal_at(low: str, start: int, opener: re.Pattern[str], removal: re.Pattern[str]) -> tuple[int, int, str] | None:
    """Where the removal phrase starts, where the removed words start and the phrase said, past up
    to three openers ('ok, can we lose the ...'); None when the line opens with no removal phrase."""
    at = start
    for _ in range(4):
        found = removal.match(low, at)
        if found is not None:
            return found.start(), found.end(), " ".join(found.group(0).split())
        skipped = opener.match(low, at)
        if skipped is None:
            return None
        at = skipped.end()
    return None


def _removed_words(words: list[Tagged]) -> tuple[ast.Word, ...]:
    """Each describing word, feature, coat or colour named, once for each of these readings
    ('varnish': the coat and 'varnished'), in order; () when any other word stands among them (a
    noun, a comparative). A property ('shine') stands for the words that set it ('shiny')."""
    removed: list[ast.Word] = []
    for word in words:
        if any(c.tag in JOINERS for c in word.candidates):
            continue
        if not any(c.tag in REMOVABLE for c in word.candidates):
            return ()
        removed += [ast.Word(word.text, c.key, c.category, word.span) for c in word.candidates if c.tag in REMOVABLE]
    return tuple(removed)


def _negated_reading(removed: tuple[ast.Word, ...], tagger: Tagger) -> bool:
    """Whether 'no' or 'not' before these words keeps its reading of word formation: one adjective
    with a declared opposite ('not glossy' = matte), or a property word that names no feature or
    describing word ('no gloss' = matte)."""
    if len({w.span for w in removed}) > 1:
        return False  # 'no clear coat': a coat, not 'clear'
    if all(w.category == "properties" for w in removed):
        return True
    for word in removed:
        entry = tagger.lexicon.entry("adjectives", word.key) if word.category == "adjectives" else None
        if entry is not None and entry.get("opposite"):
            return True
    return False
