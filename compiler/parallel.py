"""One large document compiled on several processes (#13), with the bytes of one process.

The lines are cut into chunks of CHUNK_LINES; worker k of n (a forked process) compiles chunks
k, k+n, k+2n, ... and sends each chunk's result down its own pipe (a thread of the worker sends it
while the worker compiles its next chunk: _Outbox); the parent takes each chunk's
result as soon as it is sent (up to AHEAD_CHUNKS of one worker's held, waiting for an earlier
chunk of another) and replays them in document order (chunk j from worker j mod n). So a worker
slowed by a busy machine does not stall the others at every chunk, and memory stays bounded. A chunk owns the materials whose line lies in it: its leading refinement lines
belong to the material above (the chunk before reads on past its end up to the next material).

What a chunk sends is a list of events the parent replays exactly as analyze._streamed_states
would have made them in one process: every diagnostic in the order it was found ('add'), the
states' diagnostics that are reported only when new ('new'), the two points where the sequential
code takes note of what was reported ('begin', 'end'), and each material: its name before repeats
are numbered (numbered by the parent, which sees the whole document) and its states' IR, checked
and encoded (EncodedMaterial) without the name, which the parent puts in front.

Only above PARALLEL_MIN_LINES lines, with more than one CPU, and where processes can be forked;
otherwise (or with CNLMC_WORKERS=1) the document is compiled in this process.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import pickle
import queue
import signal
import sys
import threading
from collections import deque
from collections.abc import Iterator, Mapping
from multiprocessing.connection import Connection, wait
from typing import Any

from . import ast
from .analyze import (
    after_change,
    base_name,
    build_states,
    changed_material,
    orphan_line,
    orphan_refinement,
    unique_name,
)
from .diagnostics import Diagnostic
from .document import parse_line
from .interrupts import SIGNALS
from .ir import EncodedMaterial, JSONDict, json_text, material_ir
from .ir_check import check_material
from .lexicon import Lexicon
from .lines import LINE_END
from .params import Params
from .state import Context
from .tagger import Tagger
from .workers import WORKERS_VARIABLE

CHUNK_LINES = 1000
AHEAD_CHUNKS = 3  # a worker's results the parent holds before it stops reading from that worker

ADD, NEW, BEGIN, END, MATERIAL = range(5)  # the kinds of event (see the module's doc)
Event = tuple[Any, ...]
FRONT_KEYS = ("label", "phrase")  # a material's IR keys between its name and its variant
NAMED_KEYS = ("name", *FRONT_KEYS, "variant")  # the keys up to the variant's, which names the group


def chunk_starts(source: str, lines_per_chunk: int = CHUNK_LINES) -> list[tuple[int, int]]:
    """(line number, offset) of the first line of each chunk."""
    starts = [(1, 0)]
    number = 1
    for end in LINE_END.finditer(source):
        number += 1
        if (number - 1) % lines_per_chunk == 0:
            starts.append((number, end.end()))
    return starts


def parallel_material_irs(
    source: str, ctx: Context, diags: list[Diagnostic], workers: int, lines_per_chunk: int = CHUNK_LINES
) -> Iterator[Mapping[str, Any]]:
    """What analyze.iter_material_irs gives (as EncodedMaterial) and adds to `diags`, made by
    `workers` forked processes; they are stopped when the iterator is closed or fails."""
    starts = chunk_starts(source, lines_per_chunk)
    chunks = [(i, *start, starts[i + 1][0] if i + 1 < len(starts) else None) for i, start in enumerate(starts)]
    fork = multiprocessing.get_context("fork")
    count = min(workers, len(chunks))
    pipes, processes = [], []
    sys.stdout.flush()  # a fork flushes its copy of the standard streams when it ends: nothing may be left in them
    sys.stderr.flush()
    try:
        for k in range(count):
            receiver, sender = fork.Pipe(duplex=False)
            process = fork.Process(target=_work, args=(sender, source, ctx, chunks[k::count]), daemon=True)
            process.start()
            sender.close()
            pipes.append(receiver)
            processes.append(process)
        replay = _Replay(diags)
        inbox = _Inbox(pipes, [len(chunks[k::count]) for k in range(count)])
        for j in range(len(chunks)):
            yield from replay.events(inbox.take(j % count))
        for process in processes:
            process.join()
    finally:
        for process in processes:
            if process.is_alive():
                process.terminate()
            process.join()
        for pipe in pipes:
            pipe.close()


class _Inbox:
    """The parent's reading: every worker's results taken as they are sent (at most AHEAD_CHUNKS
    held per worker), handed out per worker in the order it sent them."""

    def __init__(self, pipes: list[Connection], expected: list[int]) -> None:
        self.pipes, self.left = pipes, list(expected)
        self.held: list[deque[object]] = [deque() for _ in pipes]

    def take(self, worker: int) -> list[Event]:
        """The worker's next chunk's events (what the same document raises in one process, where
        compiling that chunk failed)."""
        while not self.held[worker]:
            self._read_ready(worker)
        result = self.held[worker].popleft()
        if isinstance(result, BaseException):
            raise result
        events: list[Event] = result  # type: ignore[assignment]
        return events

    def _read_ready(self, needed: int) -> None:
        """Wait for the needed worker's result, taking whatever the others have sent meanwhile."""
        if not self.left[needed]:
            raise RuntimeError(
                f"a worker process sent less than it was given ({WORKERS_VARIABLE}=1 compiles in one process)"
            )
        open_to = [
            k for k in range(len(self.pipes)) if self.left[k] and (k == needed or len(self.held[k]) < AHEAD_CHUNKS)
        ]
        ready = wait([self.pipes[k] for k in open_to])
        for k in open_to:
            if self.pipes[k] in ready:
                self.held[k].append(_receive(self.pipes[k]))
                self.left[k] -= 1


