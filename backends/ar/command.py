"""`cnlmc ar PHOTO "PHRASE" -o OUT.png` (or a video; or `--marker marker.png`): AR's CLI
subcommand (a cnlmc.backends.base.Command the registry lists), on the preview's render flags."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from cnlmc.commands import EXIT_ERRORS, EXIT_OK, add_lexicon_arguments, read_source, say_wrote
from cnlmc.errors import UsageError
from cnlmc.material import Document

from ..base import Command
from ..preview.commands import add_render_arguments, compiled_or_none, render_options
from ..registry import BUILTIN_COMMANDS
from .errors import ARError, NoMarkerFound
from .marker import write_marker
from .photo import ar_command
from .video import ar_video

VIDEO_SUFFIXES = (".mp4", ".avi", ".mov", ".mkv", ".m4v", ".webm")


def phrase_source(text: str, max_bytes: int) -> tuple[str, str]:
    """The AR phrase argument: a material file when such a file exists, else the phrase itself."""
    if names_a_file(text):
        return read_source(text, max_bytes)
    return text, "<phrase>"


def names_a_file(text: str) -> bool:
    """Whether the text is the path of an existing file (a phrase too long for a path is not)."""
    try:
        return Path(text).is_file()
    except (OSError, ValueError):  # ENAMETOOLONG, a NUL character
        return False


def require_opencv() -> None:
    try:
        import cv2  # noqa: F401 -- AR needs OpenCV (detection, images, video)
    except ImportError as exc:
        raise UsageError(f"AR cannot load: {exc}; install it with: pip install 'cnlmc[ar]'") from None


class ARCommand(Command):
    name = "ar"
    help = BUILTIN_COMMANDS[name].help

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        parser.add_argument("photo", nargs="?", help="a photo (.jpg/.png) or video (.mp4/.avi/.mov) showing the marker")
        parser.add_argument("phrase", nargs="?", help="a material phrase in quotes, or a material file")
        parser.add_argument("-o", "--output", help="output image or video")
        parser.add_argument("--marker", metavar="PNG", help="write a printable marker to PNG and stop")
        add_lexicon_arguments(parser)
        add_render_arguments(parser, size=False)  # the output has the photo's size

    def run(self, args: argparse.Namespace) -> int:
        require_opencv()
        if args.marker:
            say_wrote(write_marker(args.marker))
            return EXIT_OK
        if not (args.photo and args.phrase and args.output):
            raise UsageError('usage: cnlmc ar PHOTO "PHRASE" -o OUT.png   (or: cnlmc ar --marker marker.png)')
        source, name = phrase_source(args.phrase, args.max_bytes)
        result = compiled_or_none(source, name, args)
        if result is None:
            return EXIT_ERRORS
        return run_ar(args, result.document)


def run_ar(args: argparse.Namespace, document: Document) -> int:
    run = ar_video if args.photo.lower().endswith(VIDEO_SUFFIXES) else ar_command
    try:
        report = run(args.photo, document, args.output, render_options(args))
    except NoMarkerFound as exc:
        print(f"cnlmc: error: {exc}", file=sys.stderr)
        print("  = print one with: cnlmc ar --marker marker.png", file=sys.stderr)
        return EXIT_ERRORS
    except (ARError, ValueError, OSError, RuntimeError) as exc:
        raise UsageError(str(exc)) from None
    if report.missed:
        print(f"note: no marker in {report.missed} of {report.frames} frames (left unchanged)", file=sys.stderr)
    say_wrote(report.path)
    return EXIT_OK
