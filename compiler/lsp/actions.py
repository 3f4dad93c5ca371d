"""Quick fixes: replace a misspelled word with a suggestion, remove a contradictory or
inapplicable modifier (W101, W102, W103), use the nearest named colour for an unknown one."""

from __future__ import annotations

import re

from lsprotocol import types
from rapidfuzz import fuzz, process

from ..diagnostics import Diagnostic
from ..lexicon import Lexicon
from .completion import accepted_terminals
from .diagnostics import span_of, to_lsp
from .incremental import Snapshot
from .lines import line_words, tag_text

REMOVABLE = {"W101", "W102", "W103"}
COLOUR_SUFFIXES = re.compile(r"(?:-?ish|y)$")
COLOUR_CUTOFF = 70


def quick_fixes(snapshot: Snapshot, uri: str, where: types.Range, lexicon: Lexicon) -> list[types.CodeAction]:
    fixes = []
    for diag in snapshot.diagnostics_between(where.start.line, where.end.line):
        line = span_of(diag).line - 1
        if not where.start.line <= line <= where.end.line:
            continue
        lsp_diag = to_lsp(diag, snapshot.index, uri)
        if diag.code == "E001":
            fixes += spelling_fixes(snapshot, uri, diag, lsp_diag, lexicon)
        elif diag.code in REMOVABLE:
            fixes.append(removal_fix(snapshot, uri, diag, lsp_diag, lexicon))
    return fixes


def _columns(snapshot: Snapshot, diag: Diagnostic) -> tuple[int, int, int]:
    line = span_of(diag).line - 1
    start = span_of(diag).start - snapshot.index.starts[line]
    return line, start, start + (span_of(diag).end - span_of(diag).start)


def _edit(snapshot: Snapshot, uri: str, line: int, start: int, end: int, text: str) -> types.WorkspaceEdit:
    return types.WorkspaceEdit(changes={uri: [types.TextEdit(snapshot.index.range_of(line, start, end), text)]})


def spelling_fixes(
    snapshot: Snapshot, uri: str, diag: Diagnostic, lsp_diag: types.Diagnostic, lexicon: Lexicon
) -> list[types.CodeAction]:
    line, start, end = _columns(snapshot, diag)
    word = snapshot.index.lines[line][start:end]
    fixes = [
        types.CodeAction(
            title=f"Replace '{word}' with '{s}'",
            kind=types.CodeActionKind.QuickFix,
            diagnostics=[lsp_diag],
            is_preferred=(i == 0),
            edit=_edit(snapshot, uri, line, start, end, s),
        )
        for i, s in enumerate(diag.suggestions)
    ]
    colour = nearest_colour_name(word, lexicon)
    if colour and colour not in diag.suggestions and colour_fits(snapshot, line, start, lexicon):
        fixes.append(
            types.CodeAction(
                title=f"Use the nearest named colour '{colour}'",
                kind=types.CodeActionKind.QuickFix,
                diagnostics=[lsp_diag],
                is_preferred=not fixes,
                edit=_edit(snapshot, uri, line, start, end, colour),
            )
        )
    return fixes


def nearest_colour_name(word: str, lexicon: Lexicon) -> str | None:
    """The named colour an unknown colour-like word ('bluish', 'grren', 'navyblue') is nearest to."""
    if not word[:1].isalpha():
        return None
    stem = word.lower()
    if len(COLOUR_SUFFIXES.sub("", stem)) >= 3:
        stem = COLOUR_SUFFIXES.sub("", stem)
    names = {surface: key for key, e in lexicon.all_of("colours").items() for surface in (key, *e.get("aliases", []))}
    found = process.extractOne(stem, list(names), scorer=fuzz.ratio, score_cutoff=COLOUR_CUTOFF)
    return names[found[0]] if found else None


def colour_fits(snapshot: Snapshot, line: int, start: int, lexicon: Lexicon) -> bool:
    """Whether the grammar accepts a colour where the unknown word stands."""
    before = [t for t in tag_text(snapshot.index.lines[line][:start], lexicon) if t.candidates]
    return "COLOR" in accepted_terminals(before)


def removal_fix(
    snapshot: Snapshot, uri: str, diag: Diagnostic, lsp_diag: types.Diagnostic, lexicon: Lexicon
) -> types.CodeAction:
    line, start, end = _columns(snapshot, diag)
    text = snapshot.index.lines[line]
    start = _with_adverbs(snapshot, line, start, lexicon)
    start, end = _with_separator(text, start, end)
    word = text[span_of(diag).start - snapshot.index.starts[line] : _columns(snapshot, diag)[2]]
    return types.CodeAction(
        title=f"Remove '{word}'",
        kind=types.CodeActionKind.QuickFix,
        diagnostics=[lsp_diag],
        is_preferred=True,
        edit=_edit(snapshot, uri, line, start, end, ""),
    )


def _with_adverbs(snapshot: Snapshot, line: int, start: int, lexicon: Lexicon) -> int:
    """Extend a removal to the adverbs right before the word ('lightly anodized')."""
    words = [w for w in line_words(snapshot, line, lexicon) if w.end <= start]
    for word in reversed(words):
        if word.category != "adverbs" or snapshot.index.lines[line][word.end : start].strip():
            break
        start = word.start
    return start


def _with_separator(text: str, start: int, end: int) -> tuple[int, int]:
    """Remove the word with the spaces after it, or with the comma after or before it."""
    after = end
    while after < len(text) and text[after] == " ":
        after += 1
    if after < len(text) and text[after] == ",":
        after += 1
        while after < len(text) and text[after] == " ":
            after += 1
        return start, after
    before = start
    while before > 0 and text[before - 1] == " ":
        before -= 1
    if before > 0 and text[before - 1] == ",":
        return before - 1, end
    return start, after
