"""Character offsets <-> LSP positions (0-based line, column in the negotiated code units).

Lines end where `cnlmc.lines` says (CRLF, LF or a lone CR: the LSP spec's definition), so the
server, the compiler and the editor count lines alike; form feed and U+2028 stay inside a line.
"""

from __future__ import annotations

from bisect import bisect_right

from lsprotocol import types

from ..lines import LINE_END
from ..spans import Span


def code_units(text: str, encoding: str) -> int:
    """How many code units `text` takes in the client's position encoding. A lone surrogate (JSON
    can carry one) counts as one UTF-16 unit and as the three bytes its UTF-8 form would take."""
    if text.isascii() or encoding == "utf-32":
        return len(text)
    if encoding == "utf-8":
        return len(text.encode("utf-8", "surrogatepass"))
    return len(text) + sum(1 for ch in text if ord(ch) > 0xFFFF)


def chars_for_units(line: str, units: int, encoding: str) -> int:
    """The character column that `units` code units into `line` reach (clamped to the line)."""
    if line.isascii() or encoding == "utf-32":
        return max(0, min(units, len(line)))
    used = 0
    for i, ch in enumerate(line):
        if used >= units:
            return i
        used += code_units(ch, encoding)
    return len(line)


def split_lines(text: str) -> tuple[list[int], list[str]]:
    """(offset where each line starts, each line's text without its line end)."""
    starts = [0]
    lines = []
    for end in LINE_END.finditer(text):
        lines.append(text[starts[-1] : end.start()])
        starts.append(end.end())
    lines.append(text[starts[-1] :])
    return starts, lines


class LineIndex:
    """Line starts of one text, for converting compiler offsets and spans to LSP ranges."""

    def __init__(self, text: str, encoding: str = "utf-16"):
        self.text = text
        self.encoding = encoding
        self.starts, self.lines = split_lines(text)

    def line_of(self, offset: int) -> int:
        return max(0, bisect_right(self.starts, offset) - 1)

    def line_end_offset(self, line: int) -> int:
        """The offset just past the text of `line` (before its line end)."""
        return self.starts[line] + len(self.lines[line])

    def position(self, offset: int) -> types.Position:
        offset = max(0, min(offset, len(self.text)))
        line = self.line_of(offset)
        col = min(offset - self.starts[line], len(self.lines[line]))
        return types.Position(line, code_units(self.lines[line][:col], self.encoding))

    def span_range(self, span: Span) -> types.Range:
        return types.Range(self.position(span.start), self.position(span.end))

    def line_col(self, position: types.Position) -> tuple[int, int] | None:
        """(0-based line, character column) of an LSP position; None when the line does not exist."""
        if position.line < 0 or position.line >= len(self.lines):
            return None
        line = self.lines[position.line]
        return position.line, chars_for_units(line, max(0, position.character), self.encoding)

    def offset(self, position: types.Position) -> int | None:
        found = self.line_col(position)
        if found is None:
            return None
        line, col = found
        return self.starts[line] + col

    def clamped_offset(self, position: types.Position) -> int:
        """The offset of a position as the LSP spec reads an edit's range: a line past the end is
        the end of the text, a column past the line's end is the line's end (never inside a CRLF)."""
        if position.line < 0:
            return 0
        if position.line >= len(self.lines):
            return len(self.text)
        found = self.offset(position)
        assert found is not None
        return found

    def line_end(self, line: int) -> types.Position:
        return types.Position(line, code_units(self.lines[line], self.encoding))

    def range_of(self, line: int, start_col: int, end_col: int) -> types.Range:
        text = self.lines[line]
        return types.Range(
            types.Position(line, code_units(text[:start_col], self.encoding)),
            types.Position(line, code_units(text[:end_col], self.encoding)),
        )
