"""The CLI's own subcommands (compile, explain, targets, lsp) and what every subcommand shares:
exit codes, reading a source file, the source arguments, compiling with diagnostics on stderr.

Backends bring their own subcommands (`cnlmc.backends.base.Command`, listed in
`cnlmc.backends.registry.BUILTIN_COMMANDS`); they build on the helpers here.
"""

from __future__ import annotations

import argparse
import io
import json
import sys
from collections.abc import Callable, Sequence
from dataclasses import asdict
from typing import TYPE_CHECKING, Any, BinaryIO, Protocol, cast

from cnlmc.backends.registry import (
    Artifact,
    BackendRefused,
    Command,
    EmitResult,
    Target,
    TargetUnavailable,
    UnknownTarget,
    available,
    get_target,
)

from .api import Result, compile_source, compile_stream, cyclic_gc_paused, lexicon_for
from .diagnostics import Diagnostic, has_errors, render_all, visible
from .document import parse_document
from .errors import EXIT_ERRORS as EXIT_ERRORS  # the exit codes, as the commands of every area import them
from .errors import EXIT_INTERNAL as EXIT_INTERNAL
from .errors import EXIT_OK as EXIT_OK
from .errors import EXIT_USAGE as EXIT_USAGE
from .errors import UsageError
from .inputs import DEFAULT_MAX_BYTES, input_name, read_text
from .ir import terminal_safe
from .lines import iter_lines
from .tagger import Tagger

if TYPE_CHECKING:
    from .lexicon import Lexicon

# Imported where they are used, not here: a cold `cnlmc compile` to standard output needs none of
# them (cnlmc.output and its locks and signal handling, explain, the lexicon's schema checks, tempfile).

STAGES = ("tokens", "ast", "ir")
STDOUT = "-"  # `-o -`: standard output, as without -o (a file named '-' is `-o ./-`)


# ---------------------------------------------------------------- shared by every subcommand


def read_source(path: str, max_bytes: int = DEFAULT_MAX_BYTES) -> tuple[str, str]:
    """The text of a material file (or standard input for '-'), at most `max_bytes` bytes
    (cnlmc.inputs: never a device or a FIFO), and the name diagnostics use for it."""
    return read_text(path, limit=max_bytes, what="material file"), input_name(path)


def byte_count(text: str) -> int:
    """A --max-bytes value: a positive whole number of bytes, optionally with K, M or G (binary)."""
    scale = {"k": 1 << 10, "m": 1 << 20, "g": 1 << 30}.get(text[-1:].lower(), 1)
    digits = text[:-1] if scale > 1 else text
    if not digits.isdigit() or int(digits) < 1:
        raise argparse.ArgumentTypeError(f"expected a positive number of bytes such as 65536 or 64M, got '{text}'")
    return int(digits) * scale


def add_lexicon_arguments(parser: argparse.ArgumentParser) -> None:
    """--lexicon, --seed and --max-bytes, as every compiling subcommand takes them."""
    parser.add_argument(
        "--lexicon",
        "-L",
        action="append",
        default=[],
        help="an overlay name (e.g. 'paper') or a lexicon folder; may repeat; folders are searched first",
    )
    parser.add_argument("--seed", type=int, default=0, help="seed for procedural maps (default 0)")
    parser.add_argument(
        "--max-bytes",
        type=byte_count,
        default=DEFAULT_MAX_BYTES,
        metavar="N",
        help=f"read at most N bytes of the material file, e.g. 64M (default {DEFAULT_MAX_BYTES >> 20}M)",
    )


def add_source_arguments(parser: argparse.ArgumentParser) -> None:
    """A material file (or - for standard input), --lexicon, --seed and --max-bytes."""
    parser.add_argument("file", help="a material file, or - to read standard input")
    add_lexicon_arguments(parser)


def add_option_argument(parser: argparse.ArgumentParser, help: str) -> None:
    parser.add_argument("--option", action="append", default=[], metavar="KEY=VALUE", help=help)


def option_pairs(pairs: Sequence[str]) -> dict[str, str]:
    """`--option KEY=VALUE` strings -> {key: value} (typed later, by the target's declared options)."""
    options = {}
    for pair in pairs:
        if "=" not in pair:
            raise UsageError(f"--option expects KEY=VALUE, got '{pair}'")
        key, value = pair.split("=", 1)
        options[key.strip()] = value.strip()
    return options


