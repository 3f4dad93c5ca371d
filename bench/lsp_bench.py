"""Latency of diagnostics after an edit, over stdio with a real LSP client (pygls).

    .venv/bin/python bench/lsp_bench.py [--edits 200] [--debounce 0]

For a 1-line and a 1,000-line document: open it, then make edits one at a time (each a new
text: a changed comment, a misspelled word, a changed phrase) and time from sending
didChange to receiving publishDiagnostics for that version. Prints median and p99 (goal:
p99 <= 50 ms at 1,000 lines with debounce 0), then, for reference, what compiling the whole
1,000-line text once costs in-process, stage by stage.
"""

from __future__ import annotations

import argparse
import asyncio
import random
import statistics
import sys
import time

from lsprotocol import types
from pygls.lsp.client import LanguageClient
from pygls.protocol import LanguageServerProtocol

ADVERBS = ["", "lightly ", "slightly ", "very ", "barely "]
ADJECTIVES = ["brushed", "polished", "anodized", "sandblasted", "hammered", "matte", "varnished", "rusty"]
COLOURS = ["", "blue ", "dark red ", "pale orange ", "slate gray ", "gold "]
NOUNS = ["aluminum", "steel", "brass", "copper", "oak", "plastic", "titanium", "walnut"]
REFINEMENTS = ["darker", "less diffuse", "more gloss", "rougher", "lighter blue"]


METALS = ["aluminum", "steel", "brass", "copper", "titanium"]


def document(lines: int, seed: int = 0, nouns=None) -> list[str]:
    """Varied material lines (so blocks are mostly distinct), some refinements and comments.
    With the default nouns about a third of the lines draw a warning (e.g. 'anodized oak');
    with `nouns=METALS` every line is clean, as in a finished material library."""
    nouns = nouns or NOUNS
    rng = random.Random(seed)
    out = []
    for i in range(lines):
        roll = rng.random()
        if roll < 0.15 and out:
            out.append(rng.choice(REFINEMENTS))
        elif roll < 0.2:
            out.append(f"# note {i}")
        else:
            out.append(f"m{i}: {rng.choice(ADVERBS)}{rng.choice(ADJECTIVES)}, {rng.choice(COLOURS)}{rng.choice(nouns)}")
    return out


def edited_line(i: int) -> str:
    """A line never seen before: every edit makes the server do real work."""
    kind = i % 3
    if kind == 0:
        return f"e{i}: lightly brushed, blue anodized aluminum # edit {i}"
    if kind == 1:
        return f"blu{chr(97 + i % 26)}{i} plastic"
    return f"e{i}: {ADJECTIVES[i % len(ADJECTIVES)]} {COLOURS[i % len(COLOURS)]}{NOUNS[i % len(NOUNS)]}"


class FrameTimingProtocol(LanguageServerProtocol):
    """Notes when a publishDiagnostics frame arrives, before the client turns its JSON into objects."""

    def structure_message(self, data):
        if isinstance(data, dict) and data.get("method") == types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS:
            params = data.get("params") or {}
            self._server.frames[(params.get("uri"), params.get("version"))] = time.perf_counter()
        return super().structure_message(data)


class TimedClient(LanguageClient):
    def __init__(self):
        super().__init__("cnlmc-bench", "0.1", protocol_cls=FrameTimingProtocol)
        self.frames: dict[tuple[str, int], float] = {}
        self.arrivals: dict[tuple[str, int], float] = {}
        self.counts: dict[tuple[str, int], int] = {}
        self.event = asyncio.Event()

        @self.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def on_publish(params: types.PublishDiagnosticsParams):
            self.arrivals[(params.uri, params.version)] = time.perf_counter()
            self.counts[(params.uri, params.version)] = len(params.diagnostics)
            self.event.set()

    async def wait_version(self, uri: str, version: int, timeout: float = 60.0) -> float:
        deadline = time.perf_counter() + timeout
        while (uri, version) not in self.arrivals:
            self.event.clear()
            if (uri, version) in self.arrivals:
                break
            remaining = deadline - time.perf_counter()
            if remaining <= 0:
                raise TimeoutError(f"no diagnostics for {uri} v{version}")
            try:
                await asyncio.wait_for(self.event.wait(), remaining)
            except TimeoutError:
                pass
        return self.arrivals[(uri, version)]


