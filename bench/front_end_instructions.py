"""Instructions per phrase and per line of the language front end, counted by callgrind (#13, #14).

Run: .venv/bin/python bench/front_end_instructions.py [--phrases 4] [--lines 1000] [--source FILE]
Needs valgrind. A count of instructions does not depend on the load, so a change can be judged on
a busy machine (a time cannot). Two workloads, each in a child process under
`valgrind --tool=callgrind --collect-atstart=no --toggle-collect=functools_reduce`, so only the
work done inside one functools.reduce call is counted (not the start, the imports, the lexicon):
- phrases: bench/language_bench.py's PHRASES compiled with compile_source, --phrases rounds of
  them after two warm rounds (what the phrase -> IR bench times);
- lines: --lines distinct lines (bench/scale_bench.py's `distinct` kind, or --source) compiled in
  one process by compile_stream and written by the IR writer with its check (what each worker
  of `cnlmc compile` does), after the same lines once to warm the tagger's memo.
PYTHONHASHSEED is fixed so that two runs of the same code count within about 0.05 %.
Compare two versions of the code by running this in each checkout (or with PYTHONPATH pointing
at a copy of the package) and reading the per-unit counts.
"""

from __future__ import annotations

import argparse
import functools
import io
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent


def phrases_workload(rounds: int) -> None:
    sys.path.insert(0, str(HERE))
    from language_bench import PHRASES

    from cnlmc.api import compile_source, lexicon_for

    lexicon = lexicon_for()
    for _ in range(2):
        for phrase in PHRASES:
            compile_source(phrase, "bench", lexicon)
    work = [phrase for _ in range(rounds) for phrase in PHRASES]
    functools.reduce(lambda _acc, phrase: compile_source(phrase, "bench", lexicon), work, None)


def lines_workload(source: Path) -> None:
    from cnlmc.api import compile_stream, cyclic_gc_paused, lexicon_for
    from cnlmc.backends.ir_json import IrWriter

    lexicon = lexicon_for()
    text = source.read_text(encoding="utf-8")

    def run(_acc: object, text: str) -> bytes:
        with cyclic_gc_paused():
            stream = compile_stream(text, "bench.cnl", lexicon, workers=1)
            out = io.BytesIO()
            writer = IrWriter(out, stream.head, check=True)
            for material in stream.materials:
                writer.write(material)
            writer.finish([d.to_json() for d in stream.sorted_diagnostics()])
        return out.getvalue()

    run(None, text)  # warm: the tagger's memo and the lexicon's caches, as in a long file
    functools.reduce(run, [text], None)


def counted(args: list[str]) -> int:
    """Instructions inside functools.reduce of this script run with `args` under callgrind."""
    with tempfile.TemporaryDirectory() as folder:
        command = [
            "valgrind",
            "--tool=callgrind",
            "--collect-atstart=no",
            "--toggle-collect=functools_reduce",
            f"--callgrind-out-file={Path(folder) / 'out'}",
            sys.executable,
            __file__,
            *args,
        ]
        env = {**os.environ, "PYTHONHASHSEED": "0"}
        done = subprocess.run(command, capture_output=True, text=True, env=env, check=True)
    found = re.search(r"Collected : (\d+)", done.stderr)
    if found is None:
        raise RuntimeError(f"callgrind printed no count:\n{done.stderr[-2000:]}")
    return int(found.group(1))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--phrases", type=int, default=4, help="rounds of the 15 bench phrases")
    parser.add_argument("--lines", type=int, default=1000, help="distinct lines (scale_bench's kind)")
    parser.add_argument("--source", type=Path, help="a .cnl file to use instead of --lines distinct lines")
    parser.add_argument("--workload", choices=("phrases", "lines"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.workload == "phrases":
        phrases_workload(args.phrases)
        return 0
    if args.workload == "lines":
        lines_workload(args.source)
        return 0
    if shutil.which("valgrind") is None:
        print("valgrind is not installed: no instruction counts", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory() as folder:
        source = args.source
        if source is None:
            source = Path(folder) / "distinct.cnl"
            subprocess.run(
                [sys.executable, str(HERE / "scale_bench.py"), "--write", "distinct", str(args.lines), str(source)],
                check=True,
            )
        lines = sum(1 for _ in source.open("rb"))
        phrases = counted(["--workload", "phrases", "--phrases", str(args.phrases)])
        per_line = counted(["--workload", "lines", "--source", str(source)])
    count = args.phrases * 15
    print(f"phrase -> IR (compile_source): {phrases / count:,.0f} instructions a phrase ({count} phrases)")
    print(f"lines -> IR text, checked (one process): {per_line / lines:,.0f} instructions a line ({lines} lines)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
