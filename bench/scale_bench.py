"""Time, peak memory and output size of `cnlmc compile` on 1k / 10k / 100k-line files.

Run: .venv/bin/python bench/scale_bench.py [--sizes 1000 10000 100000] [--kinds cycled distinct]
     [--workers 1 2] [--phases 10000]
Two kinds of file, each a material phrase a line (about 35-45 bytes), most of them named, some
followed by a refinement line:
- cycled: drawn from 300 distinct stdlib phrases (phrase_pool), so most lines repeat one;
- distinct: every phrase different (distinct_phrases): adverb x adjective, colour x adjective x
  noun combinations from the stdlib's own word lists, so nothing can be remembered per phrase.
Each file is compiled to IR in a fresh process (`python -m cnlmc compile FILE -o OUT`) with
CNLMC_WORKERS set to each --workers count; its wall and CPU time (user + sys, the workers'
included) and its peak RSS come from that process's own rusage (os.wait4). Printed: per run, then
the RSS per input line beyond the smallest size's (the goal is <= 2 KB) and time ratios against
the size ratio (linear: the same). --phases N: the CPU time per line of each phase (parse,
analysis, boundary check, IR build, check + JSON) in this process, and peer runs in this process
of the previous code path against the current one (one process against two; the old JSON text
function against json_text). The machine is shared: run it more than once and read the CPU times.
"""

from __future__ import annotations

import argparse
import io
import json
import os
import random
import re
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path

POOL_SIZE = 300
REFINEMENTS = ("darker", "lighter", "rougher", "smoother", "glossier", "duller")


def phrase_pool(size: int = POOL_SIZE, seed: int = 13) -> list[str]:
    """`size` distinct stdlib phrases, each compiling without a diagnostic: adjective-noun pairs,
    colours, adverbs, comma groups, coat clauses and a few 'or' alternatives (variants), drawn
    with a fixed seed from the stdlib lexicon's own word lists."""
    from cnlmc.api import compile_source, lexicon_for

    lexicon = lexicon_for()
    adjectives, nouns = sorted(lexicon.all_of("adjectives")), sorted(lexicon.all_of("nouns"))
    colours, adverbs = sorted(lexicon.all_of("colours")), sorted(lexicon.all_of("adverbs"))
    coats = sorted(lexicon.all_of("coats"))
    rng = random.Random(seed)
    forms = (
        lambda: f"{rng.choice(adjectives)} {rng.choice(nouns)}",
        lambda: f"{rng.choice(colours)} {rng.choice(adjectives)} {rng.choice(nouns)}",
        lambda: f"{rng.choice(adverbs)} {rng.choice(adjectives)}, {rng.choice(colours)} {rng.choice(nouns)}",
        lambda: f"{rng.choice(nouns)} with a {rng.choice(colours)} {rng.choice(coats)}",
        lambda: f"{rng.choice(colours)} or {rng.choice(colours)} {rng.choice(nouns)}",
        lambda: rng.choice(nouns),
    )
    pool: list[str] = []
    while len(pool) < size:
        phrase = rng.choice(forms)()
        if phrase in pool:
            continue
        result = compile_source(phrase, "<pool>", lexicon)
        if result.materials and not result.diagnostics:  # no word ignored, nothing clamped
            pool.append(phrase)
    return pool


def clean_lines(lines: list[str]) -> list[str]:
    """The lines that compile, in one document, to a material with no diagnostic on their line."""
    from cnlmc.api import compile_source, lexicon_for

    result = compile_source("\n".join(lines), "<check>", lexicon_for(), keep_stages=False)
    flagged = {d.span.line for d in result.diagnostics if d.span}
    return [line for n, line in enumerate(lines, 1) if n not in flagged]


