"""Analysing a large document of unknown words yields to other requests and stops when it goes
stale (#13: work on huge documents must not stall the server). Each line is one step of the
analysis (lsp/work.py runs steps in time slices). Ordering-based: no wall-clock thresholds."""

from __future__ import annotations

import random
import string

import pytest

from .rawclient import RawServer

pytestmark = pytest.mark.lsp

SMALL = "file:///tmp/cnlmc-tests/small.cnl"
LARGE = "file:///tmp/cnlmc-tests/unknown-words-{}.cnl"


def unknown_words(lines: int, seed: int = 4) -> str:
    rng = random.Random(seed)
    word = lambda: "".join(rng.choice(string.ascii_lowercase) for _ in range(rng.randint(5, 9)))
    return "\n".join(f"{word()} {word()} {word()} {word()} {word()}" for _ in range(lines))


def is_publish(uri: str):
    return lambda m: m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri


def position_of(raw: RawServer, wanted) -> int:
    raw.wait_for(wanted, timeout=180)
    return next(i for i, m in enumerate(raw.received) if wanted(m))


@pytest.fixture(scope="module")
def raw():
    with RawServer() as server:
        server.initialize(debounceMs=0)
        server.open(SMALL, "hull: lightly brushed aluminum")
        server.diagnostics(SMALL, 1)
        yield server
        assert server.shutdown_and_exit() == 0


def test_a_hover_is_answered_while_unknown_words_are_analysed(raw):
    large = LARGE.format(1)
    raw.open(large, unknown_words(400))
    hover = raw.request("textDocument/hover", {"textDocument": {"uri": SMALL}, "position": {"line": 0, "character": 8}})
    answered = position_of(raw, lambda m: m.get("id") == hover and "method" not in m)
    published = position_of(raw, is_publish(large))
    assert answered < published
    assert len(raw.received[published]["params"]["diagnostics"]) >= 1800  # the analysis went on to the end


def test_an_edit_stops_the_stale_analysis(raw):
    large = LARGE.format(2)
    raw.open(large, unknown_words(400, seed=5))
    raw.change(large, 2, {"text": "blu plastic"})
    first = raw.received[position_of(raw, is_publish(large))]
    assert first["params"]["version"] == 2  # version 1 was never finished nor published
    assert [d["code"] for d in first["params"]["diagnostics"]] == ["E001"]