def _receive(pipe: Connection) -> object:
    """One result from a worker: its chunk's events or the exception compiling it raised."""
    try:
        result: object = pipe.recv()
    except EOFError:
        raise RuntimeError(
            f"a worker process stopped before it sent its materials ({WORKERS_VARIABLE}=1 compiles in one process)"
        ) from None
    return result


class _Replay:
    """The parent's half: diagnostics reported as analyze._streamed_states reports them, names
    numbered over the whole document, each material's name put in front of its text."""

    def __init__(self, diags: list[Diagnostic]) -> None:
        self.diags, self.seen, self.mark, self.used = diags, set[Diagnostic](), 0, dict[str, int]()

    def events(self, events: list[Event]) -> Iterator[Mapping[str, Any]]:
        diags, seen = self.diags, self.seen
        for event in events:
            kind = event[0]
            if kind == ADD:
                diags.append(event[1])
            elif kind == NEW:
                if event[1] not in seen:
                    seen.add(event[1])
                    diags.append(event[1])
            elif kind == BEGIN:
                seen.update(diags[self.mark :])
            elif kind == END:
                self.mark = len(diags)
            else:
                name = unique_name(event[1], self.used)
                for encoded in event[2]:
                    yield self.named(encoded, name)

    def named(self, encoded: tuple[dict[str, Any] | None, str, str] | JSONDict, name: str) -> Mapping[str, Any]:
        """A material made by a worker, given its name (and its variant's group); a variant's name
        is made unique over the document as analyze._variant_named makes it."""
        if isinstance(encoded, dict):  # failed the check: the writer says where
            variant = encoded["variant"]
            if variant is not None:
                variant["group"] = name
            return {**encoded, "name": unique_name(f"{name}__{variant['name']}", self.used) if variant else name}
        variant, front, rest = encoded
        if variant is None:  # the common case: json_text(None) written out
            return EncodedMaterial(f'{{"name": {json_text(name)}, {front}, "variant": null, {rest}')
        variant["group"] = name
        name = unique_name(f"{name}__{variant['name']}", self.used)
        return EncodedMaterial(f'{{"name": {json_text(name)}, {front}, "variant": {json_text(variant)}, {rest}')


# ---------------------------------------------------------------- the worker's half


def _work(pipe: Connection, source: str, ctx: Context, chunks: list[tuple[int, int, int, int | None]]) -> None:
    """A worker process: each of its chunks' events down the pipe, in order (an exception instead,
    and nothing more, where compiling fails). Signals end it at once, as they would a program
    without handlers: the parent's handlers and clean-up are the parent's (cnlmc.interrupts)."""
    for signum in SIGNALS:
        signal.signal(signum, signal.SIG_DFL)
    outbox = _Outbox(pipe)
    try:
        for index, number, offset, end in chunks:
            if outbox.broken:
                break  # the parent has gone or stopped reading: nothing left to tell
            outbox.put(chunk_events(source, ctx, number, offset, end, first=index == 0))
    except Exception as exc:  # handed to the parent, which raises it
        outbox.put(_sendable(exc))
    finally:
        outbox.close()


class _Outbox:
    """A worker's sending: each result is sent down the pipe by a thread of the worker while it
    compiles its next chunk, so a parent busy writing another worker's chunk no longer holds this
    one up (its send waited for the parent to read); at most one result waits for the thread.
    `broken` once the parent has gone (what is left is dropped)."""

    def __init__(self, pipe: Connection) -> None:
        self.pipe, self.broken = pipe, False
        self.queue: queue.Queue[object] = queue.Queue(maxsize=1)
        self.thread = threading.Thread(target=self._send_all, name="cnlmc-worker-send", daemon=True)
        self.thread.start()

    def put(self, result: object) -> None:
        self.queue.put(result)

    def close(self) -> None:
        """Send what is left, then close the pipe."""
        self.queue.put(_DONE)
        self.thread.join()
        self.pipe.close()

    def _send_all(self) -> None:
        while (result := self.queue.get()) is not _DONE:
            if self.broken:
                continue
            try:
                self.pipe.send(result)
            except OSError:  # the parent has gone or stopped reading
                self.broken = True
            except Exception as exc:  # a result that cannot be sent: the parent is told, and no more is sent
                self.broken = True
                with contextlib.suppress(Exception):
                    self.pipe.send(_sendable(exc))


