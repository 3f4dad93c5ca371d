"""Cold `cnlmc compile`: a fresh process per run, as a user's shell starts it, next to peer
processes on the same machine at the same time (#14: cold CLI within the README's numbers).

    .venv/bin/python bench/cold_start.py [--runs 15]

Each round runs every command once (so all see the same load): the cold compiles of one phrase
(`echo "white varnished oak" | cnlmc compile -`) and of a file of 5 lines, to IR on stdout and to
the glsl target ("glossy red plastic" on stdout; the oak -o a folder: its maps are PNG files), and the peers `python -c pass` and
`python -c "import json"`, `python -I -c pass`, `python -S -c pass` (no site: no .pth files of
the editable install) and `python -m cnlmc` (runpy) instead of the console script. Bytecode is
written and the cache (lexicon, graph tables, parse shapes) is warm: a first run of each command
fills a cache folder of this bench's own. Printed: wall and CPU (user + sys, rusage) medians and
minima, the ratio to `python -c pass`, and the load average before and after.

The breakdown runs the CLI's main() in a fresh process with timers around its phases:
interpreter (from the spawn to the first line of the script: start-up, site, .pth files),
imports (cnlmc.cli and cnlmc.commands, what main() imports), arguments (argparse), lexicon (from the disk cache),
compile (everything the command does but the two others), write (the copy of the spooled IR to
stdout, or `deliver`: importing cnlmc.output and writing the files), exit (from main's return to the process's end).
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CNLMC = str(Path(sys.executable).with_name("cnlmc"))
PHRASE = "white varnished oak\n"
NO_MAPS = "glossy red plastic\n"  # the glsl target prints it on stdout (the oak's maps are PNG files: -o)
FIVE_LINES = (
    "white varnished oak\n"
    "lightly brushed, blue anodized aluminum\n"
    "dark grey plastic with a glossy clear coat\n"
    "rough concrete\n"
    "glossy red plastic\n"
)
PHASES = ("interpreter", "imports", "arguments", "lexicon", "compile", "write", "exit")

#: Runs main() with timers; argv[1] is the parent's perf_counter at the spawn (CLOCK_MONOTONIC:
#: one clock for every process), argv[2] where to write the child's timestamps, the rest main's argv.
CHILD = r"""
import sys, time
first = time.perf_counter()
spawned, report, argv = float(sys.argv[1]), sys.argv[2], sys.argv[3:]
marks = {"first": first}
import cnlmc.cli as cli
from cnlmc import commands  # what main() imports first: the compile path's modules
marks["imported"] = time.perf_counter()
spent = {"lexicon": 0.0, "write": 0.0}
def timed(owner, name, phase):
    inner = getattr(owner, name)
    def wrapper(*args, **kwargs):
        start = time.perf_counter()
        try:
            return inner(*args, **kwargs)
        finally:
            spent[phase] += time.perf_counter() - start
    setattr(owner, name, wrapper)
timed(commands, "lexicon_of", "lexicon")
timed(commands.Spool, "copy_to", "write")
timed(commands, "deliver", "write")
parse = cli.build_parser
def build_parser(arguments):
    parser = parse(arguments)
    inner = parser.parse_args
    def parse_args(args=None):
        parsed = inner(args)
        marks["parsed"] = time.perf_counter()
        return parsed
    parser.parse_args = parse_args
    return parser
cli.build_parser = build_parser
marks["main"] = time.perf_counter()
code = cli.main(argv)
marks["returned"] = time.perf_counter()
with open(report, "w") as out:
    out.write(repr({"spawned": spawned, "code": code, **marks, **spent}))
