"""The `cnlmc` command line. Exit codes: 0 ok, 1 compile errors, 2 usage."""

from __future__ import annotations

import argparse
import sys

from .errors import UsageError

EXIT_OK, EXIT_ERRORS, EXIT_USAGE, EXIT_INTERNAL = 0, 1, 2, 70
STAGES = ("tokens", "ast", "ir")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="cnlmc",
        description="Compile material phrases such as "
        "'lightly brushed, blue anodized aluminum' into renderable materials.",
    )
    sub = parser.add_subparsers(dest="command", required=True)
    comp = sub.add_parser("compile", help="compile a material file (or - for stdin)")
    _common(comp)
    comp.add_argument("--target", "-t", default="ir", help="backend: see `cnlmc targets` (default: ir)")
    comp.add_argument("--emit", choices=STAGES, help="stop at a stage and print it")
    comp.add_argument("-o", "--output", help="output file or folder (default: stdout)")
    comp.add_argument(
        "--option",
        action="append",
        default=[],
        metavar="KEY=VALUE",
        help="a backend option, e.g. --option fresnel=schlick",
    )
    expl = sub.add_parser("explain", help="show every parameter and the words and rules that set it")
    _common(expl)
    sub.add_parser("targets", help="list the available targets")
    sub.add_parser("lsp", help="run the language server on stdio (for editors)")
    bake = sub.add_parser("bake", help="bake a material's procedural maps to image files")
    _common(bake)
    bake.add_argument("-o", "--output", required=True, help="output folder")
    bake.add_argument("--size", type=int, default=1024, help="map size in pixels (default 1024)")
    bake.add_argument(
        "--format",
        default="png8",
        choices=["png8", "png16", "exr-half", "exr-float"],
        help="image format (default png8)",
    )
    prev = sub.add_parser("preview", help="render a material file to a PNG (offscreen OpenGL)")
    _common(prev)
    prev.add_argument("-o", "--output", default="preview.png", help="output PNG (default preview.png)")
    prev.add_argument(
        "-i",
        "--interactive",
        action="store_true",
        help="then read refinements (darker, less grain, ...) at a prompt and re-render after each",
    )
    _render_options(prev)
    ar = sub.add_parser("ar", help="place the material on a printed marker in a photo or video")
    ar.add_argument("photo", nargs="?", help="a photo (.jpg/.png) or video (.mp4/.avi/.mov) showing the marker")
    ar.add_argument("phrase", nargs="?", help="a material phrase in quotes, or a material file")
    ar.add_argument("-o", "--output", help="output image or video")
    ar.add_argument("--marker", metavar="PNG", help="write a printable marker to PNG and stop")
    ar.add_argument("--lexicon", "-L", action="append", default=[], help="as for compile")
    ar.add_argument("--seed", type=int, default=0, help="seed for procedural maps (default 0)")
    _render_options(ar)
    sheet = sub.add_parser("sheet", help="a contact sheet PNG of every stdlib procedural graph")
    sheet.add_argument("-o", "--output", default="maps_sheet.png", help="output PNG (default maps_sheet.png)")
    sheet.add_argument("--size", type=int, default=256, help="tile size in pixels (default 256)")
    return parser


def _render_options(p) -> None:
    p.add_argument("--mesh", help="sphere, shader_ball, teapot, or an .obj/.ply/.gltf/.glb file")
    p.add_argument("--size", help="image size in pixels (preview default 512)")
    p.add_argument("--tier", help="quality tier: analytic, splitsum, fisN, mcN (see docs/preview.md)")
    p.add_argument("--budget-ms", dest="budget_ms", help="pick the best tier whose frame time fits")
    p.add_argument("--env", help="studio, sky, sun, or an .hdr/.exr environment")
    p.add_argument("--option", action="append", default=[], metavar="KEY=VALUE", help="any other render option")


def _common(p) -> None:
    p.add_argument("file", help="a material file, or - to read standard input")
    p.add_argument(
        "--lexicon",
        "-L",
        action="append",
        default=[],
        help="an overlay name (e.g. 'paper') or a lexicon folder; may repeat; folders are searched first",
    )
    p.add_argument("--seed", type=int, default=0, help="seed for procedural maps (default 0)")


def read_source(path: str) -> tuple[str, str]:
    try:
        data = sys.stdin.buffer.read() if path == "-" else open(path, "rb").read()
    except OSError as exc:
        raise UsageError(f"cannot read '{path}': {exc.strerror}") from None
    name = "<stdin>" if path == "-" else path
    if b"\x00" in data:
        raise UsageError(f"{name}: this is not a text file (it contains NUL bytes)")
    try:
        return data.decode("utf-8-sig"), name
    except UnicodeDecodeError as exc:
        raise UsageError(f"{name}: not UTF-8 text (byte {exc.start})") from None


def main(argv=None) -> int:
    try:
        return _run(build_parser().parse_args(argv))
    except UsageError as exc:
        print(f"cnlmc: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return EXIT_OK
    except Exception as exc:  # the last line of defence: never a traceback
        print(
            f"cnlmc: internal error: {type(exc).__name__}: {exc}\nplease report this with the input that caused it",
            file=sys.stderr,
        )
        return EXIT_INTERNAL


def _run(args) -> int:
    from . import commands

    handler = {
        "compile": commands.compile_cmd,
        "explain": commands.explain_cmd,
        "targets": commands.targets_cmd,
        "lsp": commands.lsp_cmd,
        "bake": commands.bake_cmd,
        "sheet": commands.sheet_cmd,
        "preview": commands.preview_cmd,
        "ar": commands.ar_cmd,
    }[args.command]
    return handler(args)


if __name__ == "__main__":
    sys.exit(main())