def distinct_phrases(count: int, seed: int = 13) -> list[str]:
    """`count` different phrases, none repeated: checked adjective-noun pairs and colours (each
    compiles without a diagnostic; colours of one word or a plain compound) combined as
    'COLOUR ADJECTIVE NOUN', 'ADVERB ADJECTIVE, COLOUR NOUN' and 'COLOUR NOUN', each combination
    checked too ('dirt brown paper' reads as two nouns: left out)."""
    from cnlmc.api import lexicon_for

    lexicon = lexicon_for()
    rng = random.Random(seed)
    adjectives, nouns = sorted(lexicon.all_of("adjectives")), sorted(lexicon.all_of("nouns"))
    adverbs = sorted(lexicon.all_of("adverbs"))
    nouns = [noun for noun in nouns if " " not in noun]  # 'reddish gray card' would read as a colour 'reddish gray'
    candidates = sorted({f"{rng.choice(adjectives)} {rng.choice(nouns)}" for _ in range(3000)})
    pairs = [line.split(" ", 1) for line in clean_lines(candidates)]
    plain = [c for c in sorted(lexicon.all_of("colours")) if re.fullmatch(r"[a-z]+( [a-z]+)?", c)]
    colours = [line.rsplit(" ", 1)[0] for line in clean_lines([f"{c} plastic" for c in plain])]
    forms: tuple[Callable[[str, str], str], ...] = (
        lambda a, n: f"{rng.choice(colours)} {a} {n}",
        lambda a, n: f"{rng.choice(adverbs)} {a}, {rng.choice(colours)} {n}",
        lambda a, n: f"{rng.choice(colours)} {n}",
    )
    seen: set[str] = set()
    out: list[str] = []
    while len(out) < count:  # each batch checked as a whole: a combination may still read otherwise
        batch: list[str] = []
        while len(batch) < min(count - len(out), 20_000) + 64:
            adjective, noun = rng.choice(pairs)
            phrase = rng.choice(forms)(adjective, noun)
            if phrase not in seen:
                seen.add(phrase)
                batch.append(phrase)
        out += clean_lines(batch)[: count - len(out)]
    return out


@dataclass
class Run:
    kind: str
    workers: int
    lines: int
    input_bytes: int
    wall_s: float
    cpu_s: float
    peak_rss_kb: int
    output_bytes: int
    warnings: int
    exit_code: int
    errors: list[str]  # the first error lines on stderr (a run that exited non-zero measured the error path)


def write_source(path: Path, lines: int, next_phrase: Callable[[], str], seed: int = 13) -> None:
    """`lines` lines: phrases from `next_phrase`, most named (`m12: ...`), a fifth unnamed (their
    names come from the words, repeats numbered), and about one in seven followed by a refinement."""
    rng = random.Random(seed)
    with path.open("w", encoding="utf-8") as out:
        n = 0
        while n < lines:
            phrase = next_phrase()
            out.write(f"m{n}: {phrase}\n" if rng.random() < 0.8 else f"{phrase}\n")
            n += 1
            if n < lines and rng.random() < 0.15:
                out.write(f"{rng.choice(REFINEMENTS)}\n")
                n += 1


def phrase_source(kind: str, lines: int, pool: list[str]) -> Callable[[], str]:
    if kind == "distinct":
        return iter(distinct_phrases(lines)).__next__
    rng = random.Random(7)
    return lambda: rng.choice(pool)


def compile_once(kind: str, workers: int, source: Path, output: Path) -> Run:
    command = [sys.executable, "-m", "cnlmc", "compile", str(source), "-o", str(output), "--max-bytes", "1G"]
    env = {**os.environ, "CNLMC_WORKERS": str(workers)}
    with tempfile.TemporaryFile() as errors:
        start = time.perf_counter()
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=errors, env=env)
        _pid, status, usage = os.wait4(process.pid, 0)
        wall = time.perf_counter() - start
        errors.seek(0)
        stderr = errors.read()
        warnings = stderr.count(b": warning[")
        error_lines = [line for line in stderr.decode("utf-8", "replace").splitlines() if "error" in line][:5]
    lines = sum(1 for _ in source.open("rb"))
    return Run(
        kind,
        workers,
        lines,
        source.stat().st_size,
        wall,
        usage.ru_utime + usage.ru_stime,  # the workers' too: the CLI joins them
        usage.ru_maxrss,  # KB on Linux: the largest of the process and its workers
        output.stat().st_size if output.exists() else 0,
        warnings,
        os.waitstatus_to_exitcode(status),
        error_lines,
    )


def report(run: Run) -> None:
    print(
        f"{run.kind:>8} x{run.workers} {run.lines:>7} lines {run.input_bytes / 1e6:5.2f} MB: wall {run.wall_s:6.2f} s  "
        f"cpu {run.cpu_s:6.2f} s ({run.cpu_s / run.lines * 1e6:4.0f} us/line)  peak RSS {run.peak_rss_kb / 1024:6.1f} MB  "
        f"out {run.output_bytes / 1e6:6.1f} MB  warnings {run.warnings}  exit {run.exit_code}",
        flush=True,
    )
    if run.exit_code != 0:
        print(
            f"!!!!!!!! {run.kind} x{run.workers} {run.lines} lines EXITED {run.exit_code}: this run timed the error path, "
            "NOT a compile; its numbers mean nothing. First errors:",
            flush=True,
        )
        for line in run.errors or ["(no error line on stderr)"]:
            print(f"!!!!!!!!   {line}", flush=True)


