"""Render a Mitsuba scene written by cnlmc, with the `cnlm` plugin registered when the scene
uses it (a plain `mitsuba scene.xml` does not know the plugin: "Plugin "cnlm" not found!"):

    python -m cnlmc.backends.exchange.mitsuba_render scene.xml -o render.exr [-D spp=256 ...]

The image goes through cnlmc.output (atomic; .exr linear, .png sRGB 8-bit). Exit codes: 0 done,
1 the scene or Mitsuba failed, 2 a usage error."""

from __future__ import annotations

import argparse
import sys
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from cnlmc.errors import UsageError
from cnlmc.output import write_files

from . import mitsuba_cnlm

SCALAR_VARIANT = "scalar_rgb"  # a scene without the plugin: Mitsuba's simplest variant
PLUGIN_MARK = f'type="{mitsuba_cnlm.PLUGIN}"'


def parse(argv: Sequence[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="python -m cnlmc.backends.exchange.mitsuba_render", description=__doc__)
    parser.add_argument("scene", help="the scene XML (cnlmc --target mitsuba)")
    parser.add_argument("-o", "--output", default="render.exr", help="the image (.exr or .png)")
    parser.add_argument("-D", dest="defines", action="append", default=[], metavar="KEY=VALUE")
    return parser.parse_args(argv)


def defines(pairs: Sequence[str]) -> dict[str, str]:
    out = {}
    for pair in pairs:
        key, sep, value = pair.partition("=")
        if not sep or not key:
            raise UsageError(f"-D {pair!r}: give KEY=VALUE, e.g. -D spp=64")
        out[key] = value
    return out


def render(scene: Path, output: Path, params: dict[str, str]) -> None:
    import mitsuba as mi

    if PLUGIN_MARK in scene.read_text(encoding="utf-8"):
        mitsuba_cnlm.register()
    elif mi.variant() is None:
        mi.set_variant(SCALAR_VARIANT)
    load: Any = mi.load_file  # its stub types the keyword parameters as bool; -D values are strings
    image = mi.render(load(str(scene), **params))
    with tempfile.TemporaryDirectory(prefix="cnlmc-render-") as tmp:
        written = Path(tmp) / output.name
        mi.util.write_bitmap(str(written), image, write_async=False)
        write_files([(output, written.read_bytes())])


def main(argv: Sequence[str] | None = None) -> int:
    args = parse(sys.argv[1:] if argv is None else argv)
    scene, output = Path(args.scene), Path(args.output)
    try:
        if not scene.is_file():
            raise UsageError(f"{scene}: no such scene file")
        if output.suffix.lower() not in (".exr", ".png"):
            raise UsageError(f"{output}: the image must end in .exr or .png")
        render(scene, output, defines(args.defines))
    except UsageError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    except (RuntimeError, mitsuba_cnlm.PluginError) as error:
        print(f"error: {scene}: {error}", file=sys.stderr)
        return 1
    print(f"wrote {output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
