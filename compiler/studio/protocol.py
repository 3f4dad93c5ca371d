"""The studio's WebSocket messages: the page sends {op, seq, ...}, the server answers each with
{op, seq, ...} (or {op: "error", seq, message}). Each tab's requests are answered in order, on a
worker thread (an analysis with its view payloads takes up to half a second): the event loop stays
free for the other tabs and for the file downloads; the refinement chips are found in the
background and sent when ready.

  edit {text[, fresh]}          -> analysis {diagnostics, tokens, colours, materials, payloads, history, ok, timing}
  refine {words}                -> analysis {..., text}  (the document with the refinement line)
  undo / redo                   -> analysis {..., text}
  complete {text, line, character} -> completion {items}
  hover {text, line, character} -> hover {markdown, range} | hover {}
  export {key, text}            -> exported {url, name, notes}
  ar_model {text}               -> ar_model {glb, usdz, notes}
  hear_chunk {pcm}              -> hearing {seconds}  (the utterance so far, streamed while recording)
  hear {pcm}                    -> analysis {..., text, heard, message} | heard {message[, heard]}
                                   (pcm: the rest of the utterance after its chunks, or all of it:
                                   base64 16-bit mono PCM at hello's speech.rate)
and, unasked, chips {words, text} after an analysis that made a history step.

Messages are read as they arrive and answered in order by one task: an edit is numbered when it
arrives, so one that a newer edit replaced while it waited is answered {op: "skipped"} at once,
without its analysis and payloads.

A payload's shader and tables go to a page once (SentParts): after that the payload names them by
key (`shader`, a table's `key`) without their text; a page that lacks one (it keeps `parts_kept`,
said in hello) sends the edit again with `fresh: true` and gets them all."""

from __future__ import annotations

import asyncio
import base64
import binascii
import functools
import json
import logging
import time
from collections.abc import Callable
from typing import Any

from aiohttp import WSMsgType, web

from .ar import ARFailed
from .exports import ExportFailed
from .session import Closed, Replaced, StudioSession
from .speech import StudioEars

JSONDict = dict[str, Any]
#: requests read ahead of the one being answered (our choice: edits come one per keystroke burst;
#: a client that sends more waits, the socket is not read meanwhile)
QUEUED_REQUESTS = 64
log = logging.getLogger("cnlmc.studio")


