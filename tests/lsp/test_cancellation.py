"""Long requests do not stall the server (#13: documentColor on a 5 MB document blocked every
other request for 14 s, and $/cancelRequest was ignored): whole-document work runs in time
slices, so a hover sent after it is answered first, and a cancelled request stops and answers
RequestCancelled (-32800). Ordering-based: no wall-clock thresholds."""

from __future__ import annotations

import pytest

from .rawclient import RawServer

pytestmark = pytest.mark.lsp

BLOCK = "hull: lightly brushed, blue anodized aluminum\ndarker blue\nblu plastic\n# comment\npolished brushed steel\n"
URI = "file:///tmp/cnlmc-tests/big-colours.cnl"


@pytest.fixture(scope="module")
def big():
    with RawServer() as raw:
        raw.initialize(debounceMs=0)
        text = BLOCK * (400_000 // len(BLOCK))
        raw.open(URI, text)
        raw.diagnostics(URI, 1, timeout=120)
        yield raw


def colours_request(raw: RawServer) -> int | str:
    return raw.request("textDocument/documentColor", {"textDocument": {"uri": URI}})


def hover_request(raw: RawServer, line: int = 0) -> int | str:
    return raw.request("textDocument/hover", {"textDocument": {"uri": URI}, "position": {"line": line, "character": 8}})


def arrival(raw: RawServer, msg_id) -> int:
    raw.response(msg_id, timeout=120)
    return next(i for i, m in enumerate(raw.received) if m.get("id") == msg_id and "method" not in m)


def test_a_hover_is_answered_while_document_colours_are_computed(big):
    colours = colours_request(big)
    hover = hover_request(big)
    assert arrival(big, hover) < arrival(big, colours)
    assert "lightly" in big.response(hover)["result"]["contents"]["value"]
    swatches = big.response(colours)["result"]
    assert len(swatches) >= 2 * (400_000 // len(BLOCK))  # every colour phrase and material swatch


def test_a_cancelled_request_answers_request_cancelled(big):
    colours = colours_request(big)
    big.notify("$/cancelRequest", {"id": colours})
    assert big.response(colours, timeout=120)["error"]["code"] == -32800
    tokens = big.request("textDocument/semanticTokens/full", {"textDocument": {"uri": URI}})
    hover = hover_request(big, 5)
    big.notify("$/cancelRequest", {"id": tokens})
    assert big.response(tokens, timeout=120)["error"]["code"] == -32800
    assert "result" in big.response(hover)
    assert big.shutdown_and_exit() == 0