def lexicon_of(args: argparse.Namespace) -> Lexicon:
    try:
        lexicon: Lexicon = lexicon_for(tuple(args.lexicon))
    except Exception as exc:
        from .lexicon_schema import LexiconError  # loaded with the lexicon's files, not from the cache

        if isinstance(exc, LexiconError):
            raise UsageError(f"lexicon: {exc}") from None
        raise
    return lexicon


def report(result: Result, source: str, name: str) -> None:
    print_diagnostics(result.diagnostics, source, name)


def print_diagnostics(diags: Sequence[Diagnostic], source: str, name: str) -> None:
    """Every diagnostic on stderr, rendered against one line table of the source (linear in their number)."""
    for text in render_all(diags, source, name):
        print(text, file=sys.stderr)


def compile_reported(source: str, name: str, args: argparse.Namespace) -> Result:
    """Compile with the arguments' lexicon and seed; diagnostics go to stderr."""
    result = compile_source(source, name, lexicon_of(args), args.seed, keep_stages=False)
    report(result, source, name)
    return result


# ---------------------------------------------------------------- compile


class CompileCommand(Command):
    name = "compile"
    help = "compile a material file (or - for stdin)"
    writes_stdout = True

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        add_source_arguments(parser)
        parser.add_argument("--target", "-t", default="ir", help="backend: see `cnlmc targets` (default: ir)")
        parser.add_argument("--emit", choices=STAGES, help="stop at a stage and print it")
        parser.add_argument("-o", "--output", help="output file or folder (default, or -: stdout)")
        add_option_argument(parser, "a backend option, e.g. --option fresnel=schlick")

    def run(self, args: argparse.Namespace) -> int:
        try:
            target = get_target("ir" if args.emit == "ir" else args.target)
        except (UnknownTarget, TargetUnavailable) as exc:
            raise UsageError(str(exc)) from None
        source, name = read_source(args.file, args.max_bytes)
        lexicon = lexicon_of(args)
        if args.emit in ("tokens", "ast"):
            return emit_stage(args.emit, source, name, lexicon)
        streams = getattr(target, "material_writer", None)
        if callable(streams):
            return compile_streamed(target, streams, source, name, lexicon, args)
        result = compile_source(source, name, lexicon, args.seed, keep_stages=False)
        report(result, source, name)
        if not result.ok:
            return EXIT_ERRORS
        emitted = run_target(target, result, args)
        if emitted is None:
            return EXIT_ERRORS
        print_notes(emitted)
        return deliver(emitted.artifacts, args.output, protect=[args.file])


def run_target(target: Target, result: Result, args: argparse.Namespace) -> EmitResult | None:
    """The target on the compiled document with the --option pairs (plus seed and output);
    None when it refuses a material (said on stderr); a bad option is a usage error."""
    options: dict[str, object] = {**option_pairs(args.option), "seed": args.seed}
    if output_path(args.output):
        options.setdefault("output", args.output)
    try:
        with cyclic_gc_paused():
            return target.emit_ir(result.ir, options)  # typed by the target (the IR target writes it as it is)
    except BackendRefused as exc:
        print(f"error[E201]: {exc}", file=sys.stderr)
        return None
    except (ValueError, TargetUnavailable) as exc:  # TargetUnavailable: a library it needs is not installed
        raise UsageError(str(exc)) from None


class _CompileErrors(Exception):
    """The document has errors (already on stderr): what is staged is discarded, exit 1."""


class MaterialWriter(Protocol):
    """What a streaming target's `material_writer(out, head)` returns (the IR target's IrWriter):
    `write(material_ir)` checks one material and writes it to `out`, `finish(diagnostics)` the rest."""

    def write(self, material: object) -> None: ...

    def finish(self, diagnostics: Sequence[object]) -> None: ...


