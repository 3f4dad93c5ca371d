"""`cnlmc preview FILE -o preview.png [--interactive]`: the preview's CLI subcommand (a
cnlmc.backends.base.Command the registry lists), and the render flags `cnlmc ar` shares."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from cnlmc.api import Result
from cnlmc.commands import (
    EXIT_ERRORS,
    EXIT_OK,
    add_option_argument,
    add_source_arguments,
    compile_reported,
    lexicon_of,
    option_pairs,
    read_source,
    say_wrote,
)
from cnlmc.errors import UsageError
from cnlmc.output import destination

from ..base import Command
from ..registry import BUILTIN_COMMANDS
from . import live
from .frames import preview_command
from .meshes import MESH_FORMATS, mesh_choices
from .window import Window

#: options that have a flag of their own (--mesh, --size, ...) besides --option KEY=VALUE
RENDER_FLAGS = ("mesh", "size", "tier", "budget_ms", "env")


def add_render_arguments(parser: argparse.ArgumentParser, size: bool = True) -> None:
    """The render flags; `size`: whether the image size is one (AR renders at the photo's size)."""
    parser.add_argument("--mesh", help=f"{mesh_choices()}, or an {MESH_FORMATS} file")
    if size:
        parser.add_argument("--size", help="image size in pixels (preview default 512)")
    parser.add_argument("--tier", help="quality tier: analytic, splitsum, fisN, mcN (see docs/preview.md)")
    parser.add_argument("--budget-ms", dest="budget_ms", help="pick the best tier whose frame time fits")
    parser.add_argument("--env", help="studio, sky, sun, or an .hdr/.exr environment")
    add_option_argument(parser, "any other render option")


def render_options(args: argparse.Namespace) -> dict[str, str]:
    """The raw option pairs of the command line: --option KEY=VALUE, the render flags, --seed."""
    options = option_pairs(args.option)
    for flag in RENDER_FLAGS:
        if getattr(args, flag, None) is not None:
            options[flag] = getattr(args, flag)
    options["seed"] = str(args.seed)
    return options


def compiled_or_none(source: str, name: str, args: argparse.Namespace) -> Result | None:
    """The compiled source (its diagnostics reported), or None when it has errors."""
    result = compile_reported(source, name, args)
    if not result.ok:
        return None
    if not result.materials:
        raise UsageError(f"{name}: no material to render")
    return result


class PreviewCommand(Command):
    name = "preview"
    help = BUILTIN_COMMANDS[name].help

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        add_source_arguments(parser)
        parser.add_argument("-o", "--output", default="preview.png", help="output PNG (default preview.png)")
        parser.add_argument(
            "-i",
            "--interactive",
            action="store_true",
            help="then read refinements (darker, less grain, ...) at a prompt and re-render after each",
        )
        add_render_arguments(parser)

    def run(self, args: argparse.Namespace) -> int:
        source, name = read_source(args.file, args.max_bytes)
        result = compiled_or_none(source, name, args)
        if result is None:
            return EXIT_ERRORS
        if args.interactive:
            return self.live(source, args)
        try:
            report = preview_command(result.document, args.output, render_options(args), protect=[args.file])
        except (ValueError, OSError, RuntimeError) as exc:
            raise UsageError(str(exc)) from None
        for note in report.notes:
            print(f"note: {note}", file=sys.stderr)
        say_wrote(report.path)
        return EXIT_OK

    def live(self, source: str, args: argparse.Namespace) -> int:
        if args.file == "-":
            raise UsageError("--interactive reads refinements from standard input: give the material as a file")
        destination(args.output, protect=[args.file])  # never over the material file it re-reads
        try:
            session = live.LiveSession(source, Path(args.output), render_options(args), lexicon_of(args))
            code: int = live.run(session, window=Window.open())
            return code
        except (ValueError, OSError, RuntimeError) as exc:
            raise UsageError(str(exc)) from None
        except KeyboardInterrupt:
            return EXIT_OK
