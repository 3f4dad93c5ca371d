"""JSON-RPC and LSP life-cycle rules on top of pygls, for messages a client may get wrong.

Every request gets a response (JSON-RPC 2.0, LSP 3.17):

- a body that is not JSON, or a message that is not a JSON-RPC 2.0 object, is dropped with a log
  line; if it still carries a usable request id it is answered with InvalidRequest (-32600);
- a request before `initialize`: ServerNotInitialized (-32002); after `shutdown`: InvalidRequest;
- an unknown method: MethodNotFound (-32601); params of the wrong shape: InvalidParams (-32602),
  with what is wrong and where (`required field missing @ $.params.position`);
- `exit` ends the server with status 0 after `shutdown` and 1 without it.

Notifications before `initialize` or after `shutdown` are dropped (exit excepted). The open
documents' text is kept by lsp/documents.py (the spec's line ends), not by pygls' workspace.
"""

from __future__ import annotations

import json
import logging
from collections.abc import Callable, Generator
from typing import TYPE_CHECKING, Any

import attrs
import cattrs
from lsprotocol import types
from pygls.protocol import LanguageServerProtocol
from pygls.protocol.json_rpc import JsonRPCNotification, JsonRPCRequestMessage, JsonRPCResponseMessage
from pygls.protocol.language_server import lsp_method

if TYPE_CHECKING:
    from cattrs import Converter

    from .documents import DocumentStore

log = logging.getLogger("cnlmc.lsp")

PARSE_ERROR = -32700
INVALID_REQUEST = -32600
METHOD_NOT_FOUND = -32601
INVALID_PARAMS = -32602
SERVER_NOT_INITIALIZED = -32002
REQUEST_CANCELLED = -32800
CONTENT_MODIFIED = -32801

Handler = Generator[Any, Any, None]


class BadParams(Exception):
    """A message whose params do not have the shape its method needs."""


class CnlProtocol(LanguageServerProtocol):
    """pygls' LSP protocol with the checks above; `accept` takes one frame body."""

    def __init__(self, server: Any, converter: Converter) -> None:
        super().__init__(server, converter)
        self.initialized = False
        self.exit_code: int | None = None
        self.on_exit: Callable[[], None] = lambda: None

    def documents(self) -> DocumentStore:
        store: DocumentStore = getattr(self._server, "documents")  # noqa: B009 - the server's, made after us
        return store

    # ------------------------------------------------------------------ one message

    def accept(self, body: bytes) -> None:
        """Decode, check and dispatch one frame body; nothing a client sends raises here."""
        data = _decode(body)
        if data is None:
            return
        problem = envelope_problem(data)
        if problem is not None:
            log.warning("dropped a message: %s", problem)
            msg_id = _usable_id(data) if isinstance(data, dict) else None
            if msg_id is not None and "method" in data:
                self.reply_error(msg_id, INVALID_REQUEST, problem)
            return
        method = data.get("method")
        if method is None:
            self._accept_response(data)
        elif "id" in data:
            self._accept_request(data["id"], method, data)
        else:
            self._accept_notification(method, data)

    def reply_error(self, msg_id: int | str, code: int, message: str) -> None:
        self._send_data({"jsonrpc": "2.0", "id": msg_id, "error": {"code": code, "message": message}})

    def _accept_request(self, msg_id: int | str, method: str, data: dict[str, Any]) -> None:
        if not self.initialized and method != types.INITIALIZE:
            self.reply_error(msg_id, SERVER_NOT_INITIALIZED, f"'{method}' before 'initialize': initialize first")
            return
        if self._shutdown:
            self.reply_error(msg_id, INVALID_REQUEST, f"'{method}' after 'shutdown': the server takes no more requests")
            return
        if not self._knows(method):
            self.reply_error(msg_id, METHOD_NOT_FOUND, f"cnlmc's language server has no method '{method}'")
            return
        kind = self.get_message_type(method) or JsonRPCRequestMessage
        if "id" not in attrs.fields_dict(kind):
            self.reply_error(msg_id, INVALID_REQUEST, f"'{method}' is a notification: it is sent without an 'id'")
            return
        try:
            message = self._structure(data, kind)
        except BadParams as exc:
            log.warning("answered '%s' (id %s) with InvalidParams: %s", method, msg_id, exc)
            self.reply_error(msg_id, INVALID_PARAMS, f"invalid params for '{method}': {exc}")
            return
        self.handle_message(message)
        if method == types.INITIALIZE:
            self.initialized = True

    def _accept_notification(self, method: str, data: dict[str, Any]) -> None:
        if method == types.EXIT:
            self.exit_code = 0 if self._shutdown else 1
            self.on_exit()
            return
        if not self.initialized or self._shutdown:
            log.info("ignored '%s': the server is %s", method, "shutting down" if self._shutdown else "not initialized")
            return
        if not self._knows(method):
            if not method.startswith("$/"):
                log.info("ignored a notification for an unknown method '%s'", method)
            return
        try:
            message = self._structure(data, self.get_message_type(method) or JsonRPCNotification)
        except BadParams as exc:
            log.warning("ignored '%s': %s", method, exc)
            return
        self.handle_message(message)
        self._forget_finished_notifications()

    def _forget_finished_notifications(self) -> None:
        """pygls files the future of every notification it runs with the in-flight requests and
        never takes it out (one per keystroke, for ever); requests are taken out when answered."""
        finished = [key for key, future in self._request_futures.items() if future.done()]
        for key in finished:
            del self._request_futures[key]

    def _accept_response(self, data: dict[str, Any]) -> None:
        kind = types.ResponseErrorMessage if "error" in data else self._result_types.pop(data["id"], None)
        try:
            message = self._structure(data, kind or JsonRPCResponseMessage)
        except BadParams as exc:
            log.warning("ignored a response from the client: %s", exc)
            return
        self.handle_message(message)

    def _knows(self, method: str) -> bool:
        return method in self.fm.builtin_features or method in self.fm.features or method == types.CANCEL_REQUEST

    def _structure(self, data: dict[str, Any], kind: Any) -> Any:
        if kind in (JsonRPCRequestMessage, JsonRPCNotification):
            data = {"params": None, **data}
        try:
            return self._converter.structure(data, kind)
        except Exception as exc:  # cattrs reports a bad shape in several ways; each is the client's mistake
            raise BadParams(_explain(exc)) from None

    # ------------------------------------------------------------------ document sync (lsp/documents.py)

    @lsp_method(types.TEXT_DOCUMENT_DID_OPEN)
    def lsp_text_document__did_open(self, params: types.DidOpenTextDocumentParams) -> Handler:
        item = params.text_document
        self.documents().open(item.uri, item.text, item.version)
        yield from self._user_handler(types.TEXT_DOCUMENT_DID_OPEN, params)

    @lsp_method(types.TEXT_DOCUMENT_DID_CHANGE)
    def lsp_text_document__did_change(self, params: types.DidChangeTextDocumentParams) -> Handler:
        document = params.text_document
        if self.documents().change(document.uri, document.version, params.content_changes, self.encoding()) is None:
            log.info("ignored a change to a document that is not open: %s", document.uri)
            return
        yield from self._user_handler(types.TEXT_DOCUMENT_DID_CHANGE, params)

    @lsp_method(types.TEXT_DOCUMENT_DID_CLOSE)
    def lsp_text_document__did_close(self, params: types.DidCloseTextDocumentParams) -> Handler:
        if self.documents().close(params.text_document.uri) is None:
            return
        yield from self._user_handler(types.TEXT_DOCUMENT_DID_CLOSE, params)

    def encoding(self) -> str:
        """The position encoding agreed at initialize ('utf-16' until then)."""
        if self._workspace is None:
            return "utf-16"
        kind = self.workspace.position_encoding
        return str(getattr(kind, "value", kind) or "utf-16")

    def _user_handler(self, method: str, params: Any) -> Handler:
        handler = self.fm.features.get(method)
        if handler is not None:
            yield handler, (params,), None


