"""`cnlmc lsp`: the language server over stdio, a thin adapter over the compiler.

Every answer comes from the compiler: diagnostics from `compile_source` (block by block,
see lsp/incremental.py), completion from the LALR parser's `accepts()` and the lexicon,
hover from the lexicon and `explain`. Never print to stdout here: it is the LSP channel.

What keeps it answering (docs/safety.md): frames are read with bounds (lsp/transport.py), every
request is answered and the life cycle follows the spec (lsp/protocol.py), documents keep the
spec's line ends (lsp/documents.py), compiler work runs on one worker thread in time slices that
a cancelled or stale request stops (lsp/work.py), and what is kept for a document is bounded and
dropped when it closes.
"""

from __future__ import annotations

import asyncio
import ctypes
import ctypes.util
import functools
import gc
import logging
import os
import sys
import threading
import time
from collections import OrderedDict
from collections.abc import Awaitable, Callable
from typing import Any, BinaryIO, TypeVar

from lsprotocol import types
from pygls.exceptions import JsonRpcException, JsonRpcInternalError
from pygls.lsp.server import LanguageServer

from .api import lexicon_for
from .errors import UsageError
from .lexicon_schema import LexiconError
from .lsp import actions, colours, completion, hover, inlay, tokens
from .lsp.diagnostics import LspDiagnostics
from .lsp.documents import DocumentStore
from .lsp.incremental import Analyzer, Snapshot
from .lsp.protocol import CONTENT_MODIFIED, CnlProtocol
from .lsp.settings import Settings, read_settings
from .lsp.transport import FrameReader, PipeWriter
from .lsp.work import Worker

#: Documents longer than this are not analysed (one note says so); `cnlmc compile` still reads them.
MAX_ANALYSED_CHARS = 16 * 1024 * 1024
#: Analyses kept for open documents, most recently used first (an evicted one is recomputed).
MAX_SNAPSHOTS = 32
MAX_LOG_LINE = 1000  # characters; a log line never carries a whole document
MAX_RETRIES = 3  # a request whose document keeps changing under it answers ContentModified

log = logging.getLogger("cnlmc.lsp")
TRACE = os.environ.get("CNLMC_LSP_TRACE")  # a file to append per-publish timings to
Result = TypeVar("Result")


class ContentModified(JsonRpcException):
    CODE = CONTENT_MODIFIED
    MESSAGE = "the document changed while the request was answered; ask again"


