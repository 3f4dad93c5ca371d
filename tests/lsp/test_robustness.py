"""Malformed requests, a 1 MB document, 200 rapid edits, unicode edits: no crash, right answers."""

from __future__ import annotations

import json

import pytest
from lsprotocol import types

from cnlmc.api import compile_source

from .conftest import fresh_uri, open_document, raw_request, replace_all, send_raw, wait_diagnostics

BLOCK = [
    "hull: lightly brushed, blue anodized aluminum",
    "darker blue",
    "blu plastic",
    "# comment",
    "polished brushed steel",
    "white varnished oak with a clear coat",
    "",
]

pytestmark = [pytest.mark.lsp, pytest.mark.asyncio(loop_scope="module")]


def doc_id(uri):
    return types.TextDocumentIdentifier(uri=uri)


async def alive(client, uri):
    """The server still answers."""
    hover = await client.text_document_hover_async(types.HoverParams(doc_id(uri), types.Position(0, 8)))
    return hover is not None


async def test_unknown_document_and_out_of_range_positions(client):
    ghost = doc_id("file:///nowhere/never-opened.cnl")
    assert await client.text_document_hover_async(types.HoverParams(ghost, types.Position(0, 0))) is None
    assert await client.text_document_completion_async(types.CompletionParams(ghost, types.Position(3, 3))) is None
    assert list(await client.text_document_document_color_async(types.DocumentColorParams(ghost))) == []
    uri = fresh_uri("range")
    open_document(client, uri, "blue plastic")
    await wait_diagnostics(client, uri, 1)
    far = types.Position(999, 999)
    assert await client.text_document_hover_async(types.HoverParams(doc_id(uri), far)) is None
    assert await client.text_document_completion_async(types.CompletionParams(doc_id(uri), far)) is None
    wide = await client.text_document_hover_async(types.HoverParams(doc_id(uri), types.Position(0, 10**6)))
    assert wide is not None  # clamped to the end of the line: 'plastic'
    actions = await client.text_document_code_action_async(
        types.CodeActionParams(doc_id(uri), types.Range(far, far), types.CodeActionContext(diagnostics=[]))
    )
    assert list(actions) == []
    hints = await client.text_document_inlay_hint_async(types.InlayHintParams(doc_id(uri), types.Range(far, far)))
    assert list(hints) == []
    assert await alive(client, uri)


async def test_malformed_json_rpc_does_not_kill_the_server(client):
    uri = fresh_uri("malformed")
    open_document(client, uri, "blue plastic")
    await wait_diagnostics(client, uri, 1)
    raw_request(client, "textDocument/hover", {"textDocument": {"uri": uri}})  # no position
    raw_request(
        client, "textDocument/hover", {"textDocument": {"uri": uri}, "position": {"line": -1, "character": "x"}}
    )
    raw_request(client, "textDocument/completion", None)
    raw_request(client, "cnlmc/noSuchMethod", {})
    send_raw(client, b"{ this is not json")
    send_raw(
        client,
        json.dumps(
            {
                "jsonrpc": "2.0",
                "method": "textDocument/didChange",
                "params": {
                    "textDocument": {"uri": "file:///ghost.cnl", "version": 3},
                    "contentChanges": [{"text": "x"}],
                },
            }
        ).encode(),
    )
    assert await alive(client, uri)
    open_document(client, fresh_uri("after-malformed"), "blu plastic")
    assert await alive(client, uri)


async def test_one_megabyte_document(client):
    uri = fresh_uri("big")
    block = "\n".join(BLOCK)
    copies = 1_000_000 // (len(block) + 1) + 1
    text = "\n".join([block] * copies)
    assert len(text) >= 1_000_000
    open_document(client, uri, text)
    diags = await wait_diagnostics(client, uri, 1, timeout=60)
    per_block = compile_source(block, "x").diagnostics
    assert len(diags) == copies * len(per_block)
    last = diags[-1]
    assert last.range.start.line == (copies - 1) * len(BLOCK) + BLOCK.index("polished brushed steel")
    # an edit at the end of the big document
    replace_all(client, uri, text + "\nbleu steel", 2)
    after = await wait_diagnostics(client, uri, 2, timeout=60)
    assert len(after) == len(diags) + 1 and after[-1].range.start.line == copies * len(BLOCK)
    assert await alive(client, uri)


async def test_two_hundred_rapid_edits(client):
    uri = fresh_uri("rapid")
    text = "\n".join(BLOCK * 20)
    open_document(client, uri, text)
    await wait_diagnostics(client, uri, 1)
    typed = "lightly brushed, pale orange anodized titanium with a clear coat # done "
    line = len(BLOCK * 20)  # a new last line, typed one character at a time, with some backspaces
    current = text + "\n"
    version = 1
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(uri=uri, version=version + 1),
            [types.TextDocumentContentChangePartial(range=_at(line - 1, len(BLOCK[-1])), text="\n")],
        )
    )
    version += 1
    col = 0
    for i in range(199):
        if i % 10 == 9 and col > 0:  # backspace
            change = types.TextDocumentContentChangePartial(
                range=types.Range(types.Position(line, col - 1), types.Position(line, col)), text=""
            )
            current = current[:-1]
            col -= 1
        else:
            ch = typed[col % len(typed)]
            change = types.TextDocumentContentChangePartial(range=_at(line, col), text=ch)
            current += ch
            col += 1
        version += 1
        client.text_document_did_change(
            types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(uri=uri, version=version), [change])
        )
    final = await wait_diagnostics(client, uri, version)
    expected = compile_source(current, "x").diagnostics
    assert [(d.code, d.span.line - 1, d.span.col - 1) for d in expected] == [
        (d.code, d.range.start.line, d.range.start.character) for d in final
    ]
    stale = [p for p in client.published if p.uri == uri and 1 < p.version < version]
    assert len(stale) < 20  # debounced: most intermediate versions were never analysed


def _at(line, col):
    return types.Range(types.Position(line, col), types.Position(line, col))


async def test_unicode_edit_before_a_word(client):
    uri = fresh_uri("uni")
    open_document(client, uri, "blu plastic\nbleu steel")
    await wait_diagnostics(client, uri, 1)
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(uri=uri, version=2),
            [types.TextDocumentContentChangePartial(range=_at(1, 0), text="漢字 🎨🎨 ")],
        )
    )
    diags = await wait_diagnostics(client, uri, 2)
    bleu = next(d for d in diags if "'bleu'" in d.message)
    # '漢字 🎨🎨 ' = 2 + 1 + 4 + 1 = 8 UTF-16 code units
    assert bleu.range == types.Range(types.Position(1, 8), types.Position(1, 12))
    hover = await client.text_document_hover_async(types.HoverParams(doc_id(uri), types.Position(1, 14)))
    assert "**steel**" in hover.contents.value
    assert hover.range == types.Range(types.Position(1, 13), types.Position(1, 18))
