"""The CLI's subcommands."""

from __future__ import annotations

import json
import sys
from dataclasses import asdict

from .cli import EXIT_ERRORS, EXIT_OK, read_source
from .diagnostics import render
from .errors import UsageError


def _lexicon(args):
    from .api import lexicon_for
    from .lexicon_schema import LexiconError

    try:
        return lexicon_for(tuple(args.lexicon))
    except LexiconError as exc:
        raise UsageError(f"lexicon: {exc}") from None


def _report(result, source: str, name: str) -> None:
    for diag in result.diagnostics:
        print(render(diag, source, name), file=sys.stderr)


def _parse_options(pairs) -> dict:
    options = {}
    for pair in pairs:
        if "=" not in pair:
            raise UsageError(f"--option expects KEY=VALUE, got '{pair}'")
        key, value = pair.split("=", 1)
        options[key.strip()] = value.strip()
    return options


def compile_cmd(args) -> int:
    from cnlmc.backends.registry import TargetUnavailable, UnknownTarget, get_backend

    from .api import compile_source

    try:
        backend = get_backend("ir" if args.emit == "ir" else args.target)
    except (UnknownTarget, TargetUnavailable) as exc:
        raise UsageError(str(exc)) from None
    source, name = read_source(args.file)
    lexicon = _lexicon(args)
    if args.emit in ("tokens", "ast"):
        return _emit_stage(args.emit, source, name, lexicon)
    result = compile_source(source, name, lexicon, args.seed)
    _report(result, source, name)
    if not result.ok:
        return EXIT_ERRORS
    options = {**_parse_options(args.option), "seed": args.seed}
    if args.output:
        options.setdefault("output", args.output)
    emitted = _run_backend(backend, result.ir, options)
    if emitted is None:
        return EXIT_ERRORS
    return _deliver(emitted.artifacts, args.output)


def _run_backend(backend, ir, options):
    """Emit; approximation notes become warnings, a refusal an error (exit 1)."""
    from cnlmc.backends.capabilities import BackendRefused

    try:
        emitted = backend.emit(ir, options)
    except BackendRefused as exc:
        print(f"error[E201]: {exc}", file=sys.stderr)
        return None
    except ValueError as exc:
        raise UsageError(str(exc)) from None
    for note in emitted.notes:
        print(f"warning[{note.code}]: {note.text()}", file=sys.stderr)
    return emitted


def _deliver(artifacts, output) -> int:
    from .output import write_artifacts

    if output:
        for path in write_artifacts(artifacts, output):
            print(f"wrote {path}", file=sys.stderr)
        return EXIT_OK
    for artifact in artifacts:
        if isinstance(artifact.content, bytes):
            raise UsageError(f"'{artifact.name}' is binary: give -o PATH")
        if len(artifacts) > 1:
            print(f"// ---- {artifact.name}")
        sys.stdout.write(artifact.content)
    return EXIT_OK


def _emit_stage(stage: str, source: str, name: str, lexicon) -> int:
    from .document import iter_lines, parse_document
    from .tagger import Tagger

    if stage == "tokens":
        tagger = Tagger(lexicon)
        for number, offset, text in iter_lines(source):
            tagged, _diags = tagger.tag_line(text, number, offset)
            for t in tagged:
                tags = "|".join(c.tag for c in t.candidates) or "?"
                print(f"{t.span.line}:{t.span.col}\t{tags}\t{t.text}" + ("\t(unknown)" if t.unknown else ""))
        return EXIT_OK
    doc = parse_document(source, lexicon, name)
    for diag in doc.diagnostics:
        print(render(diag, source, name), file=sys.stderr)
    nodes = [{"node": type(item).__name__, **asdict(item)} for item in doc.items]
    print(json.dumps(nodes, indent=2, ensure_ascii=False))
    return EXIT_ERRORS if any(d.is_error for d in doc.diagnostics) else EXIT_OK


def explain_cmd(args) -> int:
    from .api import compile_source
    from .explain import explain

    source, name = read_source(args.file)
    result = compile_source(source, name, _lexicon(args), args.seed)
    _report(result, source, name)
    sys.stdout.write(explain(result.ir))
    return EXIT_OK if result.ok else EXIT_ERRORS


def targets_cmd(args) -> int:
    from cnlmc.backends.registry import available

    for name, module in sorted(available().items()):
        print(f"{name:<10} {module}")
    return EXIT_OK