class Dispatcher:
    def __init__(
        self, session: StudioSession, socket: web.WebSocketResponse, initial_text: str, ears: StudioEars
    ) -> None:
        self.session = session
        self.ears = ears
        self.socket = socket
        self.initial_text = initial_text
        self.chip_task: asyncio.Task[None] | None = None
        self.streamed = bytearray()  # the utterance's chunks so far (hear_chunk), until its `hear`
        #: (request, its edit number or None, when it was read: time.perf_counter())
        self.queue: asyncio.Queue[tuple[JSONDict, int | None, float]] = asyncio.Queue(QUEUED_REQUESTS)

    def stop(self) -> None:
        if self.chip_task is not None:
            self.chip_task.cancel()

    async def hello(self, exports: list[JSONDict]) -> None:
        session = self.session
        await self.socket.send_json(
            {
                "op": "hello",
                "session": session.id,
                "files_url": f"/files/{session.id}/view/",
                "data_url": "/view-data/",
                "text": self.initial_text,
                "exports": exports,
                "view": session.view.module is not None,
                "parts_kept": session.settings.limits.max_sent_parts,
                "speech": {"rate": self.ears.rate, "max_seconds": session.settings.limits.max_utterance_seconds},
            }
        )

    async def serve(self) -> None:
        """Read the socket until it closes; one task answers the requests in order."""
        answering = asyncio.create_task(self.answer_queued())
        try:
            async for message in self.socket:
                if message.type != WSMsgType.TEXT:
                    break
                request = _parsed(message.data)
                ticket = self.session.announce_edit() if request.get("op") == "edit" else None
                await self.queue.put((request, ticket, time.perf_counter()))
        finally:
            answering.cancel()

    async def answer_queued(self) -> None:
        while True:
            request, ticket, read = await self.queue.get()
            await self.handle(request, ticket, read)

    async def handle(self, message: JSONDict, ticket: int | None = None, read: float | None = None) -> None:
        """Answer one request; an analysis says how long the server took (`timing`: queued_ms from
        reading the request to starting it, server_ms from reading it to the answer, JSON not included)."""
        op, seq = str(message.get("op", "")), message.get("seq")
        started = time.perf_counter()
        handler = getattr(self, f"op_{op}", None)
        if handler is None:
            await self.reply(seq, {"op": "error", "message": f"unknown request '{op}'"})
            return
        try:
            answer = await (handler(message, ticket) if op == "edit" else handler(message))
        except Replaced:
            answer = {"op": "skipped"}
        except (ValueError, ExportFailed, ARFailed, Closed) as exc:
            answer = {"op": "error", "message": str(exc)}
        except Exception as exc:  # never a traceback in the page
            log.error("studio: %s while answering '%s': %s", type(exc).__name__, op, exc)
            answer = {"op": "error", "message": f"the studio could not answer '{op}' ({type(exc).__name__})"}
        if answer is not None and read is not None and isinstance(answer.get("timing"), dict):
            answer["timing"]["queued_ms"] = round((started - read) * 1000, 2)
            answer["timing"]["server_ms"] = round((time.perf_counter() - read) * 1000, 2)
        if answer is not None:
            await self.reply(seq, answer)

    async def reply(self, seq: Any, answer: JSONDict) -> None:
        if not self.socket.closed:
            await self.socket.send_json({**answer, "seq": seq})

    async def in_thread(self, work: Callable[..., Any], *args: Any) -> Any:
        return await asyncio.get_running_loop().run_in_executor(None, functools.partial(work, *args))

    async def analysed(self, answer: JSONDict) -> JSONDict:
        if answer.get("recorded"):
            self.offer_chips()
        return {"op": "analysis", **answer}

    def offer_chips(self) -> None:
        self.stop()
        self.chip_task = asyncio.create_task(self.send_chips(self.session.text))

    async def send_chips(self, text: str) -> None:
        words = await self.in_thread(self.session.chips)
        if text == self.session.text:
            await self.reply(None, {"op": "chips", "words": words, "text": text})

    # ------------------------------------------------------------------ requests

    async def op_edit(self, message: JSONDict, ticket: int | None = None) -> JSONDict:
        self.session.check_replaced(ticket)  # skipped without a thread when already replaced
        if message.get("fresh") is True:
            self.session.sent.forget()
        return await self.analysed(await self.in_thread(self.session.edit, _text(message, "text"), None, ticket))

    async def op_refine(self, message: JSONDict) -> JSONDict:
        return await self.analysed(await self.in_thread(self.session.refine, _text(message, "words")))

    async def op_undo(self, message: JSONDict) -> JSONDict:
        return await self.analysed(await self.in_thread(self.session.undo))

    async def op_redo(self, message: JSONDict) -> JSONDict:
        return await self.analysed(await self.in_thread(self.session.redo))

    async def op_complete(self, message: JSONDict) -> JSONDict:
        """The completion items, best first, at most the settings' number; `complete` says whether
        they are all (the page then filters them itself as more letters are typed)."""
        text, line, character = _position(self.session, message)
        found = await self.in_thread(self.session.engine.completion, text, line, character)
        items = sorted(found, key=lambda item: str(item["sort"]))
        limit = self.session.settings.limits.max_completion_items
        return {"op": "completion", "items": items[:limit], "complete": len(items) <= limit}

    async def op_hover(self, message: JSONDict) -> JSONDict:
        text, line, character = _position(self.session, message)
        return {"op": "hover", **(await self.in_thread(self.session.engine.hover, text, line, character) or {})}

    async def op_export(self, message: JSONDict) -> JSONDict:
        exported = await self.in_thread(self.session.export, _text(message, "key"), _text(message, "text"))
        return {
            "op": "exported",
            "url": self.url(exported.path),
            "name": exported.path.rsplit("/", 1)[-1],
            "notes": exported.notes,
        }

    async def op_ar_model(self, message: JSONDict) -> JSONDict:
        text = _text(message, "text")
        glb = await self.in_thread(self.session.export, "glb", text)
        usdz = await self.in_thread(self.session.export, "usdz", text)
        return {
            "op": "ar_model",
            "glb": self.url(glb.path),
            "usdz": self.url(usdz.path),
            "notes": glb.notes + usdz.notes,
        }

    async def op_hear_chunk(self, message: JSONDict) -> JSONDict:
        """A part of the utterance being recorded: kept until its `hear` (an utterance over the
        length limit is refused, and its chunks dropped)."""
        try:
            self.streamed += _audio(message, self._utterance_bytes(), len(self.streamed))
        except ValueError:
            self.streamed.clear()
            raise
        return {"op": "hearing", "seconds": len(self.streamed) / 2 / self.ears.rate}

    async def op_hear(self, message: JSONDict) -> JSONDict:
        streamed, self.streamed = bytes(self.streamed), bytearray()
        pcm = streamed + _audio(message, self._utterance_bytes(), len(streamed))
        answer = await self.in_thread(self.session.speak, self.ears, pcm)
        return answer if answer.get("op") == "heard" else await self.analysed(answer)

    def _utterance_bytes(self) -> int:
        return self.ears.rate * 2 * self.session.settings.limits.max_utterance_seconds

    def url(self, relative: str) -> str:
        return f"/files/{self.session.id}/{relative}"


def _parsed(data: str) -> JSONDict:
    try:
        found = json.loads(data)
    except ValueError:
        return {}
    return found if isinstance(found, dict) else {}


def _text(message: JSONDict, key: str) -> str:
    value = message.get(key)
    if not isinstance(value, str):
        raise ValueError(f"the request has no '{key}'")
    return value


def _audio(message: JSONDict, max_bytes: int, before: int = 0) -> bytes:
    """The audio of a `hear` or `hear_chunk` request: 16-bit PCM that, after the `before` bytes of
    the utterance already streamed, keeps it within `max_bytes`."""
    try:
        pcm = base64.b64decode(_text(message, "pcm"), validate=True)
    except binascii.Error:
        raise ValueError("the request's audio is not base64") from None
    if len(pcm) % 2 or before + len(pcm) > max_bytes:
        raise ValueError(f"an utterance is 16-bit audio of at most {max_bytes // 2} samples")
    return pcm


def _position(session: StudioSession, message: JSONDict) -> tuple[str, int, int]:
    text = _text(message, "text")
    session.check_size(text)
    line, character = message.get("line"), message.get("character")
    if not isinstance(line, int) or not isinstance(character, int) or line < 0 or character < 0:
        raise ValueError("the request has no position")
    return text, line, character
