"""`cnlmc preview` and `cnlmc ar`: a thin adapter over the preview and AR packages.

Package C moves these commands into backends/preview and backends/ar (then the registry's
BUILTIN_COMMANDS points there and this module goes). The preview module itself is light (it
loads moderngl when it renders); AR loads OpenCV on import, so it is imported when `cnlmc ar` runs.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from types import ModuleType
from typing import Any

from cnlmc.api import Result
from cnlmc.commands import (
    EXIT_ERRORS,
    EXIT_OK,
    add_lexicon_arguments,
    add_option_argument,
    add_source_arguments,
    compile_reported,
    lexicon_of,
    option_pairs,
    read_source,
)
from cnlmc.errors import UsageError

from . import preview
from .base import Command

RENDER_FLAGS = ("mesh", "size", "tier", "budget_ms", "env")
VIDEO_SUFFIXES = (".mp4", ".avi", ".mov", ".mkv", ".m4v", ".webm")


def add_render_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--mesh", help="sphere, shader_ball, teapot, or an .obj/.ply/.gltf/.glb file")
    parser.add_argument("--size", help="image size in pixels (preview default 512)")
    parser.add_argument("--tier", help="quality tier: analytic, splitsum, fisN, mcN (see docs/preview.md)")
    parser.add_argument("--budget-ms", dest="budget_ms", help="pick the best tier whose frame time fits")
    parser.add_argument("--env", help="studio, sky, sun, or an .hdr/.exr environment")
    add_option_argument(parser, "any other render option")


def render_options(args: argparse.Namespace) -> dict[str, str]:
    options = option_pairs(args.option)
    for flag in RENDER_FLAGS:
        if getattr(args, flag, None) is not None:
            options[flag] = getattr(args, flag)
    options["seed"] = str(args.seed)
    return options


def compiled_or_none(source: str, name: str, args: argparse.Namespace) -> Result | None:
    result = compile_reported(source, name, args)
    if not result.ok:
        return None
    if not result.materials:
        raise UsageError(f"{name}: no material to render")
    return result


class PreviewCommand(Command):
    name = "preview"
    help = "render a material file to a PNG (offscreen OpenGL)"

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
        source, name = read_source(args.file)
        result = compiled_or_none(source, name, args)
        if result is None:
            return EXIT_ERRORS
        if args.interactive:
            return self.live(source, args)
        try:
            report = preview.preview_command(result.ir, args.output, render_options(args))
        except (ValueError, OSError, RuntimeError) as exc:
            raise UsageError(str(exc)) from None
        for note in report.notes:
            print(f"note: {note}", file=sys.stderr)
        print(f"wrote {report.path}", file=sys.stderr)
        return EXIT_OK

    def live(self, source: str, args: argparse.Namespace) -> int:
        from .preview import live  # Tk and the live session: only for --interactive

        if args.file == "-":
            raise UsageError("--interactive reads refinements from standard input: give the material as a file")
        session = live.LiveSession(source, Path(args.output), render_options(args), lexicon_of(args))
        try:
            code: int = live.run(session, window=live.Window.open())
            return code
        except (ValueError, OSError, RuntimeError) as exc:
            raise UsageError(str(exc)) from None
        except KeyboardInterrupt:
            return EXIT_OK


def phrase_source(text: str) -> tuple[str, str]:
    """The AR phrase argument: a material file when such a file exists, else the phrase itself."""
    if Path(text).is_file():
        return read_source(text)
    return text, "<phrase>"


class ARCommand(Command):
    name = "ar"
    help = "place the material on a printed marker in a photo or video"

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        parser.add_argument("photo", nargs="?", help="a photo (.jpg/.png) or video (.mp4/.avi/.mov) showing the marker")
        parser.add_argument("phrase", nargs="?", help="a material phrase in quotes, or a material file")
        parser.add_argument("-o", "--output", help="output image or video")
        parser.add_argument("--marker", metavar="PNG", help="write a printable marker to PNG and stop")
        add_lexicon_arguments(parser)
        add_render_arguments(parser)

    def run(self, args: argparse.Namespace) -> int:
        ar = load_ar()
        if args.marker:
            print(f"wrote {ar.write_marker(args.marker)}", file=sys.stderr)
            return EXIT_OK
        if not (args.photo and args.phrase and args.output):
            raise UsageError('usage: cnlmc ar PHOTO "PHRASE" -o OUT.png   (or: cnlmc ar --marker marker.png)')
        source, name = phrase_source(args.phrase)
        result = compiled_or_none(source, name, args)
        if result is None:
            return EXIT_ERRORS
        return run_ar(ar, args, result.ir)


def load_ar() -> ModuleType:
    try:
        from . import ar  # OpenCV: only when `cnlmc ar` runs
    except ImportError as exc:
        raise UsageError(f"AR cannot load: {exc}; install it with: pip install 'cnlmc[ar]'") from None
    return ar


def run_ar(ar: Any, args: argparse.Namespace, ir: dict[str, Any]) -> int:
    run = ar.ar_video if args.photo.lower().endswith(VIDEO_SUFFIXES) else ar.ar_command
    try:
        report = run(args.photo, ir, args.output, render_options(args))
    except ar.NoMarkerFound as exc:
        print(f"cnlmc: error: {exc}", file=sys.stderr)
        print("  = print one with: cnlmc ar --marker marker.png", file=sys.stderr)
        return EXIT_ERRORS
    except (ar.ARError, ValueError, OSError, RuntimeError) as exc:
        raise UsageError(str(exc)) from None
    if report.missed:
        print(f"note: no marker in {report.missed} of {report.frames} frames (left unchanged)", file=sys.stderr)
    print(f"wrote {report.path}", file=sys.stderr)
    return EXIT_OK