def lsp_cmd(args) -> int:
    try:
        from .lsp_server import main as serve
    except ImportError as exc:
        raise UsageError(f"the language server cannot load: {exc}; install it with: pip install 'cnlmc[lsp]'") from None
    serve()
    return EXIT_OK


def bake_cmd(args) -> int:
    from .api import compile_source
    from .bake import bake_materials

    source, name = read_source(args.file)
    result = compile_source(source, name, _lexicon(args), args.seed)
    _report(result, source, name)
    if not result.ok:
        return EXIT_ERRORS
    for path in bake_materials(result.ir, args.output, args.size, args.format, args.seed):
        print(f"wrote {path}", file=sys.stderr)
    return EXIT_OK


def sheet_cmd(args) -> int:
    try:
        from cnlmc.backends.maps import MapError, render_contact_sheet
    except ImportError as exc:
        raise UsageError(f"the contact sheet cannot load: {exc}; install it with: pip install 'cnlmc[maps]'") from None
    try:
        path = render_contact_sheet(args.output, size=args.size)
    except MapError as exc:
        raise UsageError(str(exc)) from None
    print(f"wrote {path}", file=sys.stderr)
    return EXIT_OK


RENDER_FLAGS = ("mesh", "size", "tier", "budget_ms", "env")
VIDEO_SUFFIXES = (".mp4", ".avi", ".mov", ".mkv", ".m4v", ".webm")


def _render_options(args) -> dict:
    options = _parse_options(args.option)
    for flag in RENDER_FLAGS:
        if getattr(args, flag, None) is not None:
            options[flag] = getattr(args, flag)
    options["seed"] = str(args.seed)
    return options


def _compiled_or_exit(source: str, name: str, args):
    from .api import compile_source

    result = compile_source(source, name, _lexicon(args), args.seed)
    _report(result, source, name)
    if not result.ok:
        return None
    if not result.materials:
        raise UsageError(f"{name}: no material to render")
    return result


def preview_cmd(args) -> int:
    try:
        from cnlmc.backends import preview
    except ImportError as exc:
        raise UsageError(f"the preview cannot load: {exc}; install it with: pip install 'cnlmc[preview]'") from None
    source, name = read_source(args.file)
    result = _compiled_or_exit(source, name, args)
    if result is None:
        return EXIT_ERRORS
    if getattr(args, "interactive", False):
        return _live_preview(source, args)
    try:
        report = preview.preview_command(result.ir, args.output, _render_options(args))
    except (ValueError, OSError, RuntimeError) as exc:
        raise UsageError(str(exc)) from None
    for note in report.notes:
        print(f"note: {note}", file=sys.stderr)
    print(f"wrote {report.path}", file=sys.stderr)
    return EXIT_OK


def _live_preview(source: str, args) -> int:
    from pathlib import Path

    from cnlmc.backends.preview import live

    if args.file == "-":
        raise UsageError("--interactive reads refinements from standard input: give the material as a file")
    session = live.LiveSession(source, Path(args.output), _render_options(args), _lexicon(args))
    try:
        return live.run(session, window=live.Window.open())
    except (ValueError, OSError, RuntimeError) as exc:
        raise UsageError(str(exc)) from None
    except KeyboardInterrupt:
        return EXIT_OK


def _phrase_source(text: str) -> tuple[str, str]:
    """The AR phrase argument: a material file when such a file exists, else the phrase itself."""
    from pathlib import Path

    if Path(text).is_file():
        return read_source(text)
    return text, "<phrase>"


def ar_cmd(args) -> int:
    try:
        from cnlmc.backends import ar
    except ImportError as exc:
        raise UsageError(f"AR cannot load: {exc}; install it with: pip install 'cnlmc[ar]'") from None
    if args.marker:
        print(f"wrote {ar.write_marker(args.marker)}", file=sys.stderr)
        return EXIT_OK
    if not (args.photo and args.phrase and args.output):
        raise UsageError('usage: cnlmc ar PHOTO "PHRASE" -o OUT.png   (or: cnlmc ar --marker marker.png)')
    source, name = _phrase_source(args.phrase)
    result = _compiled_or_exit(source, name, args)
    if result is None:
        return EXIT_ERRORS
    return _run_ar(ar, args, result.ir)


def _run_ar(ar, args, ir) -> int:
    run = ar.ar_video if args.photo.lower().endswith(VIDEO_SUFFIXES) else ar.ar_command
    try:
        report = run(args.photo, ir, args.output, _render_options(args))
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
