"""The words of one source line with the category each one has: the parser's choice where the
line parses, else the tagger's first candidate. Shared by hover, tokens, colours and actions."""

from __future__ import annotations

from dataclasses import dataclass

from ..lexicon import Lexicon
from ..tagged import Tagged
from ..tagger import TOKEN_RE, Tagger
from .incremental import Snapshot


@dataclass(frozen=True)
class LineWord:
    start: int  # character columns on the line, half-open
    end: int
    text: str
    category: str  # lexicon category, 'name', 'keyword', 'punct' or 'unknown'
    key: str
    tags: tuple[str, ...]  # every candidate tag the tagger found


def tag_text(text: str, lexicon: Lexicon) -> list[Tagged]:
    """Tagged words of a line, with spans whose offsets are the columns on that line."""
    tagged, _diags = Tagger.of(lexicon).tag_line(text, 1, 0)
    return tagged


def line_words(snapshot: Snapshot, line: int, lexicon: Lexicon) -> list[LineWord]:
    text = snapshot.index.lines[line]
    # an implied word ('wood' in 'satin varnish') has the span of the word implying it: that word is shown
    chosen = {col: word for word, col in snapshot.words_on(line) if text.startswith(word.text, col)}
    out = []
    for t in tag_text(text, lexicon):
        if t.implied_by is not None:
            continue  # no one typed it
        start, end = t.span.start, t.span.end
        tags = tuple(c.tag for c in t.candidates)
        if start in chosen and not chosen[start].unknown:
            word = chosen[start]
            out.append(LineWord(start, end, t.text, word.category, word.key, tags))
        elif t.unknown or not t.candidates:
            out.append(LineWord(start, end, t.text, "unknown", "", tags))
        else:
            first = t.candidates[0]
            out.append(LineWord(start, end, t.text, first.category, first.key, tags))
    return out


def word_at(words: list[LineWord], col: int) -> LineWord | None:
    for word in words:
        if word.start <= col <= word.end:
            return word
    return None


def comment_start(text: str) -> int | None:
    """The column of the '#' that starts a comment on the line, if any."""
    for match in TOKEN_RE.finditer(text):
        if match.group() == "#":
            return match.start()
    return None
