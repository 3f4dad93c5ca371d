"""A word of a line and its readings: what the tagger gives the parser."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from .spans import Span

NOTE_CODE = "N101"  # the note of a word read by a rule (cnlmc.word_formation) or joined by the tagger


@dataclass(frozen=True, slots=True)
class Candidate:
    """One reading of a word: its grammar terminal, lexicon key and category ("gold": COLOR or NOUN)."""

    tag: str
    key: str
    category: str


@dataclass(slots=True)
class Tagged:
    """A word (or multi-word entry) of a line with its candidate tags; made once, never changed."""

    text: str
    span: Span  # where it stands: each word of a line starts at its own offset (the parser keys words by start)
    candidates: tuple[Candidate, ...]
    unknown: bool = False
    # a word no one typed ('wood' and 'with' in 'satin varnish' = wood with a satin varnish): the span of
    # the word that implies it, which the syntax tree, the IR and the editor show (`span` then lies inside
    # that word, only to keep its place in the line)
    implied_by: Span | None = None


def written_span(words: Sequence[Tagged]) -> Span:
    """From the first word to the last as the user wrote them: a word no one typed stands for the
    words that imply it (its `implied_by`), so a note never points inside a word."""
    first, last = words[0], words[-1]
    return (first.implied_by or first.span).to(last.implied_by or last.span)


def written_text(words: Sequence[Tagged]) -> str:
    """The words as the user wrote them: parts read from one word ('darkest' = 'intensely' on 'est',
    'dark' on 'dark') are put back together in their places, words apart are joined by a space."""
    out: list[str] = []
    end = None
    for word in sorted(words, key=lambda w: w.span.start):
        if end is not None and word.span.start != end:  # apart, or a word implied inside another
            out.append(" ")
        out.append(word.text)
        end = word.span.end
    return "".join(out)
