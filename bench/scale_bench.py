"""Time, peak memory and output size of `cnlmc compile` on 1k / 10k / 100k-line files.

Run: .venv/bin/python bench/scale_bench.py [--sizes 1000 10000 100000]
Each size is a file of material phrases, one per line (about 35 bytes a line), drawn from 300
distinct stdlib phrases (see phrase_pool), most of them named, some followed by a refinement line; compiled
to IR in a fresh process (`python -m cnlmc compile FILE -o OUT`). Its wall and CPU time and its
peak RSS come from that process's own rusage (os.wait4). Printed: per size, then the RSS per
input line beyond the smallest size's (the goal is <= 2 KB) and time(largest)/time(previous)
against the size ratio (linear: the same).
"""

from __future__ import annotations

import argparse
import os
import random
import subprocess
import sys
import tempfile
import time
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


@dataclass
class Run:
    lines: int
    input_bytes: int
    wall_s: float
    cpu_s: float
    peak_rss_kb: int
    output_bytes: int
    exit_code: int


def write_source(path: Path, lines: int, pool: list[str], seed: int = 13) -> None:
    """`lines` lines: phrases drawn from the pool, most named (`m12: ...`), a fifth unnamed (their
    names come from the words, repeats numbered), and about one in seven followed by a refinement."""
    rng = random.Random(seed)
    with path.open("w", encoding="utf-8") as out:
        n = 0
        while n < lines:
            phrase = rng.choice(pool)
            out.write(f"m{n}: {phrase}\n" if rng.random() < 0.8 else f"{phrase}\n")
            n += 1
            if n < lines and rng.random() < 0.15:
                out.write(f"{rng.choice(REFINEMENTS)}\n")
                n += 1


def compile_once(source: Path, output: Path) -> Run:
    command = [sys.executable, "-m", "cnlmc", "compile", str(source), "-o", str(output), "--max-bytes", "1G"]
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _pid, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    lines = sum(1 for _ in source.open("rb"))
    return Run(
        lines,
        source.stat().st_size,
        wall,
        usage.ru_utime + usage.ru_stime,
        usage.ru_maxrss,  # KB on Linux
        output.stat().st_size if output.exists() else 0,
        process.returncode,
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1000, 10_000, 100_000])
    args = parser.parse_args()
    runs = []
    pool = phrase_pool()
    with tempfile.TemporaryDirectory() as folder:
        for size in sorted(args.sizes):
            source, output = Path(folder) / f"{size}.cnl", Path(folder) / f"{size}.ir.json"
            write_source(source, size, pool)
            run = compile_once(source, output)
            runs.append(run)
            print(
                f"{run.lines:>7} lines {run.input_bytes / 1e6:6.2f} MB in: wall {run.wall_s:7.2f} s  "
                f"cpu {run.cpu_s:7.2f} s  peak RSS {run.peak_rss_kb / 1024:8.1f} MB  "
                f"out {run.output_bytes / 1e6:7.1f} MB ({run.output_bytes / max(1, run.lines):,.0f} B/line)  "
                f"exit {run.exit_code}",
                flush=True,
            )
    base = runs[0]
    for run in runs[1:]:
        per_line = (run.peak_rss_kb - base.peak_rss_kb) * 1024 / (run.lines - base.lines)
        print(f"RSS per input line beyond the {base.lines}-line run, at {run.lines}: {per_line:,.0f} B (goal <= 2048)")
    for before, after in zip(runs, runs[1:], strict=False):
        print(
            f"time({after.lines})/time({before.lines}): wall {after.wall_s / before.wall_s:.1f}, "
            f"cpu {after.cpu_s / before.cpu_s:.1f} (sizes {after.lines / before.lines:.0f}x; linear = the same)"
        )
    return 0 if all(run.exit_code == 0 for run in runs) else 1


if __name__ == "__main__":
    sys.exit(main())