class CnlServer(LanguageServer):
    """Holds the analyzer, the settings, the open documents and what is computed for them."""

    protocol: CnlProtocol

    def __init__(self) -> None:
        super().__init__("cnlmc", "0.1.0", protocol_cls=CnlProtocol)
        self.analyzer = Analyzer(lexicon_for())
        self.worker = Worker()
        self.documents = DocumentStore()
        self.settings = Settings()
        self.generation: dict[str, int] = {}
        self.pending: dict[str, asyncio.Task[None]] = {}
        self.analyses: dict[str, tuple[str, str, asyncio.Task[Snapshot]]] = {}
        self.snapshots: OrderedDict[str, Snapshot] = OrderedDict()
        self.lsp_diagnostics = LspDiagnostics()
        self.lexicon_error: str | None = None
        self.memory = MemoryRelease()
        self.closing: set[asyncio.Task[None]] = set()

    @property
    def encoding(self) -> str:
        return self.protocol.encoding()

    # ------------------------------------------------------------------ settings

    def apply_settings(self, raw: Any) -> None:
        self.settings, problems = read_settings(raw, self.settings)
        for problem in problems:
            self.tell_user(problem)
        if self.settings.lexicon is not None:
            self.use_lexicon(self.settings.lexicon)

    def use_lexicon(self, specs: tuple[str, ...]) -> None:
        """Overlay names ('de', 'paper') or lexicon folders, as `--lexicon` takes them."""
        try:
            lexicon = lexicon_for(specs)
        except (LexiconError, UsageError, OSError) as exc:
            self.lexicon_error = str(exc)
            self.tell_user(f"cnlmc.lexicon setting ignored (the words stay as they were): {exc}")
            return
        self.lexicon_error = None
        if lexicon is not self.analyzer.lexicon:
            self.analyzer = Analyzer(lexicon)
            self.snapshots.clear()
            self.lsp_diagnostics.clear()

    def tell_user(self, message: str, kind: types.MessageType = types.MessageType.Warning) -> None:
        """A problem the user should see in the editor (window/showMessage), logged as well."""
        log.warning("%s", message)
        self.window_show_message(types.ShowMessageParams(type=kind, message=message))

    # ------------------------------------------------------------------ analysis

    def text_of(self, uri: str) -> str | None:
        document = self.documents.get(uri)
        return None if document is None else document.text

    async def snapshot(self, uri: str) -> Snapshot | None:
        """The analysis of the document's current text: kept, in progress (shared), or started."""
        for _attempt in range(MAX_RETRIES):
            text = self.text_of(uri)
            if text is None or len(text) > MAX_ANALYSED_CHARS:
                return None
            known = self.snapshots.get(uri)
            if known is not None and known.text == text and known.index.encoding == self.encoding:
                self.snapshots.move_to_end(uri)
                return known
            task = self.analysis_task(uri, text)
            try:
                return await asyncio.shield(task)
            except asyncio.CancelledError:
                if not task.cancelled():
                    raise  # this request was cancelled
                # the text changed under the analysis: try again with the new text
        raise ContentModified()

    def analysis_task(self, uri: str, text: str) -> asyncio.Task[Snapshot]:
        running = self.analyses.get(uri)
        if running is not None and running[0] == text and running[1] == self.encoding:
            return running[2]
        if running is not None:
            running[2].cancel()
        task = asyncio.ensure_future(self.analyse(uri, text, self.encoding))
        self.analyses[uri] = (text, self.encoding, task)
        return task

    async def analyse(self, uri: str, text: str, encoding: str) -> Snapshot:
        try:
            snap = await self.worker.drive(self.analyzer.analysis(text, encoding))
        finally:
            running = self.analyses.get(uri)
            if running is not None and running[2] is asyncio.current_task():
                del self.analyses[uri]
        if self.text_of(uri) == text:
            self.snapshots[uri] = snap
            self.snapshots.move_to_end(uri)
            while len(self.snapshots) > MAX_SNAPSHOTS:
                self.snapshots.popitem(last=False)
        return snap

    def schedule(self, uri: str) -> None:
        """Debounce: a newer edit cancels the waiting publish and stops the running analysis."""
        self.generation[uri] = self.generation.get(uri, 0) + 1
        waiting = self.pending.pop(uri, None)
        if waiting is not None:
            waiting.cancel()
        running = self.analyses.pop(uri, None)
        if running is not None and running[0] != self.text_of(uri):
            running[2].cancel()
        self.pending[uri] = asyncio.ensure_future(self.publish_later(uri, self.generation[uri]))

    async def publish_later(self, uri: str, generation: int) -> None:
        if self.settings.debounce_ms:
            await asyncio.sleep(self.settings.debounce_ms / 1000)
        document = self.documents.get(uri)
        if document is None:
            return
        version, t0 = document.version, time.perf_counter()
        if len(document.text) > MAX_ANALYSED_CHARS:
            self.publish(uri, version, [too_large(len(document.text))])
            return
        try:
            snap = await self.snapshot(uri)
            if snap is None or self.generation.get(uri) != generation:
                return
            t1 = time.perf_counter()
            diagnostics = await self.worker.drive(self.lsp_diagnostics.steps(snap, uri))
        except (asyncio.CancelledError, ContentModified):
            return
        except Exception as exc:  # a compiler bug must not take the editor's server down
            log.error("analysis failed for %s: %s: %s", uri, type(exc).__name__, exc)
            return
        if self.generation.get(uri) != generation:
            return
        t2 = time.perf_counter()
        self.publish(uri, version, diagnostics)
        gc.freeze()  # see keep_collections_small()
        if TRACE:
            trace(uri, version, t0, t1, t2, time.perf_counter())

    def publish(self, uri: str, version: int | None, diagnostics: list[dict[str, Any]]) -> None:
        """Send publishDiagnostics with diagnostics already in JSON form (lsp/diagnostics.py caches
        them per block): lsprotocol's converter would otherwise spend ~10 ms per 300 diagnostics."""
        params: dict[str, Any] = {"uri": uri, "diagnostics": diagnostics}
        if version is not None:
            params["version"] = version
        self.protocol._send_data(
            {"jsonrpc": "2.0", "method": types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS, "params": params}
        )

    def start_close(self, uri: str) -> None:
        """Close in the background (a task of our own: pygls keeps the future of an async
        notification handler for ever)."""
        task = asyncio.ensure_future(self.close(uri))
        self.closing.add(task)
        task.add_done_callback(self.closing.discard)

    async def close(self, uri: str) -> None:
        """Forget everything kept for a closed document and give the memory back; the empty
        publishDiagnostics that clears the editor's problems comes last, once that is done."""
        for table in (self.pending, self.analyses):
            running = table.pop(uri, None)
            task = running[2] if isinstance(running, tuple) else running
            if task is not None:
                task.cancel()
        self.generation.pop(uri, None)
        snap = self.snapshots.pop(uri, None)
        self.lsp_diagnostics.forget(uri)
        if snap is not None:
            await self.worker.call(self.analyzer.forget, snap)
        if not self.documents:
            await self.worker.call(self.analyzer.clear)
            self.lsp_diagnostics.clear()
        del snap
        self.memory.release()
        if uri not in self.documents:  # not opened again meanwhile
            self.publish(uri, None, [])

    # ------------------------------------------------------------------ serving

    def serve(self, stdin: BinaryIO, stdout: BinaryIO) -> int:
        """Answer messages on stdin until `exit` or the end of stdin; the process's exit status."""
        return asyncio.run(self._serve(stdin, stdout))

    async def _serve(self, stdin: BinaryIO, stdout: BinaryIO) -> int:
        loop = asyncio.get_running_loop()
        stopped = asyncio.Event()
        self.protocol.set_writer(PipeWriter(stdout, on_lost=stopped.set))
        self.protocol.on_exit = stopped.set
        frames: asyncio.Queue[bytes | None] = asyncio.Queue(maxsize=4)
        reader = threading.Thread(target=pump, args=(FrameReader(stdin), frames, loop), name="cnlmc-stdin", daemon=True)
        reader.start()
        stop = asyncio.ensure_future(stopped.wait())
        while True:
            frame = asyncio.ensure_future(frames.get())
            await asyncio.wait({frame, stop}, return_when=asyncio.FIRST_COMPLETED)
            if not frame.done():
                frame.cancel()
                break
            body = frame.result()
            if body is None:
                log.info("the client closed the connection (end of stdin); exiting")
                break
            self.protocol.accept(body)
        self.worker.close()
        if self.protocol.exit_code is not None:
            return self.protocol.exit_code
        return 0 if self.protocol._shutdown else 1


