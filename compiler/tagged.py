"""A word of a line and its readings: what the tagger gives the parser."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

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


def only_tag(word: Tagged, tag: str) -> bool:
    """Whether the word has one reading, of this grammar tag (a comma, a name, a colon)."""
    return len(word.candidates) == 1 and word.candidates[0].tag == tag


def written_span(words: Sequence[Tagged]) -> Span:
    """From the first word to the last as the user wrote them: a word no one typed stands for the
    words that imply it (its `implied_by`), so a note never points inside a word."""
    first, last = words[0], words[-1]
    return (first.implied_by or first.span).to(last.implied_by or last.span)


class Spanned(Protocol):
    """A word as written: its text and where it stands (a tagged word or an AST word)."""

    @property
    def text(self) -> str: ...

    @property
    def span(self) -> Span: ...


def written_words(words: Sequence[Spanned]) -> list[str]:
    """The words' texts in their order; parts read from one written word ('darkest' = 'very' on
    'est', 'dark' on 'dark') are put back together as written ('darkest'). Parts touch and each
    spans its own letters; a word no one typed (an implied 'with', a noun) spans none of its own."""
    out: list[str] = []
    last: Span | None = None
    for word in words:
        at = word.span
        own = at.end - at.start == len(word.text) > 0
        if last is not None and own and (at.start == last.end or at.end == last.start):
            out[-1] = out[-1] + word.text if at.start == last.end else word.text + out[-1]
            last = last.to(at) if at.start == last.end else at.to(last)
            continue
        out.append(word.text)
        last = at if own else None
    return out


def written_text(words: Sequence[Spanned]) -> str:
    """The words as the user wrote them, in the order they stand: parts of one word put back
    together, words apart joined by a space."""
    return " ".join(written_words(sorted(words, key=lambda w: w.span.start)))
