"""`cnlmc build CATALOG -o OUT --target T[,T...]`: the command line of a batch build."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING, TextIO

from cnlmc.backends.registry import Command

from ..cli import FRONT_END_COMMANDS
from ..diagnostics import visible
from .modes import RESULT_MODES

if TYPE_CHECKING:
    from .builder import BuildReport, Done

EXIT_OK, EXIT_FAILED, EXIT_INTERRUPTED = 0, 1, 130  # 130: 128 + SIGINT, as the other commands


class BuildCommand(Command):
    name = "build"
    help = FRONT_END_COMMANDS[name].help

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        parser.add_argument("catalog", help="a catalogue: a .cnl file, or a folder of them (searched recursively)")
        parser.add_argument("-o", "--output", required=True, help="the output folder (one subfolder per material)")
        parser.add_argument("--target", "-t", required=True, help="targets, comma-separated: maps,preview,materialx")
        parser.add_argument("--size", type=_positive, help="image size of the targets that write images (pixels)")
        parser.add_argument("--jobs", "-j", type=_positive, help="worker processes (default: every CPU; 1: no pool)")
        parser.add_argument("--scheduler", metavar="tcp://HOST:PORT", help="run the tasks on this Dask cluster")
        parser.add_argument(
            "--results",
            choices=RESULT_MODES,
            default="return",
            help="with --scheduler: files come back to be written here (return), or the workers write them "
            "into -o, a folder they share (shared)",
        )
        parser.add_argument(
            "--option", action="append", default=[], metavar="[TARGET.]KEY=VALUE", help="a target option; may repeat"
        )
        parser.add_argument(
            "--lexicon", "-L", action="append", default=[], help="an overlay name or a lexicon folder; may repeat"
        )
        parser.add_argument("--seed", type=int, default=0, help="seed for procedural maps (default 0)")

    def run(self, args: argparse.Namespace) -> int:
        from .builder import MANIFEST_NAME, build_report  # the builder loads only when a build runs

        line = ProgressLine(sys.stderr) if sys.stderr.isatty() else None
        try:
            report = build_report(
                args.catalog,
                args.output,
                [t.strip() for t in args.target.split(",") if t.strip()],
                size=args.size,
                jobs=args.jobs,
                scheduler=args.scheduler,
                results=args.results,
                options=args.option,
                lexicon=args.lexicon,
                seed=args.seed,
                progress=line,
            )
        except KeyboardInterrupt:
            print(
                "cnlmc: build interrupted: the tasks that finished are kept, nothing is half-written; "
                "run the same command again to finish",
                file=sys.stderr,
            )
            return EXIT_INTERRUPTED
        finally:
            if line is not None:
                line.end()
        print_report(report, sys.stdout, sys.stderr)
        print(f"wrote {visible(args.output.rstrip('/') + '/' + MANIFEST_NAME, one_line=True)}", file=sys.stderr)
        return EXIT_OK if report.ok else EXIT_FAILED


def _positive(text: str) -> int:
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"expected a positive whole number, got '{text}'")
    return int(text)


class ProgressLine:
    """`build: 12/40 materials (30%, 36/120 tasks), ETA 8 s` on one terminal line, rewritten as
    tasks finish; the ETA from the rate of the tasks that ran (up-to-date ones cost nothing)."""

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream
        self.shown = False

    def __call__(self, done: Done) -> None:
        rate = done.ran / done.seconds if done.seconds > 0 else 0.0
        left = done.to_run - done.ran
        eta = "done" if left == 0 else f"ETA {left / rate:.0f} s" if rate > 0 else ""
        share = 100 * done.materials_done // max(done.materials, 1)
        self.stream.write(
            f"\rbuild: {done.materials_done}/{done.materials} materials ({share}%, "
            f"{done.tasks_done}/{done.tasks} tasks), {eta}\x1b[K"
        )
        self.stream.flush()
        self.shown = True

    def end(self) -> None:
        if self.shown:
            self.stream.write("\n")
            self.stream.flush()


def print_report(report: BuildReport, out: TextIO, err: TextIO) -> None:
    from .builder import FAILED, STATUSES

    """The catalogue's warnings and the failures on `err`; the table (one row per target) on `out`."""
    for warning in report.warnings:
        print(warning, file=err)
    for where, target, text in report.failures:
        print(visible(f"{where}: {target}: {text}" if target else text), file=err)
    targets = list(report.manifest.get("targets", {}))
    width = max([len("target"), *map(len, targets)])
    print(f"{'target':<{width}}  " + "  ".join(f"{s:>10}" for s in STATUSES), file=out)
    for target in [*targets, None]:
        counts = [report.count(status, target) for status in STATUSES]
        if target is None:
            counts[STATUSES.index(FAILED)] += len(report.manifest.get("failed", []))
        name = "all" if target is None else target
        print(f"{name:<{width}}  " + "  ".join(f"{c:>10}" for c in counts), file=out)
