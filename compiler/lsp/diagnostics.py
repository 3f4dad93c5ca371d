"""Compiler diagnostics -> LSP diagnostics: exact ranges, codes, hints as related information."""

from __future__ import annotations

from collections import OrderedDict
from typing import Any

from lsprotocol import types
from pygls.protocol import default_converter

from ..diagnostics import Diagnostic, Severity
from ..spans import Span
from .incremental import BlockResult, Snapshot
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


class LspDiagnostics:
    """LSP diagnostics as JSON-ready dicts, per block and first line: reused while the block's
    text and line stay, so an edit converts (and lsprotocol's converter unstructures) one block."""

    def __init__(self, limit: int = 20000):
        self.limit = limit
        self._by_block: OrderedDict[tuple[BlockResult, int, str, str], list[dict[str, Any]]] = OrderedDict()
        self._converter = default_converter()

    def of(self, snapshot: Snapshot, uri: str) -> list[dict[str, Any]]:
        out: list[dict[str, Any]] = []
        for block in snapshot.blocks:
            relative = block.result.diagnostics
            if not relative:
                continue
            key = (block.result, block.first_line, uri, snapshot.index.encoding)
            found = self._by_block.get(key)
            if found is None:
                found = [
                    self._converter.unstructure(to_lsp(d, snapshot.index, uri, block.first_line)) for d in relative
                ]
                self._by_block[key] = found
                if len(self._by_block) > self.limit:
                    self._by_block.popitem(last=False)
            else:
                self._by_block.move_to_end(key)
            out += found
        return out


def all_to_lsp(snapshot: Snapshot, uri: str) -> list[types.Diagnostic]:
    return [to_lsp(d, snapshot.index, uri) for d in snapshot.diagnostics]
