"""Phrase -> IR latency in-process, next to lark's raw parse of the same phrase, and the cold CLI.

Run: .venv/bin/python bench/language_bench.py
Prints median and p99 per stage and phrases/s, and the cold CLI's wall and CPU time with the
parse shapes stored by an earlier run and without (cnlmc.shape_store). The peer is lark's own LALR parse of the
phrase text with its own lexer (what a lark user would write); lark's parse of our
already-tagged tokens is printed too (the floor for any parser built on lark).

Each phrase is compiled many times in a row, so after the first time its terminal sequence's
parse shape is cached (parser.parse_line_shape: keyed by the words' tags, never by the text);
the line "shape cache cleared" shows the cost when the parser has to run every time.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

from cnlmc.api import compile_source, lexicon_for
from cnlmc.parser import _token, lark_parser, parse_tagged
from cnlmc.tagger import Tagger

PHRASES = [
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
]


RAW_GRAMMAR = r"""
start: item+
item: WORD | ","
WORD: /[^\W\d_][\w'-]*/
%ignore /\s+/
"""


def raw_text_parser():
    """lark parsing the phrase text itself with its own lexer: the peer a lark user would write."""
    from lark import Lark

    return Lark(RAW_GRAMMAR, parser="lalr")


def timed(fn, repeat: int, cpu: list[float] | None = None) -> list[float]:
    """Wall seconds of each call; with `cpu`, each call's CPU seconds (time.process_time) appended
    to it (what to compare on a busy machine: a wall time includes the waits for a CPU)."""
    out = []
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        fn()
        out.append(time.perf_counter() - t)
        if cpu is not None:
            cpu.append(time.process_time() - c)
    return out


def p99(xs):
    return sorted(xs)[int(0.99 * (len(xs) - 1))]


def in_process(repeat: int = 300) -> dict:
    lexicon = lexicon_for()
    tagger, parser, raw = Tagger(lexicon), lark_parser(), raw_text_parser()
    shapes = lexicon.caches.shapes
    compile_times, parse_times, raw_times, unshaped_times = [], [], [], []
    compile_cpu: list[float] = []
    raw_cpu: list[float] = []
    for phrase in PHRASES:
        compile_source(phrase, "bench", lexicon)  # warm caches
        tagged, _ = tagger.tag_line(phrase, 1, 0)
        _tree, chosen = parse_tagged(tagged)
        tokens = [_token(t, chosen[t.span.start].tag) for t in tagged]
        compile_times += timed(lambda: compile_source(phrase, "bench", lexicon), repeat, compile_cpu)
        parse_times += timed(lambda: parser.parse(tokens), repeat)
        raw_times += timed(lambda: raw.parse(phrase), repeat, raw_cpu)
        shapes.persistent = False  # cleared means parsed again, not recalled from the stored shapes
        unshaped_times += timed(lambda: (shapes.clear(), compile_source(phrase, "bench", lexicon)), repeat // 4)
        shapes.persistent = True
    return {
        "compile": compile_times,
        "parse": parse_times,
        "raw": raw_times,
        "unshaped": unshaped_times,
        "compile cpu": compile_cpu,
        "raw cpu": raw_cpu,
    }


def cold_cli(runs: int = 7) -> dict[str, list[tuple[float, float]]]:
    """A new process per run, as a user's shell starts it: bytecode cached (as pip installs do),
    lexicon, grammar tables and parse shapes cached after the first run (in a cache folder of its
    own). Each run is paired with one whose stored parse shapes were deleted first (the peer: the
    previous start, which imports lark and loads the LALR tables). (wall, CPU) seconds per run;
    CPU (user + sys, from the process's rusage) is what to compare on a busy machine."""
    import tempfile

    example = Path(__file__).resolve().parents[1] / "examples" / "anodized.cnl"
    command = [sys.executable, "-m", "cnlmc", "compile", str(example), "--target", "ir"]
    out: dict[str, list[tuple[float, float]]] = {"stored shapes": [], "no stored shapes": []}
    with tempfile.TemporaryDirectory() as home:
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "CNLMC_NO_CACHE")}
        env["XDG_CACHE_HOME"] = home
        subprocess.run(command, check=True, capture_output=True, env=env)  # writes bytecode and caches
        for _ in range(runs):
            out["stored shapes"].append(_timed_run(command, env))
            for stored in Path(home, "cnlmc").glob("shapes-*"):
                stored.unlink()
            out["no stored shapes"].append(_timed_run(command, env))
    return out


def _timed_run(command: list[str], env: dict[str, str]) -> tuple[float, float]:
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    _pid, status, usage = os.wait4(process.pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0, "the cold compile failed"
    return time.perf_counter() - start, usage.ru_utime + usage.ru_stime


def main() -> None:
    print(f"load average at the start: {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs")
    stats = in_process()
    med_c, med_p = statistics.median(stats["compile"]), statistics.median(stats["parse"])
    print(f"{'stage':<32}{'median':>12}{'p99':>12}")
    print(f"{'phrase -> IR (cnlmc)':<32}{med_c * 1e6:>10.1f}us{p99(stats['compile']) * 1e6:>10.1f}us")
    unshaped = stats["unshaped"]
    print(
        f"{'  shape cache cleared each time':<32}{statistics.median(unshaped) * 1e6:>10.1f}us"
        f"{p99(unshaped) * 1e6:>10.1f}us"
    )
    print(f"{'lark LALR parse of the tokens':<32}{med_p * 1e6:>10.1f}us{p99(stats['parse']) * 1e6:>10.1f}us")
    med_r = statistics.median(stats["raw"])
    print(f"{'lark LALR parse of the raw text':<32}{med_r * 1e6:>10.1f}us{p99(stats['raw']) * 1e6:>10.1f}us")
    print(
        f"ratio phrase->IR / lark raw-text parse: {med_c / med_r:.2f}x   "
        f"/ parse of tagged tokens: {med_c / med_p:.2f}x   phrases/s: {1 / med_c:,.0f}"
    )
    cpu_c, cpu_r = statistics.median(stats["compile cpu"]), statistics.median(stats["raw cpu"])
    print(
        f"CPU time (process_time, the same calls): phrase -> IR median {cpu_c * 1e6:.1f}us, lark raw-text parse "
        f"{cpu_r * 1e6:.1f}us: ratio {cpu_c / cpu_r:.2f}x   load average now: {os.getloadavg()[0]:.2f}"
    )
    cold = cold_cli()
    for label, runs in cold.items():
        wall, cpu = [w for w, _c in runs], [c for _w, c in runs]
        print(
            f"cold `cnlmc compile --target ir`, {label}: wall median {statistics.median(wall) * 1e3:.0f} ms "
            f"(min {min(wall) * 1e3:.0f}), CPU median {statistics.median(cpu) * 1e3:.0f} ms "
            f"(min {min(cpu) * 1e3:.0f}) over {len(runs)} runs"
        )
    ratio = statistics.median(c for _w, c in cold["stored shapes"]) / statistics.median(
        c for _w, c in cold["no stored shapes"]
    )
    print(f"ratio CPU stored / not stored: {ratio:.2f}x   load average now: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
