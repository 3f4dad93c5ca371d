"""Source positions: every AST node and every IR value knows where it came from."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass


@dataclass(frozen=True, init=False)
class Span:
    """A half-open character range [start, end) in a source text, with 1-based line/col."""

    start: int
    end: int
    line: int
    col: int

    def __init__(self, start: int, end: int, line: int, col: int) -> None:
        # Spans and AST nodes are made for every word of every phrase. A frozen dataclass's own
        # __init__ sets each field through object.__setattr__, twice as slow as filling the
        # instance's __dict__ as the hand-written __init__ of each of them does.
        fields = self.__dict__
        fields["start"] = start
        fields["end"] = end
        fields["line"] = line
        fields["col"] = col

    @property
    def line_start(self) -> int:
        """Where the line of this span starts in the text (its column 1)."""
        return self.start - (self.col - 1)

    @property
    def end_col(self) -> int:
        return self.col + (self.end - self.start)

    def to(self, other: Span) -> Span:
        """The span from the start of self to the end of other (same line)."""
        return Span(self.start, max(self.end, other.end), self.line, self.col)

    def as_list(self) -> list[int]:
        col = self.col
        return [self.line, col, col + (self.end - self.start)]  # end_col, without its call


def line_span(line: int, col: int, length: int, line_offset: int) -> Span:
    """A span on `line` starting at 1-based `col`, given the line's offset in the file."""
    start = line_offset + col - 1
    return Span(start, start + length, line, col)


def blanked(text: str, ranges: Iterable[tuple[int, int]]) -> str:
    """`text` with each [start, end) of `ranges` (indices into it) turned to spaces: the words read
    past, every other column where the user wrote it (so spans of the rest stay true)."""
    chars = list(text)
    for start, end in ranges:
        chars[start:end] = " " * (end - start)
    return "".join(chars)
