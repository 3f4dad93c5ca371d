"""Diagnostics are values: passes collect them and go on; the CLI and the LSP render them."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

from .spans import Span

FailureKey = tuple[int, int, str]  # (parser stack depth, LALR state, token type) where a line failed to parse


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


def render(diag: Diagnostic, source: str, filename: str) -> str:
    """file:line:col: severity: message, then the source line, a caret line and hints."""
    if diag.span is None:
        head = f"{filename}: {diag.severity.value}[{diag.code}]: {diag.message}"
        return "\n".join([head, *(f"  = {h}" for h in diag.hints)])
    span = diag.span
    head = f"{filename}:{span.line}:{span.col}: {diag.severity.value}[{diag.code}]: {diag.message}"
    text = _source_line(source, span.line)
    width = max(1, min(span.end - span.start, max(1, len(text) - span.col + 1)))
    caret = " " * (span.col - 1) + "^" + "~" * (width - 1)
    gutter = f"{span.line:>4} | "
    lines = [head, gutter + text, " " * (len(gutter) - 2) + "| " + caret]
    lines += [f"     = {h}" for h in diag.hints]
    return "\n".join(lines)


def _source_line(source: str, line: int) -> str:
    lines = source.splitlines()
    if 1 <= line <= len(lines):
        return lines[line - 1].replace("\t", " ")
    return ""


def has_errors(diags: Iterable[Diagnostic]) -> bool:
    return any(d.is_error for d in diags)
