"""The maps target's subcommands: `cnlmc bake` (every material's maps to image files, with a
progress bar) and `cnlmc sheet` (a contact sheet of every stdlib graph)."""

from __future__ import annotations

import argparse
import os
import sys
from typing import TextIO

from cnlmc.commands import EXIT_ERRORS, EXIT_OK, add_source_arguments, compile_reported, read_source, say_wrote
from cnlmc.errors import UsageError
from cnlmc.output import Staging, writable_destination

from ..base import Command
from ..registry import BUILTIN_COMMANDS
from .errors import MapError
from .service import MapBakeError, bake_files, has_maps
from .sheet import render_contact_sheet
from .target import TARGET
from .writer import image_library


class ProgressBar:
    """A one-line bar on stderr, drawn only when stderr is a terminal and there is more than one map."""

    def __init__(self, stream: TextIO | None = None, width: int = 30):
        self.stream = stream if stream is not None else sys.stderr  # the stderr of this call, not of the import
        self.width = width
        self.enabled = self.stream.isatty()

    def __call__(self, done: int, total: int, name: str) -> None:
        if not self.enabled or total <= 1:
            return
        filled = int(self.width * done / total)
        self.stream.write(f"\r[{'#' * filled}{'.' * (self.width - filled)}] {done}/{total} {name[:40]:<40}")
        if done == total:
            self.stream.write("\n")
        self.stream.flush()


class BakeCommand(Command):
    name = "bake"
    help = BUILTIN_COMMANDS[name].help

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        add_source_arguments(parser)
        parser.add_argument("-o", "--output", required=True, help="output folder")
        declared = {option.name: option for option in TARGET.options}  # the maps target's own defaults
        size, fmt = declared["size"], declared["format"]
        parser.add_argument("--size", type=int, default=size.default, help=f"{size.doc} (default {size.default})")
        parser.add_argument(
            "--format", default=fmt.default, choices=fmt.choices, help=f"{fmt.doc} (default {fmt.default})"
        )

    def run(self, args: argparse.Namespace) -> int:
        source, name = read_source(args.file, args.max_bytes)
        if os.path.lexists(args.output) and not os.path.isdir(args.output):
            raise UsageError(f"cannot write into '{args.output}': it is not a folder")
        result = compile_reported(source, name, args)
        if not result.ok:
            return EXIT_ERRORS
        progress, paths = ProgressBar(), []
        try:
            image_library()  # loaded before the staging's signal guard (writer.image_library)
        except ImportError as exc:
            raise UsageError(f"bake cannot write images: {exc}; install it with: pip install 'cnlmc[maps]'") from None
        # every material's maps, or none of them; the folder locked against a concurrent writer
        with Staging(protect=[args.file], root=args.output) as staging:
            staging.claim(args.output)
            for material in result.document.materials:
                if not has_maps(material):
                    print(f"{material.name}: uniform, no maps to bake", file=sys.stderr)
                    continue
                try:
                    paths += bake_files(
                        material, args.output, args.size, args.format, args.seed, on_progress=progress, staging=staging
                    )
                except MapBakeError as exc:
                    raise UsageError(exc.reason) from None
            staging.commit()
        for path in paths:
            say_wrote(path)
        return EXIT_OK


#: The contact sheet's tile size: every stdlib graph's outputs at this size are held at once
#: (at 3000 px that was 9.5 GB).
SHEET_TILE = (16, 1024)


class SheetCommand(Command):
    name = "sheet"
    help = BUILTIN_COMMANDS[name].help

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        parser.add_argument("-o", "--output", default="maps_sheet.png", help="output PNG (default maps_sheet.png)")
        low, high = SHEET_TILE
        parser.add_argument("--size", type=int, default=256, help=f"tile size in pixels, {low} to {high} (default 256)")

    def run(self, args: argparse.Namespace) -> int:
        low, high = SHEET_TILE
        if not low <= args.size <= high:
            raise UsageError(f"sheet: tile size {args.size} is out of range: use {low} to {high} pixels")
        writable_destination(args.output)  # a bad -o is refused before the seconds of rendering (#13)
        try:
            path = render_contact_sheet(args.output, size=args.size)
        except ImportError as exc:
            raise UsageError(
                f"the contact sheet cannot load: {exc}; install it with: pip install 'cnlmc[maps]'"
            ) from None
        except MapError as exc:
            raise UsageError(str(exc)) from None
        say_wrote(path)
        return EXIT_OK