def compile_streamed(
    target: Target,
    material_writer: Callable[[BinaryIO, dict[str, Any]], MaterialWriter],
    source: str,
    name: str,
    lexicon: Lexicon,
    args: argparse.Namespace,
) -> int:
    """compile to a target that writes one file a material at a time (`material_writer`, the IR
    target's): each material's IR is made, checked, written to the staged output
    (cnlmc.output.write_streamed; for stdout a Spool: memory, then a file on disk) and let go, so
    memory does not grow with the document. The diagnostics go to stderr once every line is read; with an error
    nothing is written (exit 1), as when the whole IR is made first."""
    stream = compile_stream(source, name, lexicon, args.seed)

    def write(out: BinaryIO) -> None:
        writer = material_writer(out, stream.head)
        for material in stream.materials:
            writer.write(material)
        diags = stream.sorted_diagnostics()
        print_diagnostics(diags, source, name)
        if has_errors(diags):
            raise _CompileErrors
        options: dict[str, object] = {**option_pairs(args.option), "seed": args.seed}
        if output_path(args.output):
            options["output"] = args.output
        try:
            target.parse_options(options)
            writer.finish([d.to_json() for d in diags])
        except ValueError as exc:
            raise UsageError(str(exc)) from None

    try:
        with cyclic_gc_paused():
            if output_path(args.output):
                from .output import write_streamed

                say_wrote(write_streamed("materials.ir.json", args.output, write, protect=[args.file]))
            else:
                _to_stdout(write)
    except _CompileErrors:
        return EXIT_ERRORS
    return EXIT_OK


def _to_stdout(write: Callable[[BinaryIO], None]) -> None:
    """`write` into a spool (in memory up to SPOOL_IN_MEMORY bytes, then a file on disk in TMPDIR),
    then copied to stdout once it has succeeded."""
    with Spool() as spool:
        try:
            write(cast(BinaryIO, spool))  # it only writes
            spool.flush()
        except OSError as exc:
            raise _spool_error(exc) from None
        if sys.stdout is None:  # started with standard output closed (`>&-`)
            raise UsageError("cannot write to standard output: it is closed; give -o FILE")
        try:
            sys.stdout.flush()
            spool.copy_to(sys.stdout.buffer)
            sys.stdout.buffer.flush()
        except BrokenPipeError:
            raise
        except OSError as exc:
            raise UsageError(f"cannot write to standard output: {exc.strerror or exc}") from None


#: What a Spool keeps in memory before it moves to a file on disk (our choice: a phrase's IR is a
#: few KiB, a large document's many MiB; 8 MiB bounds the memory the way the file did).
SPOOL_IN_MEMORY = 8 << 20
COPY_CHUNK = 1 << 16


class Spool:
    """A write-only staging buffer: bytes in memory until they pass `limit`, then all of them in an
    anonymous temporary file (tempfile is imported only then). `copy_to` writes what it holds."""

    def __init__(self, limit: int = SPOOL_IN_MEMORY) -> None:
        self.limit = limit
        self.memory: io.BytesIO | None = io.BytesIO()
        self.file: BinaryIO | None = None

    def __enter__(self) -> Spool:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def write(self, data: bytes) -> int:
        if self.memory is not None and self.memory.tell() + len(data) > self.limit:
            self._to_disk()
        target = self.memory if self.memory is not None else self.file
        assert target is not None
        return target.write(data)

    def _to_disk(self) -> None:
        import tempfile

        try:
            file = tempfile.TemporaryFile()
        except OSError as exc:
            raise _spool_error(exc) from None
        assert self.memory is not None
        file.write(self.memory.getbuffer())
        self.memory, self.file = None, file

    def flush(self) -> None:
        if self.file is not None:
            self.file.flush()

    def copy_to(self, out: BinaryIO) -> None:
        if self.memory is not None:
            out.write(self.memory.getbuffer())
            return
        assert self.file is not None
        self.file.seek(0)
        while chunk := self.file.read(COPY_CHUNK):
            out.write(chunk)

    def close(self) -> None:
        if self.file is not None:
            self.file.close()
        self.memory = self.file = None


def _spool_error(exc: OSError) -> UsageError:
    import tempfile

    return UsageError(
        f"cannot write the output to a temporary file in '{tempfile.gettempdir()}': {exc.strerror or exc}; "
        "give -o PATH, or set TMPDIR to a folder with room"
    )


def print_notes(emitted: EmitResult) -> None:
    """Approximation notes become warnings: nothing is dropped silently."""
    for note in emitted.notes:
        print(f"warning[{note.code}]: {note.text()}", file=sys.stderr)


def say_wrote(path: object) -> None:
    """'wrote PATH' on stderr, the path's control characters shown escaped."""
    print(f"wrote {visible(str(path), one_line=True)}", file=sys.stderr)


def output_path(output: str | None) -> str | None:
    """The -o value as a path to write, or None for standard output (no -o, or `-o -`)."""
    return None if not output or output == STDOUT else output


