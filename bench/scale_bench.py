"""Time, peak memory and output size of `cnlmc compile` on 1k / 10k / 100k-line files.

Run: .venv/bin/python bench/scale_bench.py [--sizes 1000 10000 100000]
Each size is a file of named material phrases, one per line (about 30 bytes a line), compiled
to IR in a fresh process (`python -m cnlmc compile FILE -o OUT`). Its wall and CPU time and its
peak RSS come from that process's own rusage (os.wait4). Printed: per size, then the RSS per
input line beyond the smallest size's (the goal is <= 2 KB) and time(largest)/time(previous)
against the size ratio (linear: the same).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

PHRASES = (
    "aluminum",
    "anodized aluminum",
    "blue anodized aluminum",
    "lightly brushed, blue anodized aluminum",
    "white varnished oak",
    "oak with a glossy white varnish",
    "red or blue anodized aluminum",
    "heavily rusted iron",
    "polished white marble",
    "matte black rubber",
    "gold plated steel",
    "brushed and anodized titanium",
    "frosted glass",
    "deep red velvet",
    "metallic red car paint",
)


@dataclass
class Run:
    lines: int
    input_bytes: int
    wall_s: float
    cpu_s: float
    peak_rss_kb: int
    output_bytes: int
    exit_code: int


def write_source(path: Path, lines: int) -> None:
    with path.open("w", encoding="utf-8") as out:
        for n in range(lines):
            out.write(f"m{n}: {PHRASES[n % len(PHRASES)]}\n")


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
    with tempfile.TemporaryDirectory() as folder:
        for size in sorted(args.sizes):
            source, output = Path(folder) / f"{size}.cnl", Path(folder) / f"{size}.ir.json"
            write_source(source, size)
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
