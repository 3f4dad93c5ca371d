"""Phrase -> IR now against the first wave's compiler, on this machine, in alternating processes.

Issue #14 asks that the second wave's larger lexicon and language "not slow the hot path". The
first wave's numbers in the README came from other machines; this bench measures the question
itself: it checks out the first wave's last commit (03a1175, before the second wave's first change)
into a temporary git worktree, makes it importable as `cnlmc` (a folder of links laid out as its
pyproject's package-dir says), and times the same phrases through `cnlmc.api.compile_source` in
both, each in its own process, alternating, with lark's raw-text parse timed in every process as
the common peer. CPU time (time.process_time) of each call; medians over the rounds.

    .venv/bin/python bench/front_end_vs_first_wave.py            # 5 rounds each
    .venv/bin/python bench/front_end_vs_first_wave.py --rounds 3 --rev 03a1175
    .venv/bin/python bench/front_end_vs_first_wave.py --instructions   # callgrind too (valgrind)

Prints per process kind: the median CPU per phrase -> IR, lark's raw parse in the same processes,
their ratio, and the ratio now / first wave. With --instructions, valgrind's instruction counts of
the same work (load-independent).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FIRST_WAVE = "03a1175"
PACKAGE_DIRS = {"grammar": "grammar", "backends": "backends", "stdlib": "stdlib"}  # cnlmc.X -> folder

# One process's work: compile each phrase REPEAT times (after a warm-up), lark's raw parse too;
# prints the CPU seconds of every call as JSON. Runs against whichever `cnlmc` is first on the path.
WORKER = r"""
import json, sys, time
from lark import Lark
from cnlmc.api import compile_source, lexicon_for
phrases, repeat = json.loads(sys.argv[1]), int(sys.argv[2])
raw = Lark(r'''
start: item+
item: WORD | ","
WORD: /[^\W\d_][\w'-]*/
%ignore /\s+/
''', parser="lalr")
lexicon = lexicon_for()
def cpu(fn):
    out = []
    for _ in range(repeat):
        c = time.process_time()
        fn()
        out.append(time.process_time() - c)
    return out
compile_cpu, raw_cpu = [], []
for phrase in phrases:
    compile_source(phrase, "bench", lexicon)
    raw.parse(phrase)
    compile_cpu += cpu(lambda: compile_source(phrase, "bench", lexicon))
    raw_cpu += cpu(lambda: raw.parse(phrase))
print(json.dumps({"compile": compile_cpu, "raw": raw_cpu}))
"""


def phrases() -> list[str]:
    sys.path.insert(0, str(ROOT / "bench"))
    from language_bench import PHRASES  # the same phrases as the README's phrase -> IR row

    return list(PHRASES)


def first_wave_package(rev: str, work: Path) -> Path:
    """A folder whose `cnlmc` is the compiler at `rev` (a detached worktree plus links)."""
    tree = work / "tree"
    subprocess.run(
        ["git", "-C", str(ROOT), "worktree", "add", "--detach", "-f", str(tree), rev], check=True, capture_output=True
    )
    package = work / "path" / "cnlmc"
    package.mkdir(parents=True)
    for item in (tree / "compiler").iterdir():
        (package / item.name).symlink_to(item)
    for name, folder in PACKAGE_DIRS.items():
        (package / name).symlink_to(tree / folder)
    return work / "path"


def run_worker(python_path: str | None, texts: list[str], repeat: int, tool: list[str] | None = None) -> dict:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    if python_path:
        env["PYTHONPATH"] = python_path
    command = [*(tool or []), sys.executable, "-c", WORKER, json.dumps(texts), str(repeat)]
    done = subprocess.run(command, check=True, capture_output=True, text=True, env=env, cwd=tempfile.gettempdir())
    return {"out": json.loads(done.stdout.strip().splitlines()[-1]), "err": done.stderr}


def instructions(python_path: str | None, texts: list[str], repeat: int, work: Path) -> int:
    """valgrind --tool=callgrind's total instructions of the worker (start-up included)."""
    out = work / f"callgrind.{'old' if python_path else 'new'}.{repeat}"
    run_worker(python_path, texts, repeat, ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}"])
    summary = next(line for line in out.read_text().splitlines() if line.startswith("summary:"))
    return int(summary.split()[1])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rev", default=FIRST_WAVE, help="the first wave's commit (default %(default)s)")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--repeat", type=int, default=200, help="calls per phrase per process")
    ap.add_argument("--instructions", action="store_true", help="count instructions with callgrind too")
    args = ap.parse_args()
    texts = phrases()
    print(f"load average at the start: {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs; {len(texts)} phrases")
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        try:
            old_path = str(first_wave_package(args.rev, work))
            report(args, texts, old_path, work)
        finally:
            subprocess.run(
                ["git", "-C", str(ROOT), "worktree", "remove", "--force", str(work / "tree")], capture_output=True
            )


def report(args: argparse.Namespace, texts: list[str], old_path: str, work: Path) -> None:
    medians: dict[str, dict[str, list[float]]] = {
        "first wave": {"compile": [], "raw": []},
        "now": {"compile": [], "raw": []},
    }
    for _ in range(args.rounds):
        for label, path in (("first wave", old_path), ("now", None)):
            out = run_worker(path, texts, args.repeat)["out"]
            for key in ("compile", "raw"):
                medians[label][key].append(statistics.median(out[key]))
    print(f"{'':<12}{'phrase -> IR':>14}{'lark raw parse':>16}{'ratio':>8}   (CPU, median of {args.rounds} processes)")
    own = {}
    for label, m in medians.items():
        c, r = statistics.median(m["compile"]), statistics.median(m["raw"])
        own[label] = c
        print(f"{label:<12}{c * 1e6:>12.1f}us{r * 1e6:>14.1f}us{c / r:>7.2f}x")
    print(
        f"now / first wave (phrase -> IR CPU): {own['now'] / own['first wave']:.2f}x   "
        f"load average now: {os.getloadavg()[0]:.2f}"
    )
    if args.instructions:
        counts = {}
        for label, path in (("first wave", old_path), ("now", None)):
            few, many = instructions(path, texts, 5, work), instructions(path, texts, 105, work)
            counts[label] = (many - few) / (100 * len(texts))
        print(
            f"instructions a phrase (callgrind, 100 extra calls each): first wave {counts['first wave']:,.0f}, "
            f"now {counts['now']:,.0f}: {counts['now'] / counts['first wave']:.2f}x"
        )


if __name__ == "__main__":
    main()