def deliver(artifacts: list[Artifact], output: str | None, protect: Sequence[str] = ()) -> int:
    """Write the files (all-or-nothing, never over an input in `protect`: cnlmc.output) where -o
    says, or print them on stdout (no -o, or `-o -`) when all of them are text: nothing is
    printed when one is binary."""
    if not artifacts:
        print(
            "cnlmc: note: nothing to write: the result has no files (no material of the input has what this target writes)",
            file=sys.stderr,
        )
        return EXIT_OK
    path = output_path(output)
    if path:
        from .output import write_artifacts

        for written in write_artifacts(artifacts, path, protect):
            say_wrote(written)
        return EXIT_OK
    binary = next((a.name for a in artifacts if isinstance(a.content, bytes)), None)
    if binary is not None and output == STDOUT:
        raise UsageError(
            f"-o - writes to standard output, which takes text; this result has binary files ('{binary}'): "
            "give -o FOLDER or -o FILE to write them (a file named '-' is -o ./-)"
        )
    if binary is not None:
        raise UsageError(f"'{binary}' is binary: give -o PATH")
    for artifact in artifacts:
        if len(artifacts) > 1:
            print(f"// ---- {artifact.name}")
        assert isinstance(artifact.content, str)  # (no binary: checked above)
        sys.stdout.write(artifact.content)
    return EXIT_OK


def emit_stage(stage: str, source: str, name: str, lexicon: Lexicon) -> int:
    """--emit tokens | ast: the stage printed on stdout."""
    if stage == "tokens":
        tagger = Tagger.of(lexicon)
        for number, offset, text in iter_lines(source):
            tagged, _diags = tagger.tag_line(text, number, offset)
            for t in tagged:
                tags = "|".join(c.tag for c in t.candidates) or "?"
                span = t.span if t.implied_by is None else t.implied_by  # an implied word: where its implier is
                print(
                    f"{span.line}:{span.col}\t{tags}\t{visible(t.text, one_line=True)}"
                    + ("\t(unknown)" if t.unknown else "")
                    + ("\t(implied)" if t.implied_by is not None else "")
                )
        return EXIT_OK
    doc = parse_document(source, lexicon, name)
    print_diagnostics(doc.diagnostics, source, name)
    nodes = [{"node": type(item).__name__, **asdict(item)} for item in doc.items]
    print(terminal_safe(json.dumps(nodes, indent=2, ensure_ascii=False)))
    return EXIT_ERRORS if any(d.is_error for d in doc.diagnostics) else EXIT_OK


# ---------------------------------------------------------------- explain, targets, lsp


class ExplainCommand(Command):
    name = "explain"
    help = "show every parameter and the words and rules that set it"

    def add_arguments(self, parser: argparse.ArgumentParser) -> None:
        add_source_arguments(parser)

    def run(self, args: argparse.Namespace) -> int:
        from .explain import explain

        source, name = read_source(args.file, args.max_bytes)
        result = compile_reported(source, name, args)
        sys.stdout.write(explain(result.ir))
        return EXIT_OK if result.ok else EXIT_ERRORS


class TargetsCommand(Command):
    name = "targets"
    help = "list the available targets"

    def run(self, args: argparse.Namespace) -> int:
        for name, module in sorted(available().items()):
            try:
                description = get_target(name).description
            except TargetUnavailable as exc:
                description = f"(not here: {exc})"
            except Exception as exc:  # a broken plugin must not hide the others
                description = f"(cannot load: {type(exc).__name__}: {exc})"
            print(f"{name:<10} {description} [{module}]")
        return EXIT_OK


class LspCommand(Command):
    name = "lsp"
    help = "run the language server on stdio (for editors)"

    def run(self, args: argparse.Namespace) -> int:
        try:
            from .lsp_server import main as serve  # pygls, an optional dependency: only for `cnlmc lsp`
        except ImportError as exc:
            raise UsageError(
                f"the language server cannot load: {exc}; install it with: pip install 'cnlmc[lsp]'"
            ) from None
        serve()
        return EXIT_OK


#: The CLI's own subcommands, in the order `cnlmc --help` lists them (then cnlmc.cli's
#: FRONT_END_COMMANDS: build, serve, listen; then backends' commands).
LANGUAGE_COMMANDS: tuple[Command, ...] = (
    CompileCommand(),
    ExplainCommand(),
    TargetsCommand(),
    LspCommand(),
)