def summarise(runs: list[Run]) -> None:
    """RSS per added line and time ratios, per kind and worker count."""
    for kind, workers in sorted({(r.kind, r.workers) for r in runs}):
        series = [r for r in runs if (r.kind, r.workers) == (kind, workers)]
        base = series[0]
        for run in series[1:]:
            per_line = (run.peak_rss_kb - base.peak_rss_kb) * 1024 / (run.lines - base.lines)
            print(
                f"{kind} x{workers}: RSS per line beyond {base.lines} lines, at {run.lines}: {per_line:,.0f} B (<= 2048)"
            )
        for before, after in zip(series, series[1:], strict=False):
            print(
                f"{kind} x{workers}: time({after.lines})/time({before.lines}): wall {after.wall_s / before.wall_s:.1f}, "
                f"cpu {after.cpu_s / before.cpu_s:.1f} (sizes {after.lines / before.lines:.0f}x; linear = the same)"
            )


# ---------------------------------------------------------------- phases and peers, in this process

PHASES = ("parse", "analysis", "boundary check", "IR build", "check", "JSON")


def phase_times(text: str) -> tuple[dict[str, float], int, list[dict[str, object]]]:
    """CPU seconds per phase of the one-process path over `text`, the number of materials, and
    their IR (for the JSON peer). The boundary check is the analysis's last passes (ranges.py)."""
    from cnlmc import analyze
    from cnlmc.api import cyclic_gc_paused, lexicon_for
    from cnlmc.document import iter_items
    from cnlmc.ir import json_text, material_ir
    from cnlmc.ir_check import check_material
    from cnlmc.params import Params
    from cnlmc.state import Context

    lexicon = lexicon_for()
    ctx = Context(lexicon, filename="bench.cnl")
    clock, spent = time.process_time, dict.fromkeys(PHASES, 0.0)
    convention = ctx.settings.get("alpha_convention", Params.alpha_convention)

    def timed_pass(step: Callable[..., object]) -> Callable[..., object]:
        def run(state: object, context: object) -> object:
            start = clock()
            try:
                return step(state, context)
            finally:
                spent["boundary check"] += clock() - start

        return run

    def timed_items(items: Iterator[object]) -> Iterator[object]:
        while True:
            start = clock()
            item = next(items, None)
            spent["parse"] += clock() - start
            if item is None:
                return
            yield item

    saved = analyze.FINAL_PASSES
    analyze.FINAL_PASSES = tuple(p if p is analyze.select_model else timed_pass(p) for p in saved)
    materials: list[dict[str, object]] = []
    diags: list[object] = []
    used: dict[str, int] = {}
    try:
        with cyclic_gc_paused():
            groups = analyze._material_groups(timed_items(iter_items(text, lexicon, diags)), diags)  # type: ignore[arg-type]
            for material, refinements in groups:
                start = clock()
                name = analyze.material_name(material, used)
                states = analyze.build_states(material, refinements, ctx, name, diags)  # type: ignore[arg-type]
                spent["analysis"] += clock() - start
                for state in states:
                    start = clock()
                    ir = material_ir(state, convention, lexicon.caches.rounded_optics)
                    middle = clock()
                    check_material(ir)
                    end = clock()
                    json_text(ir)
                    spent["IR build"] += middle - start
                    spent["check"] += end - middle
                    spent["JSON"] += clock() - end
                    materials.append(ir)
    finally:
        analyze.FINAL_PASSES = saved
    spent["analysis"] -= spent["boundary check"]
    return spent, len(materials), materials


def previous_json_text(value: object, encoder: json.JSONEncoder) -> str:
    """The IR's JSON text function before this change: `encoder` with its circular-reference check
    (made once by the caller), a regular expression over every text."""
    from cnlmc.ir import _UNSAFE_ON_TERMINAL, _escaped

    text = encoder.encode(value)
    if _UNSAFE_ON_TERMINAL.search(text) is None:
        return text
    return _UNSAFE_ON_TERMINAL.sub(_escaped, text)


def peer_run(text: str, workers: int) -> tuple[float, float, bytes]:
    """Wall and CPU seconds (this process and its workers) of compile_stream + the IR writer."""
    import resource

    from cnlmc.api import compile_stream, cyclic_gc_paused, lexicon_for
    from cnlmc.backends.ir_json import IrWriter

    def cpu() -> float:
        own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
        return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime

    wall, used = time.perf_counter(), cpu()
    with cyclic_gc_paused():
        stream = compile_stream(text, "bench.cnl", lexicon_for(), workers=workers)
        out = io.BytesIO()
        writer = IrWriter(out, stream.head, check=True)
        for material in stream.materials:
            writer.write(material)
        writer.finish([d.to_json() for d in stream.sorted_diagnostics()])
    return time.perf_counter() - wall, cpu() - used, out.getvalue()