async def measure(client: TimedClient, name: str, lines: list[str], edits: int) -> list[float]:
    uri = f"file:///bench/{name}.cnl"
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(
            types.TextDocumentItem(uri=uri, language_id="cnl", version=1, text="\n".join(lines))
        )
    )
    await client.wait_version(uri, 1)
    rng = random.Random(1)
    latencies, at_frame = [], []
    for i in range(edits):
        line = rng.randrange(len(lines))
        new = edited_line(i)
        change = types.TextDocumentContentChangePartial(
            range=types.Range(types.Position(line, 0), types.Position(line, len(lines[line]))), text=new
        )
        lines[line] = new
        version = i + 2
        sent = time.perf_counter()
        client.text_document_did_change(
            types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(uri=uri, version=version), [change])
        )
        arrived = await client.wait_version(uri, version)
        latencies.append((arrived - sent) * 1000)
        at_frame.append((client.frames[(uri, version)] - sent) * 1000)
    return latencies, at_frame


def percentile(values: list[float], p: float) -> float:
    ordered = sorted(values)
    k = min(len(ordered) - 1, max(0, round(p / 100 * (len(ordered) - 1))))
    return ordered[k]


async def run(edits: int, debounce: int) -> list[tuple]:
    client = TimedClient()
    await client.start_io(sys.executable, "-m", "cnlmc", "lsp")
    await client.initialize_async(
        types.InitializeParams(capabilities=types.ClientCapabilities(), initialization_options={"debounceMs": debounce})
    )
    client.initialized(types.InitializedParams())
    rows = []
    for name, count, nouns in (("one-line", 1, None), ("thousand-lines", 1000, None), ("thousand-clean", 1000, METALS)):
        latencies, at_frame = await measure(client, f"{name}-{debounce}", document(count, nouns=nouns), edits)
        diagnostics = client.counts[(f"file:///bench/{name}-{debounce}.cnl", edits + 1)]
        rows.append(
            (
                name,
                count,
                diagnostics,
                debounce,
                edits,
                statistics.median(at_frame),
                percentile(at_frame, 99),
                statistics.median(latencies),
                percentile(latencies, 99),
                max(latencies),
            )
        )
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    return rows


def whole_compile_stages(lines: list[str]) -> list[tuple[str, float]]:
    """What one non-incremental compile of the text costs, by stage (in-process, ms)."""
    from cnlmc.analyze import analyze, to_ir
    from cnlmc.api import lexicon_for
    from cnlmc.document import parse_document
    from cnlmc.state import Context

    lexicon = lexicon_for()
    text = "\n".join(lines)
    t0 = time.perf_counter()
    doc = parse_document(text, lexicon, "bench.cnl")
    t1 = time.perf_counter()
    ctx = Context(lexicon, filename="bench.cnl")
    states, diags = analyze(doc, ctx)
    t2 = time.perf_counter()
    to_ir(states, diags, ctx)
    t3 = time.perf_counter()
    return [
        ("parse (tag + LALR)", (t1 - t0) * 1000),
        ("analyze (passes)", (t2 - t1) * 1000),
        ("to_ir (rounding, provenance)", (t3 - t2) * 1000),
        ("total", (t3 - t0) * 1000),
    ]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--edits", type=int, default=200)
    parser.add_argument(
        "--debounce", type=int, nargs="*", default=[0, 120], help="server debounce settings to measure (ms)"
    )
    args = parser.parse_args()
    rows = []
    for debounce in args.debounce:
        rows += asyncio.run(run(args.edits if debounce == 0 else min(args.edits, 40), debounce))
    print("latency from didChange sent to publishDiagnostics: when its frame arrives | after the client parsed it")
    print(
        f"{'document':<16}{'lines':>6}{'diags':>6}{'debounce':>9}{'edits':>6}"
        f"{'frame med':>10}{'frame p99':>10}{'parsed med':>11}{'parsed p99':>11}{'max':>8}"
    )
    for name, count, diags, debounce, edits, f_med, f_p99, median, p99, worst in rows:
        print(
            f"{name:<16}{count:>6}{diags:>6}{debounce:>9}{edits:>6}"
            f"{f_med:>10.2f}{f_p99:>10.2f}{median:>11.2f}{p99:>11.2f}{worst:>8.2f}"
        )
    print("(ms; goal: p99 <= 50 ms at 1,000 lines with debounce 0)")
    print("\nfor reference, compiling the whole 1,000-line text once (no incremental cache):")
    whole_compile_stages(document(1000))  # warm up the grammar and lexicon
    for stage, ms in whole_compile_stages(document(1000, seed=2)):
        print(f"  {stage:<30}{ms:>8.1f} ms")


if __name__ == "__main__":
    main()
