"""`cnlmc lsp`: the language server over stdio, a thin adapter over the compiler.

Every answer comes from the compiler: diagnostics from `compile_source` (block by block,
see lsp/incremental.py), completion from the LALR parser's `accepts()` and the lexicon,
hover from the lexicon and `explain`. Never print to stdout here: it is the LSP channel.
"""

from __future__ import annotations

import asyncio
import gc
import logging
import os
import time
from concurrent.futures import ThreadPoolExecutor
from typing import Any

from lsprotocol import types
from pygls.lsp.server import LanguageServer

from .api import lexicon_for
from .lexicon_schema import LexiconError
from .lsp import actions, colours, completion, hover, inlay, tokens
from .lsp.diagnostics import LspDiagnostics
from .lsp.incremental import Analyzer, Cancelled, Snapshot

DEFAULT_DEBOUNCE_MS = 120
log = logging.getLogger("cnlmc.lsp")
TRACE = os.environ.get("CNLMC_LSP_TRACE")  # a file to append per-publish timings to


class CnlServer(LanguageServer):
    """Holds the analyzer, the settings, and per-document debounce state."""

    def __init__(self) -> None:
        super().__init__("cnlmc", "0.1.0")
        self.analyzer = Analyzer(lexicon_for())
        self.worker = ThreadPoolExecutor(max_workers=1, thread_name_prefix="cnlmc-analysis")
        self.debounce_ms = DEFAULT_DEBOUNCE_MS
        self.inlay_hints = True
        self.generation: dict[str, int] = {}
        self.pending: dict[str, asyncio.Task[None]] = {}
        self.snapshots: dict[str, Snapshot] = {}
        self.lsp_diagnostics = LspDiagnostics()
        self.lexicon_error: str | None = None

    @property
    def encoding(self) -> str:
        kind = self.workspace.position_encoding
        return str(getattr(kind, "value", kind) or "utf-16")

    def apply_settings(self, settings: Any) -> None:
        if not isinstance(settings, dict):
            return
        settings = settings.get("cnlmc", settings)
        if isinstance(settings.get("debounceMs"), (int, float)):
            self.debounce_ms = max(0, settings["debounceMs"])
        if isinstance(settings.get("inlayHints"), bool):
            self.inlay_hints = settings["inlayHints"]
        if isinstance(settings.get("lexicon"), list):
            self.use_lexicon(tuple(str(s) for s in settings["lexicon"]))

    def use_lexicon(self, specs: tuple[str, ...]) -> None:
        """Overlay names ('de', 'paper') or lexicon folders, as `--lexicon` takes them."""
        try:
            lexicon = lexicon_for(specs)
        except LexiconError as exc:
            log.warning("cnlmc.lexicon setting ignored: %s", exc)
            self.lexicon_error = str(exc)
            return
        self.lexicon_error = None
        if lexicon is not self.analyzer.lexicon:
            self.analyzer = Analyzer(lexicon)
            self.snapshots.clear()

    def text_of(self, uri: str) -> str | None:
        if uri not in self.generation:
            return None
        return self.workspace.get_text_document(uri).source

    async def snapshot(self, uri: str) -> Snapshot | None:
        """The analysis of the document's current text (cached; computed on the worker thread)."""
        text = self.text_of(uri)
        if text is None:
            return None
        known = self.snapshots.get(uri)
        if known is not None and known.text == text and known.index.encoding == self.encoding:
            return known
        loop = asyncio.get_running_loop()
        snap = await loop.run_in_executor(self.worker, self.analyzer.analyse, text, self.encoding)
        self.snapshots[uri] = snap
        return snap

    def schedule(self, uri: str) -> None:
        """Debounce: a newer edit cancels the waiting run and makes a running one stop early."""
        self.generation[uri] = self.generation.get(uri, 0) + 1
        waiting = self.pending.pop(uri, None)
        if waiting is not None:
            waiting.cancel()
        self.pending[uri] = asyncio.ensure_future(self.publish_later(uri, self.generation[uri]))

    def publish(self, uri: str, version: int | None, diagnostics: list[dict[str, Any]]) -> None:
        """Send publishDiagnostics with diagnostics already in JSON form (lsp/diagnostics.py caches
        them per block): lsprotocol's converter would otherwise spend ~10 ms per 300 diagnostics."""
        params: dict[str, Any] = {"uri": uri, "diagnostics": diagnostics}
        if version is not None:
            params["version"] = version
        send = getattr(self.protocol, "_send_data", None)
        if send is None:  # pragma: no cover - a pygls without it: the typed, slower path
            params["diagnostics"] = [self.protocol._converter.structure(d, types.Diagnostic) for d in diagnostics]
            self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(**params))
            return
        send({"jsonrpc": "2.0", "method": types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS, "params": params})

    async def publish_later(self, uri: str, generation: int) -> None:
        if self.debounce_ms:
            await asyncio.sleep(self.debounce_ms / 1000)
        text = self.text_of(uri)
        if text is None:
            return
        version = self.workspace.get_text_document(uri).version
        t0 = time.perf_counter()

        def current() -> bool:
            return self.generation.get(uri) == generation

        loop = asyncio.get_running_loop()
        try:
            snap = await loop.run_in_executor(self.worker, self.analyzer.analyse, text, self.encoding, current)
        except Cancelled:
            return
        except Exception:  # a compiler bug must not take the editor's server down
            log.exception("analysis failed for %s", uri)
            return
        if not current():
            return
        self.snapshots[uri] = snap
        t1 = time.perf_counter()
        diagnostics = self.lsp_diagnostics.of(snap, uri)
        t2 = time.perf_counter()
        self.publish(uri, version, diagnostics)
        t3 = time.perf_counter()
        gc.freeze()  # see keep_collections_small()
        if TRACE:
            with open(TRACE, "a", encoding="utf-8") as trace:
                trace.write(
                    f"{uri} v{version} analyse {(t1 - t0) * 1000:.1f} convert {(t2 - t1) * 1000:.1f} "
                    f"send {(t3 - t2) * 1000:.1f} ms\n"
                )