_DONE = object()  # the end of a worker's results


def _sendable(exc: Exception) -> Exception:
    """`exc`, or a RuntimeError saying what it was where it cannot be pickled."""
    try:
        pickle.dumps(exc)
    except Exception:  # anything pickling raises
        return RuntimeError(f"{type(exc).__name__}: {exc}")
    return exc


def chunk_events(source: str, ctx: Context, number: int, offset: int, end: int | None, first: bool) -> list[Event]:
    """The events of the chunk whose first line is `number` at `offset`, up to line `end` (excluded;
    None: the last chunk); `first`: the document's first chunk."""
    diags: list[Diagnostic] = []
    events: list[Event] = []
    flushed = 0
    convention = ctx.settings.get("alpha_convention", Params.alpha_convention)
    rounded_optics = ctx.lexicon.caches.rounded_optics
    items = _items(source, number, offset, Tagger.of(ctx.lexicon), diags)
    for material, refinements in _owned_groups(items, diags, end, first, ctx.lexicon):
        events += [(ADD, d) for d in diags[flushed:]]
        events.append((BEGIN,))
        flushed = len(diags)
        states = build_states(material, refinements, ctx, "", diags)
        events += [(ADD, d) for d in diags[flushed:]]
        flushed = len(diags)
        encoded = []
        for state in states:
            events += [(NEW, d) for d in state.diagnostics]
            encoded.append(_encoded(material_ir(state, convention, rounded_optics)))
        events.append((MATERIAL, base_name(material), encoded))
        events.append((END,))
    events += [(ADD, d) for d in diags[flushed:]]
    return events


_NAMELESS = '{"name": "", '  # how a worker's material (named by the parent) starts
_NO_VARIANT = ', "variant": null, '


def _encoded(material: JSONDict) -> tuple[dict[str, Any] | None, str, str] | JSONDict:
    """The material checked (as the IR writer checks it) and written as JSON text in the pieces
    around what depends on its name (the name, the variant's group): its variant, the text of
    its label and phrase, and the text of the rest (see _Replay.text). One that fails the check is
    sent as it is (the parent's writer checks it again, and fails naming its place in the document)."""
    try:
        check_material(material, "material")
    except ValueError:
        return material
    if material["variant"] is None and material["name"] == "":  # the common case: the text cut in three
        text = json_text(material)  # '{"name": "", FRONT, "variant": null, REST'
        cut = text.index(_NO_VARIANT)  # the key's own: in a string every '"' is escaped
        return None, text[len(_NAMELESS) : cut], text[cut + len(_NO_VARIANT) :]
    front = json_text({key: material[key] for key in FRONT_KEYS if key in material})
    rest = json_text({key: value for key, value in material.items() if key not in NAMED_KEYS})
    return material["variant"], front[1:-1], rest[1:]


def _items(
    source: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]
) -> Iterator[tuple[ast.Item, bool]]:
    """document.iter_items from line `number` (at `offset`) on."""
    for end in LINE_END.finditer(source, offset):
        yield from _item(source[offset : end.start()], number, offset, tagger, diags)
        number, offset = number + 1, end.end()
    yield from _item(source[offset:], number, offset, tagger, diags)


def _item(
    text: str, number: int, offset: int, tagger: Tagger, diags: list[Diagnostic]
) -> Iterator[tuple[ast.Item, bool]]:
    before = len(diags)
    node = parse_line(text, number, offset, tagger, diags)
    if node is not None:
        yield node, len(diags) > before and any(d.is_error for d in diags[before:])


def _owned_groups(
    items: Iterator[tuple[ast.Item, bool]], diags: list[Diagnostic], end: int | None, first: bool, lexicon: Lexicon
) -> Iterator[tuple[ast.Material, list[ast.Refinement]]]:
    """analyze._material_groups over the materials whose line is before `end`: the chunk's
    leading lines up to its first material's, and their diagnostics, are dropped unless it is the
    first (the chunk before reports them); the first material at `end` or later stops it (its
    line's diagnostics kept: in one process they are found before the last material's states are
    made)."""
    material: ast.Material | None = None
    refinements: list[ast.Refinement] = []
    material_ok = False
    for item, has_error in items:
        if isinstance(item, ast.Material):
            if end is not None and item.span.line >= end:
                break
            if material is None and not first:
                diags.clear()  # the leading lines and this one: the chunk before reports them
            elif material is not None and material_ok:
                yield material, refinements
            material, refinements, material_ok = item, [], not has_error
        elif material is None and first and has_error:
            diags.append(orphan_refinement(item))
        elif material is None and first:
            material = orphan_line(item, lexicon, diags)  # 'paler blue' first: its own material
            material_ok = material is not None
        elif material is None:
            pass  # before the chunk's first material: the chunk before reports it
        elif not has_error and item.changes_material and (changed := changed_material(material, item, lexicon)):
            material = changed
            refinements += after_change(item)
        elif not has_error:
            refinements.append(item)
    if material is not None and material_ok:
        yield material, refinements
    elif material is None and not first:
        diags.clear()