def pump(reader: FrameReader, frames: asyncio.Queue[bytes | None], loop: asyncio.AbstractEventLoop) -> None:
    """The stdin thread: frames to the event loop, a few at a time (None: the end of stdin)."""
    while True:
        try:
            body = reader.next_frame()
        except (OSError, ValueError) as exc:
            log.warning("cannot read from the client any more (%s)", exc)
            body = None
        try:
            asyncio.run_coroutine_threadsafe(frames.put(body), loop).result()
        except (RuntimeError, asyncio.CancelledError):
            return  # the server has stopped
        if body is None:
            return


def too_large(chars: int) -> dict[str, Any]:
    return {
        "range": {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 0}},
        "severity": int(types.DiagnosticSeverity.Information),
        "source": "cnlmc",
        "message": f"this document has {chars} characters; the language server checks documents of up to "
        f"{MAX_ANALYSED_CHARS} (run `cnlmc compile` on the file instead)",
    }


def trace(uri: str, version: int | None, t0: float, t1: float, t2: float, t3: float) -> None:
    assert TRACE
    with open(TRACE, "a", encoding="utf-8") as out:
        out.write(
            f"{uri} v{version} analyse {(t1 - t0) * 1000:.1f} convert {(t2 - t1) * 1000:.1f} "
            f"send {(t3 - t2) * 1000:.1f} ms\n"
        )


