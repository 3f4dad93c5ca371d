"""Exports: a document's materials through a registry target, exactly as `cnlmc compile -t TARGET`
runs it (same options, same capability notes), written by cnlmc.output into the session's folder.
A result of several files (a .gltf with its textures, a MaterialX document with its maps) is also
offered as one zip."""

from __future__ import annotations

import io
import zipfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from cnlmc.backends.registry import BackendRefused, TargetUnavailable, get_target

from ..api import cyclic_gc_paused
from ..errors import UsageError
from ..output import write_artifacts, write_atomic
from .settings import ExportKind


@dataclass(frozen=True)
class Exported:
    """The file to download (relative to the session folder) and the target's notes, as the CLI
    prints them ('warning[W3..]: ...')."""

    path: str
    notes: list[str]


class ExportFailed(Exception):
    """A target that cannot run here or refuses a material: the message is for the page."""


def export(ir: dict[str, Any], kind: ExportKind, folder: Path, seed: int = 0) -> Exported:
    """Run `kind`'s target on the IR document; write its files under folder/exports/<key>/."""
    try:
        target = get_target(kind.target)
        with cyclic_gc_paused():
            emitted = target.emit_ir(ir, {**kind.options, "seed": seed})
    except TargetUnavailable as exc:
        raise ExportFailed(f"{kind.label} cannot be made here: {exc}") from None
    except (BackendRefused, ValueError) as exc:
        raise ExportFailed(f"{kind.label}: {exc}") from None
    if not emitted.artifacts:
        raise ExportFailed(f"{kind.label}: nothing to export (no material has what this export holds)")
    out = folder / "exports" / kind.key
    try:
        written = write_artifacts(emitted.artifacts, str(out) + "/")
        relative = _zipped(written, out, kind) if kind.zip else written[0].relative_to(folder).as_posix()
    except UsageError as exc:
        raise ExportFailed(str(exc)) from None
    return Exported(relative, [_note_text(note) for note in emitted.notes])


def _zipped(written: list[Path], out: Path, kind: ExportKind) -> str:
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for path in written:
            archive.write(path, path.relative_to(out).as_posix())
    target = out.parent / kind.file
    write_atomic(target, buffer.getvalue())
    return target.relative_to(out.parent.parent).as_posix()


def _note_text(note: Any) -> str:
    """A capability note as `cnlmc compile` prints it (cnlmc.commands.print_notes)."""
    return f"warning[{note.code}]: {note.text()}"
