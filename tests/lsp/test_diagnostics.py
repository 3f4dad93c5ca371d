"""Diagnostics over stdio: on open, on change, exact UTF-16 ranges, codes, hints."""

from __future__ import annotations

import pytest
from lsprotocol import types

from cnlmc.api import compile_source

from .conftest import open_fixture, position_of, replace_all, wait_diagnostics

pytestmark = [pytest.mark.lsp, pytest.mark.asyncio(loop_scope="module")]


async def test_open_publishes_every_error_and_warning(client):
    uri, text, diags = await open_fixture(client, "materials.cnl")
    expected = compile_source(text, "materials.cnl").diagnostics
    assert sorted(d.code for d in diags) == sorted(d.code for d in expected)
    assert {"E001", "W101", "W102", "W103"} <= {d.code for d in diags}


async def test_ranges_codes_and_hints(client):
    uri, text, diags = await open_fixture(client, "materials.cnl")
    unknown = next(d for d in diags if d.code == "E001")
    start = position_of(text, "blu plastic")
    assert unknown.range == types.Range(start, types.Position(start.line, start.character + 3))
    assert unknown.severity == types.DiagnosticSeverity.Error
    assert unknown.source == "cnlmc"
    assert unknown.related_information[0].message.startswith("did you mean 'blue'")
    contradiction = next(d for d in diags if d.code == "W101")
    assert contradiction.severity == types.DiagnosticSeverity.Warning
    # adjectives apply in their canonical order (brushed shapes, polished finishes), so the
    # warning stands on the word that wins: 'polished'
    polished = position_of(text, "polished brushed steel")
    assert contradiction.range.start == polished


async def test_unicode_before_words_keeps_ranges_right(client):
    uri, text, diags = await open_fixture(client, "unicode.cnl")
    blu = next(d for d in diags if "'blu'" in d.message)
    bleu = next(d for d in diags if "'bleu'" in d.message)
    # '😀' is two UTF-16 code units: 'blu' starts at character 3, not 2
    assert blu.range == types.Range(types.Position(1, 3), types.Position(1, 6))
    # '木材: 🎨 ' is 2 + 2 + 2 + 1 = 7 code units
    assert bleu.range == types.Range(types.Position(2, 7), types.Position(2, 11))


async def test_change_updates_diagnostics(client):
    uri, text, diags = await open_fixture(client, "materials.cnl")
    fixed = text.replace("blu plastic", "blue plastic")
    replace_all(client, uri, fixed, 2)
    after = await wait_diagnostics(client, uri, 2)
    assert "E001" not in {d.code for d in after}
    assert len(after) == len(diags) - 1


async def test_incremental_change_is_applied(client):
    uri, text, _diags = await open_fixture(client, "clean.cnl")
    start = position_of(text, "plastic")
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(uri=uri, version=2),
            [
                types.TextDocumentContentChangePartial(
                    range=types.Range(start, types.Position(start.line, start.character + 7)), text="plastid"
                )
            ],
        )
    )
    after = await wait_diagnostics(client, uri, 2)
    assert [d.code for d in after] == ["E001"]
    assert after[0].range.start == start


async def test_clean_document_has_no_diagnostics(client):
    _uri, _text, diags = await open_fixture(client, "clean.cnl")
    assert list(diags) == []
