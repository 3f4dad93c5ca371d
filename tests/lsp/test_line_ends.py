"""The server's copy of a document stays the editor's (#13): lines end at CRLF, LF and a lone CR
(the LSP spec), never at form feed or U+2028, in every position encoding; incremental edits land
where the editor made them and diagnostics sit on the editor's lines."""

from __future__ import annotations

import re

import pytest
from lsprotocol import types

from cnlmc.api import compile_source
from cnlmc.lsp.documents import DocumentStore

from .rawclient import RawServer

pytestmark = pytest.mark.lsp

ENCODINGS = ["utf-8", "utf-16", "utf-32"]
SPEC_LINE_END = re.compile(r"\r\n|\n|\r")


def units(text: str, encoding: str) -> int:
    if encoding == "utf-8":
        return len(text.encode("utf-8"))
    if encoding == "utf-16":
        return len(text.encode("utf-16-le")) // 2
    return len(text)


def editor_lines(text: str) -> list[tuple[int, str]]:
    """(offset, text) of each line as the LSP spec (and so the editor) counts them."""
    out, start = [], 0
    for end in SPEC_LINE_END.finditer(text):
        out.append((start, text[start : end.start()]))
        start = end.end()
    return [*out, (start, text[start:])]


def position(text: str, offset: int, encoding: str) -> dict:
    lines = editor_lines(text)
    number = max(i for i, (start, _) in enumerate(lines) if start <= offset)
    start, line = lines[number]
    return {"line": number, "character": units(line[: offset - start], encoding)}


def edit(text: str, old: str, new: str, encoding: str) -> tuple[str, dict]:
    """The editor replaces the first `old` with `new`: the new text and the change it sends."""
    at = text.index(old)
    change = {
        "range": {"start": position(text, at, encoding), "end": position(text, at + len(old), encoding)},
        "text": new,
    }
    return text[:at] + new + text[at + len(old) :], change


def expected(text: str, encoding: str) -> list[tuple[str, int, int, str]]:
    """(code, line, character, message) of compiling the editor's text, in `encoding` units."""
    lines = editor_lines(text)
    out = []
    for diag in compile_source(text, "x.cnl").diagnostics:
        if diag.span is None:
            continue
        line = lines[diag.span.line - 1][1]
        out.append((diag.code, diag.span.line - 1, units(line[: diag.span.col - 1], encoding), diag.message))
    return out


def published(diags: list[dict]) -> list[tuple[str, int, int, str]]:
    return [(d["code"], d["range"]["start"]["line"], d["range"]["start"]["character"], d["message"]) for d in diags]


DOCUMENT = (
    "hull: blue plastic\f# a form feed inside a line\n"
    "bleu steel\u2028 # a line separator inside a line\n"
    "🎨 red steel\rbleu oak\r\n"
    "deck: white varnished oak\n"
    "blu plastic"
)
EDITS = [
    ("bleu steel", "blu steel"),  # after a form feed on the line above
    ("blu steel", "bleu steal"),
    ("bleu oak", "blue oak"),  # after a lone CR
    ("varnished", "varnishd"),  # after a CRLF
    ("\f# a form", "\f\u2028# a form"),  # more separators that do not end lines
    ("red steel\rblue", "red steel\nblue"),  # a lone CR becomes a LF
    ("blu plastic", "blu plastic\rbleu"),  # a new lone CR at the end
]


@pytest.mark.parametrize("encoding", ENCODINGS)
def test_edits_around_separators_land_where_the_editor_made_them(encoding):
    uri = f"file:///tmp/cnlmc-tests/line-ends-{encoding}.cnl"
    with RawServer() as raw:
        raw.initialize(encoding, debounceMs=0)
        text = DOCUMENT
        raw.open(uri, text)
        assert published(raw.diagnostics(uri, 1)) == expected(text, encoding)
        for version, (old, new) in enumerate(EDITS, start=2):
            text, change = edit(text, old, new, encoding)
            raw.change(uri, version, change)
            assert published(raw.diagnostics(uri, version)) == expected(text, encoding), (old, new)
        hover = raw.call(
            "textDocument/hover",
            {"textDocument": {"uri": uri}, "position": position(text, text.index("steal") + 1, encoding)},
        )
        assert "steal" in hover["result"]["contents"]["value"]
        assert raw.shutdown_and_exit() == 0


@pytest.mark.parametrize("encoding", ENCODINGS)
def test_document_store_applies_edits_with_the_spec_line_ends(encoding):
    store = DocumentStore()
    text = DOCUMENT
    store.open("u", text, 1)
    for version, (old, new) in enumerate(EDITS, start=2):
        text, change = edit(text, old, new, encoding)
        where = change["range"]
        partial = types.TextDocumentContentChangePartial(
            range=types.Range(types.Position(**where["start"]), types.Position(**where["end"])), text=change["text"]
        )
        store.change("u", version, [partial], encoding)
        assert store.get("u").text == text


def test_positions_past_the_end_clamp_as_the_spec_says():
    store = DocumentStore()
    store.open("u", "ab\r\ncd", 1)
    far = types.Range(types.Position(0, 99), types.Position(0, 99))  # past the line's end: before the CRLF
    store.change("u", 2, [types.TextDocumentContentChangePartial(range=far, text="X")], "utf-16")
    assert store.get("u").text == "abX\r\ncd"
    beyond = types.Range(types.Position(7, 0), types.Position(9, 0))  # past the last line: the end
    store.change("u", 3, [types.TextDocumentContentChangePartial(range=beyond, text="!")], "utf-16")
    assert store.get("u").text == "abX\r\ncd!"
    assert store.change("not-open", 1, [], "utf-16") is None