def typing_peer(materials: list[dict[str, object]]) -> None:
    """The IR writer's check: Material.from_ir (what it called before: typed records built and let
    go) against cnlmc.ir_check.check_material (the same verdicts, no records)."""
    from cnlmc.ir_check import check_material
    from cnlmc.material import Material

    start = time.process_time()
    for material in materials:
        Material.from_ir(material)
    middle = time.process_time()
    for material in materials:
        check_material(material)
    end = time.process_time()
    print(
        f"  peer, the writer's check: Material.from_ir {(middle - start) / len(materials) * 1e6:.1f} us, "
        f"ir_check {(end - middle) / len(materials) * 1e6:.1f} us per material "
        f"(ratio {(middle - start) / max(1e-9, end - middle):.1f}x)"
    )


def phases_and_peers(lines: int, pool: list[str], folder: Path) -> None:
    from cnlmc.ir import _plain, json_text

    source = folder / "phases.cnl"
    for kind in ("cycled", "distinct"):
        write_source(source, lines, phrase_source(kind, lines, pool))
        text = source.read_text(encoding="utf-8")
        phase_times(text)  # warm: the tagger's memo, the lexicon's caches
        spent, count, materials = phase_times(text)
        cells = "  ".join(f"{phase} {spent[phase] / lines * 1e6:4.0f}" for phase in PHASES)
        print(f"{kind} {lines} lines, CPU us per line: {cells}  (total {sum(spent.values()):.2f} s, {count} materials)")
        start = time.process_time()
        encoder = json.JSONEncoder(ensure_ascii=False, default=_plain)  # as the previous code had it
        old = [previous_json_text(m, encoder) for m in materials]
        middle = time.process_time()
        start_new = time.process_time()
        same = [json_text(m) for m in materials] == old
        end = time.process_time()
        print(
            f"  peer, JSON text: previous {middle - start:.3f} s, now {end - start_new:.3f} s "
            f"(ratio {(middle - start) / max(1e-9, end - start_new):.2f}x, same text: {same})"
        )
        typing_peer(materials)
        one, two = peer_run(text, 1), peer_run(text, 2)
        print(
            f"  peer, one process (previous path) vs two: wall {one[0]:.2f} s -> {two[0]:.2f} s "
            f"({one[0] / two[0]:.2f}x), cpu {one[1]:.2f} s -> {two[1]:.2f} s, same bytes: {one[2] == two[2]}"
        )


def write_in_a_process(kind: str, size: int, path: Path) -> None:
    """The source written by another process: this one stays small, so that the compiles it starts
    measure their own peak RSS (Linux keeps a process's peak RSS across exec, and a child started
    by vfork begins with its parent's)."""
    subprocess.run([sys.executable, __file__, "--write", kind, str(size), str(path)], check=True)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10_000, 100_000])
    parser.add_argument("--kinds", nargs="+", choices=("cycled", "distinct"), default=["cycled", "distinct"])
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--phases", type=int, default=0, metavar="LINES", help="phases and peers at this size")
    parser.add_argument("--write", nargs=3, metavar=("KIND", "LINES", "PATH"), help=argparse.SUPPRESS)
    parser.add_argument("--phases-only", type=int, default=0, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.write:
        kind, size, path = args.write[0], int(args.write[1]), Path(args.write[2])
        write_source(path, size, phrase_source(kind, size, phrase_pool() if kind == "cycled" else []))
        return 0
    if args.phases_only:
        with tempfile.TemporaryDirectory() as folder:
            phases_and_peers(args.phases_only, phrase_pool(), Path(folder))
        return 0
    print(f"load average at the start: {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs", flush=True)
    if args.phases:
        subprocess.run([sys.executable, __file__, "--phases-only", str(args.phases)], check=True)
    runs = []
    with tempfile.TemporaryDirectory() as folder:
        for kind in args.kinds:
            for size in sorted(args.sizes):
                source = Path(folder) / f"{kind}{size}.cnl"
                write_in_a_process(kind, size, source)
                for workers in args.workers:
                    run = compile_once(kind, workers, source, Path(folder) / f"{kind}{size}x{workers}.ir.json")
                    runs.append(run)
                    report(run)
    summarise(runs)
    print(f"load average at the end: {os.getloadavg()[0]:.2f}")
    failed = [run for run in runs if run.exit_code != 0]
    for run in failed:
        print(f"!!!!!!!! FAILED: {run.kind} x{run.workers} {run.lines} lines exited {run.exit_code} (see above)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