class MemoryRelease:
    """Gives memory back after a document closes: collects what gc.freeze() kept out of reach,
    then asks the C allocator to return free pages to the system (glibc's malloc_trim). On glibc
    the threshold above which blocks get their own mapping is also fixed (glibc raises it after
    each large free, and then large published diagnostics and document texts fragment the heap)."""

    M_MMAP_THRESHOLD = -3  # glibc <malloc.h>
    MMAP_THRESHOLD_BYTES = 256 * 1024

    def __init__(self) -> None:
        self._trim: Callable[[int], int] | None = None
        name = ctypes.util.find_library("c") if sys.platform.startswith("linux") else None
        if name:
            try:
                libc = ctypes.CDLL(name)
                self._trim = libc.malloc_trim
                libc.mallopt(self.M_MMAP_THRESHOLD, self.MMAP_THRESHOLD_BYTES)
            except (OSError, AttributeError):
                self._trim = None

    def release(self) -> None:
        gc.unfreeze()
        gc.collect()
        gc.freeze()
        if self._trim is not None:
            self._trim(0)


def keep_collections_small() -> None:
    """Full garbage collections over the cached blocks cost 50-100 ms in the middle of typing
    (bench/lsp_bench.py). The caches are bounded and hold no cycles worth collecting, so what
    survives a publish is frozen out of the collector's reach (gc.freeze after each publish;
    MemoryRelease unfreezes and collects when a document closes)."""
    gc.collect()
    gc.freeze()


def answered(name: str) -> Callable[[Callable[..., Awaitable[Result]]], Callable[..., Awaitable[Result]]]:
    """A request handler whose failures reach the client as one clean error, never a traceback."""

    def wrap(handler: Callable[..., Awaitable[Result]]) -> Callable[..., Awaitable[Result]]:
        @functools.wraps(handler)
        async def run(ls: CnlServer, params: Any) -> Result:
            try:
                return await handler(ls, params)
            except JsonRpcException:
                raise
            except Exception as exc:
                log.error("%s failed: %s: %s", name, type(exc).__name__, exc)
                raise JsonRpcInternalError(
                    f"cnlmc could not answer {name}: {type(exc).__name__}: {exc} (a bug in cnlmc; please report it)"
                ) from None

        return run

    return wrap


server = CnlServer()


@server.feature(types.INITIALIZE)
def on_initialize(ls: CnlServer, params: types.InitializeParams) -> None:
    ls.apply_settings(params.initialization_options)


@server.feature(types.WORKSPACE_DID_CHANGE_CONFIGURATION)
def on_configuration(ls: CnlServer, params: types.DidChangeConfigurationParams) -> None:
    ls.apply_settings(params.settings)
    for uri in ls.documents:
        ls.schedule(uri)  # the words may have changed: re-check every open document


@server.feature(types.TEXT_DOCUMENT_DID_OPEN)
def did_open(ls: CnlServer, params: types.DidOpenTextDocumentParams) -> None:
    ls.schedule(params.text_document.uri)


@server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
def did_change(ls: CnlServer, params: types.DidChangeTextDocumentParams) -> None:
    ls.schedule(params.text_document.uri)


@server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
def did_close(ls: CnlServer, params: types.DidCloseTextDocumentParams) -> None:
    ls.start_close(params.text_document.uri)


@server.feature(types.TEXT_DOCUMENT_HOVER)
@answered("hover")
async def on_hover(ls: CnlServer, params: types.HoverParams) -> types.Hover | None:
    snap = await ls.snapshot(params.text_document.uri)
    if snap is None:
        return None
    return await ls.worker.call(hover.hover, snap, params.position, ls.analyzer.lexicon)


@server.feature(
    types.TEXT_DOCUMENT_COMPLETION, types.CompletionOptions(trigger_characters=[" ", ","], resolve_provider=False)
)
@answered("completion")
async def on_completion(ls: CnlServer, params: types.CompletionParams) -> types.CompletionList | None:
    snap = await ls.snapshot(params.text_document.uri)
    if snap is None:
        return None
    return await ls.worker.call(completion.complete, snap, params.position, ls.analyzer.lexicon)


