"""The JSON-RPC and LSP life cycle (#13): every request gets a response, `exit` without
`shutdown` exits 1, a bad message is a clean error (never a traceback), settings and lexicon
problems reach the user (window/showMessage), a lone surrogate does not stop diagnostics."""

from __future__ import annotations

import pytest

from cnlmc.lsp.settings import MAX_DEBOUNCE_MS

from .rawclient import RawServer

pytestmark = pytest.mark.lsp

URI = "file:///tmp/cnlmc-tests/protocol.cnl"


@pytest.fixture(scope="module")
def server():
    with RawServer() as raw:
        raw.initialize()
        raw.open(URI, "blue plastic")
        raw.diagnostics(URI, 1)
        yield raw


def error_of(raw: RawServer, method, params=None, msg_id=None) -> dict:
    answer = raw.response(raw.request(method, params, msg_id))
    assert "result" not in answer, answer
    return answer["error"]


def test_invalid_params_are_answered_with_what_is_wrong(server):
    missing = error_of(server, "textDocument/hover", {"textDocument": {"uri": URI}})
    assert missing["code"] == -32602
    assert "required field missing @ $.params.position" in missing["message"]
    wrong = error_of(
        server, "textDocument/hover", {"textDocument": {"uri": URI}, "position": {"line": 0, "character": "x"}}
    )
    assert wrong["code"] == -32602 and "expected int @ $.params.position.character" in wrong["message"]
    assert error_of(server, "textDocument/completion", None)["code"] == -32602
    assert error_of(server, "textDocument/hover", "a string")["code"] == -32600  # params must be an object or array


def test_a_notification_sent_as_a_request_is_answered(server):
    error = error_of(server, "textDocument/didClose", {"textDocument": {"uri": "file:///never-opened.cnl"}})
    assert error == {"code": -32600, "message": "'textDocument/didClose' is a notification: it is sent without an 'id'"}


def test_unknown_method(server):
    error = error_of(server, "cnlmc/noSuchMethod", {})
    assert error == {"code": -32601, "message": "cnlmc's language server has no method 'cnlmc/noSuchMethod'"}


def test_a_method_that_is_not_a_string_is_a_clean_error(server):
    server.send({"jsonrpc": "2.0", "id": 77, "method": 5, "params": {}})
    server.send({"jsonrpc": "2.0", "id": 78, "method": ["textDocument/hover"]})
    first, second = server.response(77), server.response(78)
    assert first["error"] == {"code": -32600, "message": "'method' must be a string, not a number"}
    assert second["error"] == {"code": -32600, "message": "'method' must be a string, not an array"}
    for answer in (first, second):
        assert "data" not in answer["error"] and "Traceback" not in str(answer)


def test_messages_that_are_not_json_rpc_are_dropped(server):
    server.send([{"jsonrpc": "2.0", "id": 1, "method": "shutdown"}])  # a batch: not LSP
    server.send({"jsonrpc": "1.0", "id": 90, "method": "shutdown"})
    server.send({"jsonrpc": "2.0", "id": {"a": 1}, "method": "shutdown"})
    server.send({"jsonrpc": "2.0", "id": True, "method": "shutdown"})
    server.send({"jsonrpc": "2.0"})
    server.send({"jsonrpc": "2.0", "method": "$/cancelRequest", "params": {"id": None}})
    server.send({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": 3}})
    assert error_of(server, "cnlmc/stillThere")["code"] == -32601  # and not shut down by any of them
    assert server.response(90)["error"]["code"] == -32600
    assert "Traceback" not in server.stderr()


def test_a_lone_surrogate_with_utf8_positions_keeps_diagnostics_coming():
    with RawServer() as raw:
        raw.initialize("utf-8", debounceMs=0)
        uri = "file:///tmp/cnlmc-tests/surrogate.cnl"
        raw.open(uri, "blu plastic # \ud800 broken\nbleu steel")
        diags = raw.diagnostics(uri, 1)
        assert [d["range"]["start"] for d in diags if "'bleu'" in d["message"]] == [{"line": 1, "character": 0}]
        raw.change(uri, 2, {"range": _range(0, 0, 0, 0), "text": "\udfff"})
        assert any("'bleu'" in d["message"] for d in raw.diagnostics(uri, 2))
        hover = raw.call("textDocument/hover", {"textDocument": {"uri": uri}, "position": {"line": 1, "character": 6}})
        assert "steel" in hover["result"]["contents"]["value"]
        assert raw.shutdown_and_exit() == 0


def _range(l0, c0, l1, c1):
    return {"start": {"line": l0, "character": c0}, "end": {"line": l1, "character": c1}}


def test_requests_before_initialize_and_after_shutdown_are_answered():
    with RawServer() as raw:
        early = raw.response(
            raw.request("textDocument/hover", {"textDocument": {"uri": URI}, "position": _range(0, 0, 0, 0)["start"]})
        )
        assert early["error"]["code"] == -32002
        raw.initialize()
        assert raw.call("shutdown")["result"] is None
        late = raw.response(
            raw.request("textDocument/hover", {"textDocument": {"uri": URI}, "position": {"line": 0, "character": 0}})
        )
        assert late["error"]["code"] == -32600 and "after 'shutdown'" in late["error"]["message"]
        assert raw.call("shutdown")["error"]["code"] == -32600
        raw.notify("exit")
        assert raw.wait() == 0


def test_exit_without_shutdown_exits_1():
    with RawServer() as raw:
        raw.initialize()
        raw.notify("exit")
        assert raw.wait() == 1


def test_settings_problems_are_shown_to_the_user():
    with RawServer() as raw:
        raw.initialize(debounceMs=10**12, inlayHints="yes", lexicon=["klingon"], debounse=3)
        raw.call("cnlmc/sync")  # every notification sent during initialize has arrived
        shown = raw.shown_messages()
        assert any(f"cnlmc.debounceMs is 1000000000000: it must be 0 to {MAX_DEBOUNCE_MS} ms" in m for m in shown)
        assert any("cnlmc.inlayHints must be true or false" in m for m in shown)
        assert any("cnlmc.lexicon setting ignored" in m and "klingon" in m for m in shown)
        assert any("unknown setting cnlmc.debounse (did you mean 'debounceMs'?)" in m for m in shown)
        uri = "file:///tmp/cnlmc-tests/debounce.cnl"
        raw.open(uri, "blu plastic")
        assert raw.diagnostics(uri, 1, timeout=MAX_DEBOUNCE_MS / 1000 + 20)  # a huge debounce is not "never"
        raw.notify("workspace/didChangeConfiguration", {"settings": {"cnlmc": {"lexicon": ["/no/such/folder"]}}})
        raw.call("cnlmc/sync")
        assert any("/no/such/folder" in m for m in raw.shown_messages())
        assert raw.shutdown_and_exit() == 0
