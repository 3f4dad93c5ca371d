"""Compiler diagnostics -> LSP diagnostics: exact ranges, codes, hints as related information."""

from __future__ import annotations

from lsprotocol import types

from ..diagnostics import Severity
from .positions import LineIndex

SEVERITIES = {
    Severity.ERROR: types.DiagnosticSeverity.Error,
    Severity.WARNING: types.DiagnosticSeverity.Warning,
    Severity.NOTE: types.DiagnosticSeverity.Information,
}


def to_lsp(diag, index: LineIndex, uri: str) -> types.Diagnostic:
    where = index.span_range(diag.span)
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


def all_to_lsp(snapshot, uri: str) -> list[types.Diagnostic]:
    return [to_lsp(d, snapshot.index, uri) for d in snapshot.diagnostics]