@server.feature(
    types.TEXT_DOCUMENT_CODE_ACTION, types.CodeActionOptions(code_action_kinds=[types.CodeActionKind.QuickFix])
)
@answered("codeAction")
async def on_code_action(ls: CnlServer, params: types.CodeActionParams) -> list[types.CodeAction] | None:
    snap = await ls.snapshot(params.text_document.uri)
    if snap is None:
        return None
    uri, lexicon = params.text_document.uri, ls.analyzer.lexicon
    return await ls.worker.call(actions.quick_fixes, snap, uri, params.range, lexicon)


@server.feature(types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL, tokens.LEGEND)
@answered("semanticTokens")
async def on_semantic_tokens(ls: CnlServer, params: types.SemanticTokensParams) -> types.SemanticTokens:
    snap = await ls.snapshot(params.text_document.uri)
    if snap is None:
        return types.SemanticTokens(data=[])
    return tokens.encode(await ls.worker.collect(tokens.token_batches(snap, ls.analyzer.lexicon)))


@server.feature(types.TEXT_DOCUMENT_DOCUMENT_COLOR)
@answered("documentColor")
async def on_document_colour(ls: CnlServer, params: types.DocumentColorParams) -> list[types.ColorInformation]:
    snap = await ls.snapshot(params.text_document.uri)
    if snap is None:
        return []
    return await ls.worker.collect(colours.colour_batches(snap, ls.analyzer.lexicon))


@server.feature(types.TEXT_DOCUMENT_COLOR_PRESENTATION)
@answered("colorPresentation")
async def on_colour_presentation(ls: CnlServer, params: types.ColorPresentationParams) -> list[types.ColorPresentation]:
    snap = await ls.snapshot(params.text_document.uri)
    lexicon = ls.analyzer.lexicon
    replaces = await ls.worker.call(colours.is_colour_range, snap, params.range) if snap else True
    return await ls.worker.call(colours.presentations, params.color, params.range, lexicon, replaces)


@server.feature(types.TEXT_DOCUMENT_INLAY_HINT)
@answered("inlayHint")
async def on_inlay_hints(ls: CnlServer, params: types.InlayHintParams) -> list[types.InlayHint]:
    if not ls.settings.inlay_hints:
        return []
    snap = await ls.snapshot(params.text_document.uri)
    return await ls.worker.collect(inlay.hint_batches(snap, params.range)) if snap else []


class OneLineFormatter(logging.Formatter):
    """Log lines on stderr without tracebacks: an exception is named in the line it ends."""

    def format(self, record: logging.LogRecord) -> str:
        text = record.getMessage()
        if record.exc_info and record.exc_info[1] is not None:
            exc = record.exc_info[1]
            text += f": {type(exc).__name__}: {exc}"
        text = " ".join(text.split())
        if len(text) > MAX_LOG_LINE:
            text = text[: MAX_LOG_LINE - 3] + "..."
        return f"cnlmc-lsp {record.levelname} {text}"


def use_the_c_allocator() -> None:
    """Run on the C allocator (Linux, unless PYTHONMALLOC says otherwise), by starting again
    with PYTHONMALLOC=malloc before anything is read from stdin. Python's small-object allocator
    keeps each 1 MiB arena while one object in it lives, so the memory of closed documents stayed
    with the process (bench/lsp_memory.py: 90 MB kept after 100 documents); glibc's malloc,
    trimmed after each close (MemoryRelease), gives it back."""
    if not sys.platform.startswith("linux") or "PYTHONMALLOC" in os.environ:
        return
    try:
        os.execve(sys.executable, [sys.executable, *sys.orig_argv[1:]], {**os.environ, "PYTHONMALLOC": "malloc"})
    except OSError as exc:  # keep serving on the default allocator
        log.warning("could not restart on the C allocator (%s); memory of closed documents may stay", exc)


def main() -> None:
    use_the_c_allocator()
    handler = logging.StreamHandler()  # stderr
    handler.setFormatter(OneLineFormatter())
    logging.basicConfig(level=logging.WARNING, handlers=[handler])
    keep_collections_small()
    stdin = open(sys.stdin.fileno(), "rb", closefd=False)  # the reader thread's own (see pump)
    raise SystemExit(server.serve(stdin, sys.stdout.buffer))


if __name__ == "__main__":
    main()
