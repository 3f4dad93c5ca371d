"""Frames a client gets wrong (#13): a huge or absurd Content-Length, a missing or non-numeric
one, LF-only headers, garbage between frames. The server logs a line, drops the frame, and
answers the next good one; it never dies and never waits forever."""

from __future__ import annotations

import io
import json

import pytest

from cnlmc.lsp.transport import MAX_FRAME_BYTES, MAX_HEADER_LINE_BYTES, FrameReader

from .rawclient import RawServer

pytestmark = pytest.mark.lsp

HOVER_URI = "file:///tmp/cnlmc-tests/transport.cnl"


@pytest.fixture(scope="module")
def server():
    with RawServer() as raw:
        raw.initialize()
        raw.open(HOVER_URI, "blue plastic")
        raw.diagnostics(HOVER_URI, 1)
        yield raw


def hover_answered(raw: RawServer) -> bool:
    answer = raw.call(
        "textDocument/hover", {"textDocument": {"uri": HOVER_URI}, "position": {"line": 0, "character": 8}}
    )
    return "plastic" in answer["result"]["contents"]["value"]


def frame(body: bytes, length: bytes | None = None) -> bytes:
    return b"Content-Length: " + (length if length is not None else b"%d" % len(body)) + b"\r\n\r\n" + body


PING = json.dumps({"jsonrpc": "2.0", "id": "ping", "method": "cnlmc/ping"}).encode()


def test_content_length_of_a_hundred_gigabytes_is_refused_not_allocated(server):
    server.send_bytes(frame(b"{}", b"99999999999"))
    assert hover_answered(server)
    assert "dropped a frame of 99999999999 bytes: the limit is 67108864 bytes (64 MiB)" in server.stderr()


def test_content_length_of_ten_to_the_thirty(server):
    server.send_bytes(frame(b"{}", b"1" + b"0" * 30))
    assert hover_answered(server)
    assert "dropped a frame of 1000000000000000000000000000000 bytes" in server.stderr()


def test_non_numeric_and_missing_content_length(server):
    server.send_bytes(frame(PING, b"twelve") + b"\r\n")
    server.send_bytes(b"Content-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n" + PING + b"\r\n")
    assert hover_answered(server)
    log = server.stderr()
    assert "dropped a frame whose Content-Length is not a number: twelve" in log
    assert "dropped a frame without a Content-Length header" in log
    assert not any(m.get("id") == "ping" for m in server.received)  # those frames were not read as requests


def test_lf_only_headers_are_read(server):
    body = json.dumps({"jsonrpc": "2.0", "id": "lf", "method": "shutdown-typo"}).encode()
    server.send_bytes(b"Content-Length: %d\n\n" % len(body) + body)
    assert server.response("lf")["error"]["code"] == -32601


def test_garbage_and_long_lines_between_frames(server):
    server.send_bytes(b"\x00\xff garbage \r\n" + b"x" * (3 * MAX_HEADER_LINE_BYTES) + b"\n")
    server.send_bytes(b"junk without a newline")  # the next header is glued to it
    assert hover_answered(server)
    assert "bytes that were not an LSP frame" in server.stderr()


def test_a_body_that_is_not_json_or_not_utf8(server):
    for body in (b"{ not json", b"\xff\xfe\x00", b"[" * 100_000, b'{"id": 1e999999}', b"7" * 5000):
        server.send_bytes(frame(body))
    assert hover_answered(server)
    assert "dropped a frame that is not JSON" in server.stderr()


def test_no_traceback_in_the_log(server):
    assert hover_answered(server)
    assert "Traceback" not in server.stderr()


def test_end_of_stdin_ends_the_server():
    with RawServer() as raw:
        raw.initialize()
        raw.proc.stdin.close()
        assert raw.wait() == 1  # the client went away without shutdown


def test_end_of_stdin_in_the_middle_of_a_frame():
    with RawServer() as raw:
        raw.initialize()
        raw.call("shutdown")
        raw.send_bytes(b"Content-Length: 100\r\n\r\n{")
        raw.proc.stdin.close()
        assert raw.wait() == 0  # shut down properly first
        assert "closed the connection 99 bytes before the end of a frame" in raw.stderr()


# ---------------------------------------------------------------- the reader alone


def read_all(data: bytes) -> tuple[list[bytes], list[str]]:
    warnings: list[str] = []
    reader = FrameReader(io.BufferedReader(io.BytesIO(data)), warn=warnings.append)
    frames = []
    while (body := reader.next_frame()) is not None:
        frames.append(body)
    return frames, warnings


def test_reader_resynchronises_on_the_next_header():
    good = frame(b"{}")
    assert read_all(good + b"noise" + good)[0] == [b"{}", b"{}"]
    assert read_all(frame(b'{"a": 1}', b"x") + good)[0] == [b"{}"]
    assert read_all(frame(b"{}", b"%d" % (MAX_FRAME_BYTES + 1)) + good)[0] == [b"{}"]
    assert read_all(b"Content-Length: " + b"9" * 50_000 + b"\r\n\r\n" + good)[0] == [b"{}"]


def test_reader_limits_the_header_block():
    headers = b"".join(b"X-Header-%d: v\r\n" % i for i in range(100))
    frames, warnings = read_all(headers + b"Content-Length: 2\r\n\r\n{}")
    assert "more than 32 header lines" in warnings[0]