def keep_collections_small() -> None:
    """Full garbage collections over the cached blocks cost 50-100 ms in the middle of typing
    (bench/lsp_bench.py). The caches are bounded and hold no cycles worth collecting, so what
    survives a publish is frozen out of the collector's reach (gc.freeze after each publish)."""
    gc.collect()
    gc.freeze()


server = CnlServer()


@server.feature(types.INITIALIZE)
def on_initialize(ls: CnlServer, params: types.InitializeParams) -> None:
    ls.apply_settings(params.initialization_options or {})


@server.feature(types.WORKSPACE_DID_CHANGE_CONFIGURATION)
def on_configuration(ls: CnlServer, params: types.DidChangeConfigurationParams) -> None:
    ls.apply_settings(params.settings or {})
    for uri in list(ls.generation):
        ls.schedule(uri)  # the words may have changed: re-check every open document


@server.feature(types.TEXT_DOCUMENT_DID_OPEN)
def did_open(ls: CnlServer, params: types.DidOpenTextDocumentParams) -> None:
    ls.schedule(params.text_document.uri)


@server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
def did_change(ls: CnlServer, params: types.DidChangeTextDocumentParams) -> None:
    ls.schedule(params.text_document.uri)


@server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
def did_close(ls: CnlServer, params: types.DidCloseTextDocumentParams) -> None:
    uri = params.text_document.uri
    waiting = ls.pending.pop(uri, None)
    if waiting is not None:
        waiting.cancel()
    ls.generation.pop(uri, None)
    ls.snapshots.pop(uri, None)
    ls.publish(uri, None, [])


@server.feature(types.TEXT_DOCUMENT_HOVER)
async def on_hover(ls: CnlServer, params: types.HoverParams) -> types.Hover | None:
    snap = await ls.snapshot(params.text_document.uri)
    return hover.hover(snap, params.position, ls.analyzer.lexicon) if snap else None


@server.feature(
    types.TEXT_DOCUMENT_COMPLETION, types.CompletionOptions(trigger_characters=[" ", ","], resolve_provider=False)
)
async def on_completion(ls: CnlServer, params: types.CompletionParams) -> types.CompletionList | None:
    snap = await ls.snapshot(params.text_document.uri)
    if snap is None:
        return None
    return completion.complete(snap, params.position, ls.analyzer.lexicon)


@server.feature(
    types.TEXT_DOCUMENT_CODE_ACTION, types.CodeActionOptions(code_action_kinds=[types.CodeActionKind.QuickFix])
)
async def on_code_action(ls: CnlServer, params: types.CodeActionParams) -> list[types.CodeAction] | None:
    snap = await ls.snapshot(params.text_document.uri)
    if snap is None:
        return None
    return actions.quick_fixes(snap, params.text_document.uri, params.range, ls.analyzer.lexicon)


@server.feature(types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL, tokens.LEGEND)
async def on_semantic_tokens(ls: CnlServer, params: types.SemanticTokensParams) -> types.SemanticTokens:
    snap = await ls.snapshot(params.text_document.uri)
    if snap is None:
        return types.SemanticTokens(data=[])
    return tokens.semantic_tokens(snap, ls.analyzer.lexicon)


@server.feature(types.TEXT_DOCUMENT_DOCUMENT_COLOR)
async def on_document_colour(ls: CnlServer, params: types.DocumentColorParams) -> list[types.ColorInformation]:
    snap = await ls.snapshot(params.text_document.uri)
    return colours.document_colours(snap, ls.analyzer.lexicon) if snap else []


@server.feature(types.TEXT_DOCUMENT_COLOR_PRESENTATION)
async def on_colour_presentation(ls: CnlServer, params: types.ColorPresentationParams) -> list[types.ColorPresentation]:
    snap = await ls.snapshot(params.text_document.uri)
    replaces = colours.is_colour_range(snap, params.range) if snap else True
    return colours.presentations(params.color, params.range, ls.analyzer.lexicon, replaces)


@server.feature(types.TEXT_DOCUMENT_INLAY_HINT)
async def on_inlay_hints(ls: CnlServer, params: types.InlayHintParams) -> list[types.InlayHint]:
    if not ls.inlay_hints:
        return []
    snap = await ls.snapshot(params.text_document.uri)
    return inlay.inlay_hints(snap, params.range) if snap else []


def main() -> None:
    logging.basicConfig(level=logging.WARNING, format="cnlmc-lsp %(levelname)s %(message)s")  # stderr
    keep_collections_small()
    server.start_io()


if __name__ == "__main__":
    main()