def _decode(body: bytes) -> Any:
    try:
        return json.loads(body)
    except (ValueError, RecursionError) as exc:  # not UTF-8, not JSON, nested too deep, a 5000-digit number
        log.warning("dropped a frame that is not JSON: %s", _one_line(str(exc) or type(exc).__name__))
        return None


def envelope_problem(data: Any) -> str | None:
    """What makes `data` not a JSON-RPC 2.0 request, notification or response (None: nothing)."""
    if not isinstance(data, dict):
        return f"a message must be a JSON object, not {type(data).__name__} (batches are not part of LSP)"
    if data.get("jsonrpc") != "2.0":
        return "'jsonrpc' must be \"2.0\""
    if "method" in data and not isinstance(data["method"], str):
        return f"'method' must be a string, not {_json_type(data['method'])}"
    if "id" in data and _usable_id(data) is None:
        return f"'id' must be an integer or a string, not {_json_type(data['id'])}"
    if "method" not in data and "id" not in data:
        return "a message needs a 'method' (request, notification) or an 'id' (response)"
    if data.get("params") is not None and not isinstance(data["params"], (dict, list)):
        return f"'params' must be an object or an array, not {_json_type(data['params'])}"
    return None


def _usable_id(data: dict[str, Any]) -> int | str | None:
    msg_id = data.get("id")
    if isinstance(msg_id, bool) or not isinstance(msg_id, (int, str)):
        return None
    if isinstance(msg_id, int) and not -(2**53) <= msg_id <= 2**53:
        return None
    return msg_id


def _json_type(value: Any) -> str:
    names = {dict: "an object", list: "an array", str: "a string", bool: "a boolean", float: "a number"}
    if value is None:
        return "null"
    if isinstance(value, int) and not isinstance(value, bool):
        return "a number" if -(2**53) <= value <= 2**53 else "an integer too large for JSON-RPC"
    return names.get(type(value), type(value).__name__)


def _explain(exc: Exception) -> str:
    if isinstance(exc, cattrs.BaseValidationError):
        found = cattrs.transform_error(exc)
        return "; ".join(_one_line(line) for line in found[:3]) + ("; ..." if len(found) > 3 else "")
    return _one_line(f"{type(exc).__name__}: {exc}")


def _one_line(text: str, limit: int = 300) -> str:
    flat = " ".join(text.split())
    return flat if len(flat) <= limit else flat[: limit - 3] + "..."
