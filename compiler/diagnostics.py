"""Diagnostics are values: passes collect them and go on; the CLI and the LSP render them."""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

from .lines import LineTable
from .spans import Span

FailureKey = tuple[int, int, str]  # (state under the top, top state, token type): parser.failure_key


@dataclass(frozen=True)
class Mistake:
    """A friendly message and hint for a syntax error, learned from grammar/bad_examples.toml."""

    message: str
    hint: str


class Severity(str, Enum):  # noqa: UP042 -- str() of a member stays "Severity.ERROR"
    ERROR = "error"
    WARNING = "warning"
    NOTE = "note"


@dataclass(frozen=True)
class Diagnostic:
    span: Span | None
    severity: Severity
    code: str
    message: str
    hints: tuple[str, ...] = ()
    suggestions: tuple[str, ...] = field(default=(), compare=False)

    @property
    def is_error(self) -> bool:
        return self.severity is Severity.ERROR

    def to_json(self) -> dict[str, Any]:
        out: dict[str, Any] = {"severity": self.severity.value, "code": self.code, "message": self.message}
        if self.span is not None:
            out["line"], out["col"], out["end_col"] = self.span.as_list()
        if self.hints:
            out["hints"] = list(self.hints)
        if self.suggestions:
            out["suggestions"] = list(self.suggestions)
        return out


def error(
    span: Span | None, code: str, message: str, hints: Iterable[str] = (), suggestions: Iterable[str] = ()
) -> Diagnostic:
    return Diagnostic(span, Severity.ERROR, code, message, tuple(hints), tuple(suggestions))


def warning(
    span: Span | None, code: str, message: str, hints: Iterable[str] = (), suggestions: Iterable[str] = ()
) -> Diagnostic:
    return Diagnostic(span, Severity.WARNING, code, message, tuple(hints), tuple(suggestions))


def did_you_mean(suggestions: Sequence[str]) -> tuple[str, ...]:
    """The hint line for a list of suggested words, or nothing."""
    if not suggestions:
        return ()
    quoted = " or ".join(f"'{s}'" for s in suggestions[:3])
    return (f"did you mean {quoted}?",)


def _escape_table(keep: str) -> dict[int, str]:
    """Control characters -> visible escapes: C0 and DEL and C1 (as \\x1b), line and paragraph
    separators and the bidirectional overrides (as \\u202e); the characters in `keep` stay."""
    codes = [*range(0x20), 0x7F, *range(0x80, 0xA0), 0x2028, 0x2029, *range(0x202A, 0x202F), *range(0x2066, 0x206A)]
    return {c: (f"\\x{c:02x}" if c < 0x100 else f"\\u{c:04x}") for c in codes if chr(c) not in keep}


_VISIBLE = _escape_table("\t\n")  # text: tabs and newlines are layout
_VISIBLE_LINE = _escape_table("")  # one line (a file name, a source line): everything escaped


def visible(text: str, *, one_line: bool = False) -> str:
    """`text` safe to print on a terminal: control characters (ESC, BEL, CR, C1, bidi overrides)
    become visible escapes such as `\\x1b`, so input cannot retitle, clear or rewrite the
    terminal. Tabs and newlines stay unless `one_line`."""
    return text.translate(_VISIBLE_LINE if one_line else _VISIBLE)


def render(diag: Diagnostic, source: str | LineTable, filename: str) -> str:
    """file:line:col: severity: message, then the source line, a caret line and hints; control
    characters from the source, the file name or the message are escaped (`visible`), and the
    caret sits under the escaped text of the span. Give a `LineTable` (or use `render_all`) to
    render many diagnostics of one source: a plain string is split into lines on every call."""
    name, message = visible(filename, one_line=True), visible(diag.message)
    hints = [f"{'  ' if diag.span is None else '     '}= {visible(h)}" for h in diag.hints]
    if diag.span is None:
        return "\n".join([f"{name}: {diag.severity.value}[{diag.code}]: {message}", *hints])
    span = diag.span
    head = f"{name}:{span.line}:{span.col}: {diag.severity.value}[{diag.code}]: {message}"
    table = source if isinstance(source, LineTable) else LineTable(source)
    raw = table.line(span.line).replace("\t", " ")
    width = max(1, min(span.end - span.start, max(1, len(raw) - span.col + 1)))
    before, marked = raw[: span.col - 1], raw[span.col - 1 : span.col - 1 + width]
    text = visible(raw, one_line=True)
    if len(text) != len(raw):  # escapes widen the line: measure the span in the escaped text
        width = max(1, len(visible(marked, one_line=True)))
        caret = " " * len(visible(before, one_line=True)) + "^" + "~" * (width - 1)
    else:
        caret = " " * (span.col - 1) + "^" + "~" * (width - 1)
    gutter = f"{span.line:>4} | "
    lines = [head, gutter + text, " " * (len(gutter) - 2) + "| " + caret, *hints]
    return "\n".join(lines)


def render_all(diags: Iterable[Diagnostic], source: str, filename: str) -> Iterator[str]:
    """Each diagnostic rendered (`render`), the source split into lines once for all of them."""
    table = LineTable(source)
    for diag in diags:
        yield render(diag, table, filename)


def has_errors(diags: Iterable[Diagnostic]) -> bool:
    return any(d.is_error for d in diags)
