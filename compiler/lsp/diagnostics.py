"""Compiler diagnostics -> LSP diagnostics: exact ranges, codes, hints as related information."""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Generator
from typing import Any

from lsprotocol import types
from pygls.protocol import default_converter

from ..diagnostics import Diagnostic, Severity
from ..spans import Span
from .incremental import Block, BlockResult, Snapshot
from .positions import LineIndex

SEVERITIES = {
    Severity.ERROR: types.DiagnosticSeverity.Error,
    Severity.WARNING: types.DiagnosticSeverity.Warning,
    Severity.NOTE: types.DiagnosticSeverity.Information,
}


def span_of(diag: Diagnostic) -> Span:
    """Where a diagnostic the editor shows stands: each has a span (incremental._with_spans)."""
    assert diag.span is not None, diag
    return diag.span


def to_lsp(diag: Diagnostic, index: LineIndex, uri: str, first_line: int = 0) -> types.Diagnostic:
    """`diag`'s span is on line first_line + span.line (0-based); only its line and columns are used."""
    span = span_of(diag)
    line = first_line + span.line - 1
    start = span.col - 1
    where = index.range_of(line, start, start + (span.end - span.start))
    related = [types.DiagnosticRelatedInformation(types.Location(uri, where), hint) for hint in diag.hints]
    return types.Diagnostic(
        range=where,
        message=diag.message,
        severity=SEVERITIES[diag.severity],
        code=diag.code,
        source="cnlmc",
        related_information=related or None,
        data={"suggestions": list(diag.suggestions)} if diag.suggestions else None,
    )


#: At most this many diagnostics are published for one document (then one note says how many more).
MAX_PUBLISHED_DIAGNOSTICS = 50_000
#: At most this many converted diagnostics are kept between edits, over all documents.
MAX_CACHED_DIAGNOSTICS = 100_000

BlockKey = tuple[BlockResult, int, str, str]


class LspDiagnostics:
    """LSP diagnostics as JSON-ready dicts, per block and first line: reused while the block's
    text and line stay, so an edit converts (and lsprotocol's converter unstructures) one block.
    Bounded in diagnostics kept; a closed document's are dropped (`forget`)."""

    def __init__(self, limit: int = MAX_CACHED_DIAGNOSTICS):
        self.limit = limit
        self.kept = 0
        self._by_block: OrderedDict[BlockKey, list[dict[str, Any]]] = OrderedDict()
        self._converter = default_converter()

    def of(self, snapshot: Snapshot, uri: str) -> list[dict[str, Any]]:
        steps = self.steps(snapshot, uri)
        while True:
            try:
                next(steps)
            except StopIteration as done:
                return done.value  # type: ignore[no-any-return]

    def steps(self, snapshot: Snapshot, uri: str) -> Generator[None, None, list[dict[str, Any]]]:
        """The document's diagnostics, one block per step (lsp/work.py runs them in slices)."""
        out: list[dict[str, Any]] = []
        for block in snapshot.blocks:
            if not block.result.diagnostics:
                continue
            out += self._block(block, snapshot, uri)
            if len(out) > MAX_PUBLISHED_DIAGNOSTICS:
                return out[:MAX_PUBLISHED_DIAGNOSTICS] + [self._too_many(len(out), snapshot, uri)]
            yield
        return out

    def _block(self, block: Block, snapshot: Snapshot, uri: str) -> list[dict[str, Any]]:
        key = (block.result, block.first_line, uri, snapshot.index.encoding)
        found = self._by_block.get(key)
        if found is not None:
            self._by_block.move_to_end(key)
            return found
        found = [
            self._converter.unstructure(to_lsp(d, snapshot.index, uri, block.first_line))
            for d in block.result.diagnostics
        ]
        self._by_block[key] = found
        self.kept += len(found)
        while self.kept > self.limit and self._by_block:
            _old, dropped = self._by_block.popitem(last=False)
            self.kept -= len(dropped)
        return found

    def _too_many(self, found: int, snapshot: Snapshot, uri: str) -> dict[str, Any]:
        note = types.Diagnostic(
            range=snapshot.index.range_of(0, 0, 0),
            message=f"{found}+ problems in this document; the first {MAX_PUBLISHED_DIAGNOSTICS} are shown "
            "(run `cnlmc compile` on the file for all of them)",
            severity=types.DiagnosticSeverity.Information,
            source="cnlmc",
        )
        unstructured: dict[str, Any] = self._converter.unstructure(note)
        return unstructured

    def forget(self, uri: str) -> None:
        """Drop what was kept for a closed document."""
        for key in [k for k in self._by_block if k[2] == uri]:
            self.kept -= len(self._by_block.pop(key))

    def clear(self) -> None:
        self._by_block.clear()
        self.kept = 0


def all_to_lsp(snapshot: Snapshot, uri: str) -> list[types.Diagnostic]:
    return [to_lsp(d, snapshot.index, uri) for d in snapshot.diagnostics]
