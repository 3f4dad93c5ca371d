"""A line said as a statement about the thing (issue #14: writers, non-native speakers, chat):
'the table is oak', "it's brushed steel", 'the walls were painted a faded duck-egg blue', 'the
throne was hewn from black basalt', 'the oak table is varnished'.

The words up to the first copula of teaching.toml [statements] (and a `made` phrase after it) are
read past with a note, and the rest is the line; where the words before the copula name the
material ('the oak table is varnished'), only the copula goes, so the material and what is said of
it stay one line ('oak table varnished': varnished oak). Only a line that does not parse comes here
(cnlmc.document); the rest is read as any line is, blanked in place so its columns stay the line's.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from . import ast
from .diagnostics import Diagnostic, Severity
from .phrase_patterns import alternatives
from .spans import Span, blanked
from .suggest import teaching
from .tagged import NOTE_CODE

__all__ = ["Statement", "statement"]

#: parses a line (the statement's line with some columns blanked), its problems to the list
Parse = Callable[[str, list[Diagnostic]], ast.Item | None]


class Statement:
    """Where a statement's subject and copula stand in its line."""

    def __init__(self, subject: tuple[int, int], copula: tuple[int, int]) -> None:
        self.subject = subject  # columns of the words before the copula (after a leading article)
        self.copula = copula  # columns of the copula and its 'made' phrase


def statement(text: str) -> Statement | None:
    """The subject and copula of a line said as a statement, or None (no copula, or too many words
    before it)."""
    table = teaching()["statements"]
    low = text.lower()
    pattern = rf"(?:^|(?<=\s))(?:{alternatives(table['copulas'])})(?:\s+(?:{alternatives(table['made'])}))?(?=\s)"
    found = re.search(pattern, low)
    if found is None or not low[found.end() :].strip():
        return None
    before = low[: found.start()].split()
    if len(before) > int(table["subject_words"]):
        return None
    start = len(low) - len(low.lstrip())
    return Statement((start, found.start()), (found.start(), found.end()))


def read_statement(
    text: str,
    found: Statement,
    line: int,
    offset: int,
    parse: Parse,
    names_material: bool,
    kept: Sequence[tuple[int, int]] = (),
) -> tuple[ast.Material, list[Diagnostic]] | None:
    """The line read as its statement: the copula blanked where the subject names the material,
    else the subject too but for its colour words (`kept`, columns: 'the red chair is plastic' is
    red plastic); the material and its notes, or None when that does not read."""
    start = found.copula[0] if names_material else found.subject[0]
    end = found.copula[1]
    said: list[Diagnostic] = []
    node = parse(blanked(text, _between(start, end, kept)), said)  # the subject and copula, but its colours
    if not isinstance(node, ast.Material) or any(d.is_error for d in said):
        return None
    gone = " ".join(text[start:end].split())
    span = Span(offset + start, offset + end, line, start + 1)
    if names_material:  # 'the oak table is varnished'
        note = f"read past '{gone}': a statement about the material; what follows describes it"
    else:  # 'the table is oak', "it's brushed steel"
        note = f"read past '{gone}': a statement about the thing; what follows names the material"
    return node, [Diagnostic(span, Severity.NOTE, NOTE_CODE, note), *said]


def _between(start: int, end: int, kept: Sequence[tuple[int, int]]) -> list[tuple[int, int]]:
    """[start, end) less the `kept` ranges inside it (sorted), as ranges."""
    gaps, at = [], start
    for first, last in sorted(kept):
        if first > at:
            gaps.append((at, first))
        at = max(at, last)
    return [*gaps, (at, end)] if at < end else gaps