"""


def run(command: Sequence[str], stdin: str, env: dict[str, str]) -> tuple[float, float]:
    """(wall, CPU) seconds of one process."""
    start = time.perf_counter()
    process = subprocess.Popen(
        command, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env
    )
    assert process.stdin is not None
    process.stdin.write(stdin.encode())
    process.stdin.close()
    _pid, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"failed: {' '.join(command)}")
    return wall, usage.ru_utime + usage.ru_stime


def breakdown(argv: Sequence[str], stdin: str, env: dict[str, str], folder: Path) -> dict[str, float]:
    """One run's phases in seconds (see the module's doc)."""
    report = folder / "phases.txt"
    spawned = time.perf_counter()
    process = subprocess.Popen(
        [sys.executable, "-c", CHILD, repr(spawned), str(report), *argv],
        stdin=subprocess.PIPE,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        env=env,
    )
    assert process.stdin is not None
    process.stdin.write(stdin.encode())
    process.stdin.close()
    process.wait()
    ended = time.perf_counter()
    marks = eval(report.read_text())  # our own child's dict of numbers
    assert marks["code"] == 0, "the timed compile failed"
    handler = marks["returned"] - marks["parsed"]
    return {
        "interpreter": marks["first"] - spawned,
        "imports": marks["imported"] - marks["first"],
        "arguments": marks["parsed"] - marks["main"],
        "lexicon": marks["lexicon"],
        "compile": handler - marks["lexicon"] - marks["write"],
        "write": marks["write"],
        "exit": ended - marks["returned"],
    }


def ms(seconds: float) -> str:
    return f"{seconds * 1e3:7.1f}"


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    options.add_argument("--runs", type=int, default=15, help="rounds (default 15)")
    runs = options.parse_args().runs
    print(f"load average at the start: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    with tempfile.TemporaryDirectory() as home:
        folder = Path(home)
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "CNLMC_NO_CACHE")}
        env["XDG_CACHE_HOME"] = str(folder / "cache")
        five = folder / "five.cnl"
        five.write_text(FIVE_LINES)
        out = str(folder / "out")
        python = sys.executable
        commands: dict[str, tuple[list[str], str]] = {
            "cnlmc compile - (1 phrase, IR)": ([CNLMC, "compile", "-"], PHRASE),
            "cnlmc compile five.cnl (IR)": ([CNLMC, "compile", str(five)], ""),
            "cnlmc compile - --target glsl (no maps)": ([CNLMC, "compile", "-", "--target", "glsl"], NO_MAPS),
            "cnlmc compile - --target glsl -o": ([CNLMC, "compile", "-", "--target", "glsl", "-o", out], PHRASE),
            "cnlmc compile five.cnl --target glsl -o": (
                [CNLMC, "compile", str(five), "--target", "glsl", "-o", out],
                "",
            ),
            "python -m cnlmc compile - (runpy)": ([python, "-m", "cnlmc", "compile", "-"], PHRASE),
            "peer: python -c pass": ([python, "-c", "pass"], ""),
            'peer: python -c "import json"': ([python, "-c", "import json"], ""),
            "peer: python -I -c pass": ([python, "-I", "-c", "pass"], ""),
            "peer: python -S -c pass (no site)": ([python, "-S", "-c", "pass"], ""),
        }
        for command, stdin in commands.values():  # bytecode and caches written
            run(command, stdin, env)
        times: dict[str, list[tuple[float, float]]] = {label: [] for label in commands}
        for _ in range(runs):
            for label, (command, stdin) in commands.items():
                times[label].append(run(command, stdin, env))
        peer = statistics.median(w for w, _c in times["peer: python -c pass"])
        peer_cpu = statistics.median(c for _w, c in times["peer: python -c pass"])
        print(
            f"\n{'median of ' + str(runs) + ' runs (ms)':<44}{'wall':>8}{'min':>8}{'CPU':>8}{'min':>8}  ratio to pass"
        )
        for label, pairs in times.items():
            wall, cpu = [w for w, _c in pairs], [c for _w, c in pairs]
            print(
                f"{label:<44}{ms(statistics.median(wall))} {ms(min(wall))} {ms(statistics.median(cpu))} "
                f"{ms(min(cpu))}  wall {statistics.median(wall) / peer:4.1f}x  CPU {statistics.median(cpu) / peer_cpu:4.1f}x"
            )
        print(f"\nbreakdown, median of {runs} runs (ms): " + "  ".join(f"{p:>11}" for p in PHASES) + "      sum")
        for label, argv, stdin in (
            ("compile - (IR)", ["compile", "-"], PHRASE),
            ("compile five.cnl (IR)", ["compile", str(five)], ""),
            ("compile - --target glsl (no maps)", ["compile", "-", "--target", "glsl"], NO_MAPS),
            ("compile - --target glsl -o", ["compile", "-", "--target", "glsl", "-o", out], PHRASE),
        ):
            rows = [breakdown(argv, stdin, env, folder) for _ in range(runs)]
            medians = {p: statistics.median(r[p] for r in rows) for p in PHASES}
            print(
                f"{label:<38}" + "  ".join(f"{ms(medians[p]):>11}" for p in PHASES) + f"  {ms(sum(medians.values()))}"
            )
    print(f"\nload average at the end: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
