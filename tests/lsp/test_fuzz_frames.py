"""A bounded fuzz over raw LSP frames (#13): random headers, lengths and bodies (JSON-RPC shaped
messages with random methods and params, garbage bytes) sent to one real `cnlmc lsp`. After
every example the server must answer a request, and at the end it must still be alive, answer
a hover, and have written no traceback. Derandomized, so CI runs the same examples every time.

A declared length is either at most SLACK bytes beyond the body or far over the frame limit: a
length the server cannot distinguish from a real, still arriving body would swallow the probe
(that is the protocol, not a bug), so each example ends with SLACK bytes of blank lines."""

from __future__ import annotations

import json

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cnlmc.lsp.transport import MAX_FRAME_BYTES

from .rawclient import RawServer

pytestmark = pytest.mark.lsp

SLACK = 64
URI = "file:///tmp/cnlmc-tests/fuzz.cnl"
URIS = [URI, "file:///tmp/cnlmc-tests/fuzz-other.cnl", "untitled:x", ""]
METHODS = [
    "textDocument/hover",
    "textDocument/completion",
    "textDocument/documentColor",
    "textDocument/colorPresentation",
    "textDocument/semanticTokens/full",
    "textDocument/codeAction",
    "textDocument/inlayHint",
    "textDocument/didOpen",
    "textDocument/didChange",
    "textDocument/didClose",
    "workspace/didChangeConfiguration",
    "$/cancelRequest",
    "$/setTrace",
    "initialized",
    "cnlmc/unknown",
]
PHRASES = ["blue plastic", "blu steel", "\r", "\n", "\r\n", "\f", "\u2028", "# ``` [x](y)", "😀", "\ud800", "darker"]

json_leaf = st.none() | st.booleans() | st.integers(-(2**70), 2**70) | st.floats(allow_nan=False) | st.text(max_size=8)
json_value = st.recursive(
    json_leaf,
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=6), inner, max_size=3),
    max_leaves=8,
)
number = st.one_of(st.integers(-3, 40), st.integers(-(2**40), 2**40), st.sampled_from([0, 2**31, 2**64]))
point = st.fixed_dictionaries({"line": number, "character": number})
position = point | point | json_value
text = st.lists(st.sampled_from(PHRASES), max_size=6).map(" ".join)
shaped_params = st.fixed_dictionaries(
    {
        "textDocument": st.fixed_dictionaries(
            {"uri": st.sampled_from(URIS)},
            optional={"version": number, "text": text, "languageId": st.just("cnl")},
        ),
        "position": position,
    },
    optional={
        "range": st.fixed_dictionaries({"start": position, "end": position}),
        "contentChanges": st.lists(
            st.fixed_dictionaries(
                {"text": text}, optional={"range": st.fixed_dictionaries({"start": position, "end": position})}
            ),
            max_size=3,
        ),
        "settings": json_value,
        "id": json_value,
        "color": st.fixed_dictionaries({c: st.floats(-2, 2) for c in ("red", "green", "blue", "alpha")}),
        "context": json_value,
    },
)
message = st.fixed_dictionaries(
    {"jsonrpc": st.sampled_from(["2.0", "2.0", "2.0", "1.0", 2])},
    optional={
        "method": st.sampled_from(METHODS) | json_value,
        "id": st.integers(1000, 10**6) | st.text(max_size=4) | json_value,
        "params": shaped_params | json_value,
        "result": json_value,
    },
)
request = st.fixed_dictionaries(
    {
        "jsonrpc": st.just("2.0"),
        "id": st.integers(1000, 10**6),
        "method": st.sampled_from(METHODS),
        "params": shaped_params,
    }
)
notification = st.fixed_dictionaries(
    {"jsonrpc": st.just("2.0"), "method": st.sampled_from(METHODS), "params": shaped_params}
)
body = st.one_of(
    request.map(lambda m: json.dumps(m).encode()),
    request.map(lambda m: json.dumps(m).encode()),
    request.map(lambda m: json.dumps(m).encode()),
    notification.map(lambda m: json.dumps(m).encode()),
    notification.map(lambda m: json.dumps(m).encode()),
    message.map(lambda m: json.dumps(m).encode()),
    st.binary(max_size=80),
)
length = st.one_of(
    st.none(),  # the body's own length (most frames)
    st.none(),
    st.none(),
    st.none(),
    st.integers(0, SLACK).map(str),
    st.sampled_from([str(MAX_FRAME_BYTES + 1), "99999999999", "1" + "0" * 30, "-1", "x", "", " 12", "0x10"]),
)
header_line = st.sampled_from(
    [b"Content-Type: application/vscode-jsonrpc; charset=utf-8", b"X-Junk: \xff", b"no colon here", b": empty name"]
)


@st.composite
def frames(draw) -> bytes:
    content = draw(body)
    declared = draw(length)
    declared = str(len(content)) if declared is None else declared
    extra = draw(st.lists(header_line, max_size=2)) if draw(st.integers(0, 3)) == 0 else []
    end = draw(st.sampled_from([b"\r\n", b"\r\n", b"\n"]))
    lines = [b"Content-Length: " + declared.encode(), *extra]
    if draw(st.booleans()):
        lines.reverse()
    if draw(st.integers(0, 9)) == 0:
        lines = lines[1:]  # no Content-Length at all
    return end.join(lines) + end + end + content


@pytest.fixture(scope="module")
def server():
    with RawServer() as raw:
        raw.initialize(debounceMs=0)
        raw.open(URI, "blue plastic\nblu steel")
        raw.diagnostics(URI, 1)
        yield raw


@settings(max_examples=60, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(chunks=st.lists(frames() | st.binary(min_size=1, max_size=40), min_size=1, max_size=4))
def test_random_frames_never_stop_the_server(server, chunks):
    for chunk in chunks:
        server.send_bytes(chunk)
    server.send_bytes(b"\r\n" * SLACK)
    probe = server.request("cnlmc/probe", {})
    assert server.response(probe, timeout=60)["error"]["code"] == -32601


def test_after_the_fuzz_the_server_answers_and_logged_no_traceback(server):
    server.open(URI + "?after", "blue plastic")
    server.diagnostics(URI + "?after", 1)
    hover = server.call(
        "textDocument/hover", {"textDocument": {"uri": URI + "?after"}, "position": {"line": 0, "character": 8}}
    )
    assert "plastic" in hover["result"]["contents"]["value"]
    assert server.proc.poll() is None
    log = server.stderr()
    assert "Traceback" not in log and "internal error" not in log
