"""The desktop's marker AR: an uploaded photo with a printed marker, the document's material
standing on it, made by the `ar` command itself (through the registry, as `cnlmc ar` runs it)."""

from __future__ import annotations

import argparse
import contextlib
import io
import threading
from pathlib import Path

from cnlmc.backends.registry import TargetUnavailable, get_command

from ..errors import UsageError
from ..output import write_atomic

PHOTO_SUFFIXES = {"image/jpeg": ".jpg", "image/png": ".png"}


class ARFailed(Exception):
    """The composite could not be made: the message (from the command) is for the page."""


class MarkerComposer:
    """Runs the `ar` command; one at a time (it reports on stderr, which is the process's)."""

    def __init__(self) -> None:
        self.lock = threading.Lock()

    def composite(self, photo: bytes, content_type: str, document: str, folder: Path) -> str:
        """Write the photo and document into `folder/ar/`, run `ar`, return the image's path
        relative to `folder`."""
        suffix = PHOTO_SUFFIXES.get(content_type)
        if suffix is None:
            raise ARFailed("the photo must be a JPEG or PNG image")
        work = folder / "ar"
        photo_path, source_path, out_path = work / f"photo{suffix}", work / "document.cnl", work / "composite.png"
        try:
            write_atomic(photo_path, photo)
            write_atomic(source_path, document)
            command = get_command("ar")
        except (UsageError, TargetUnavailable) as exc:
            raise ARFailed(str(exc)) from None
        parser = argparse.ArgumentParser(prog="cnlmc ar", add_help=False)
        command.add_arguments(parser)
        args = parser.parse_args([str(photo_path), str(source_path), "-o", str(out_path)])
        said = io.StringIO()
        with self.lock, contextlib.redirect_stderr(said), contextlib.redirect_stdout(io.StringIO()):
            try:
                code = command.run(args)
            except UsageError as exc:
                raise ARFailed(str(exc)) from None
        if code != 0 or not out_path.exists():
            raise ARFailed(" ".join(said.getvalue().split()) or "no composite was made")
        return out_path.relative_to(folder).as_posix()
