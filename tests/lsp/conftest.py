"""pytest-lsp fixtures: the real server over stdio, and a client that records every
publishDiagnostics with its document version."""

from __future__ import annotations

import asyncio
import itertools
import json
import sys
import time
from pathlib import Path

import pytest_lsp
from lsprotocol import types
from pygls.protocol import default_converter
from pytest_lsp import ClientServerConfig, LanguageClient
from pytest_lsp.client import DEFAULT_CLIENT_FEATURES, register_lsp_features

FIXTURES = Path(__file__).parent / "fixtures"
SERVER_COMMAND = [sys.executable, "-m", "cnlmc", "lsp"]


def _record_publish(client: LanguageClient, params: types.PublishDiagnosticsParams):
    client.diagnostics[params.uri] = params.diagnostics
    client.published.append(params)


def make_recording_client() -> LanguageClient:
    client = LanguageClient(converter_factory=default_converter)
    client.published = []
    register_lsp_features(client, {**DEFAULT_CLIENT_FEATURES, types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS: _record_publish})
    return client


CONFIG = ClientServerConfig(server_command=SERVER_COMMAND, client_factory=make_recording_client)


def initialize_params(**options) -> types.InitializeParams:
    capabilities = types.ClientCapabilities(
        general=types.GeneralClientCapabilities(position_encodings=[types.PositionEncodingKind.Utf16]),
        text_document=types.TextDocumentClientCapabilities(
            completion=types.CompletionClientCapabilities(
                completion_item=types.ClientCompletionItemOptions(
                    snippet_support=False, documentation_format=[types.MarkupKind.Markdown]
                )
            ),
            hover=types.HoverClientCapabilities(content_format=[types.MarkupKind.Markdown]),
            publish_diagnostics=types.PublishDiagnosticsClientCapabilities(
                related_information=True, version_support=True
            ),
        ),
    )
    return types.InitializeParams(
        capabilities=capabilities, initialization_options={"debounceMs": 20, "inlayHints": True, **options}
    )


@pytest_lsp.fixture(config=CONFIG, scope="module")
async def client(lsp_client: LanguageClient):
    """One server per test module (starting one takes ~1 s); every test uses its own URIs."""
    await lsp_client.initialize_session(initialize_params())
    yield
    await lsp_client.shutdown_session()


async def wait_diagnostics(client: LanguageClient, uri: str, version: int, timeout: float = 20.0):
    """The diagnostics the server published for `uri` at document `version`."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        for params in reversed(client.published):
            if params.uri == uri and params.version == version:
                return params.diagnostics
        await asyncio.sleep(0.005)
    raise TimeoutError(f"no diagnostics for {uri} version {version}")


_fresh = itertools.count()


def fresh_uri(stem: str) -> str:
    """A URI no other test in the module has opened."""
    return f"file:///tmp/cnlmc-tests/{stem}-{next(_fresh)}.cnl"


def send_raw(client: LanguageClient, body: bytes) -> None:
    """Write one JSON-RPC frame with any body, bypassing the client's type checks."""
    client._server.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)


def raw_request(client: LanguageClient, method: str, params, msg_id: int = 900001) -> None:
    send_raw(client, json.dumps({"jsonrpc": "2.0", "id": msg_id, "method": method, "params": params}).encode())


def open_document(client: LanguageClient, uri: str, text: str, version: int = 1) -> None:
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(types.TextDocumentItem(uri=uri, language_id="cnl", version=version, text=text))
    )


async def open_fixture(client: LanguageClient, name: str):
    """Open tests/lsp/fixtures/NAME and return (uri, text, diagnostics)."""
    path = FIXTURES / name
    uri = path.as_uri() + f"?{next(_fresh)}"
    text = path.read_text("utf-8")
    open_document(client, uri, text)
    return uri, text, await wait_diagnostics(client, uri, 1)


def replace_all(client: LanguageClient, uri: str, text: str, version: int) -> None:
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(uri=uri, version=version),
            [types.TextDocumentContentChangeWholeDocument(text=text)],
        )
    )


def position_of(text: str, needle: str, line_hint: int | None = None, offset: int = 0) -> types.Position:
    """The UTF-16 LSP position of `needle` (first occurrence, or on line `line_hint`)."""
    for number, line in enumerate(text.split("\n")):
        if line_hint is not None and number != line_hint:
            continue
        col = line.find(needle)
        if col >= 0:
            col += offset
            return types.Position(number, len(line[:col].encode("utf-16-le")) // 2)
    raise ValueError(needle)
