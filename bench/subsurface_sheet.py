"""docs/subsurface.png: the translucent materials (issue #19) on the teapot, front-lit and backlit,
the preview (splitsum, the default tier) beside Mitsuba's volumetric reference of the same scene
(backends/preview/subsurface_reference.py: volpathmis, --spp samples).

Columns: front-lit preview | front-lit Mitsuba | backlit preview | backlit Mitsuba. Front: the
studio and its key light; back: the key light behind the teapot (bench/preview_chart_translucent.py)
in the studio dimmed to DIM (a dark room with a lamp behind the object: what light comes through
shows). Mitsuba's tiles are shown through a 3x3 median filter (labelled "med3"): at the spp a sheet
can afford here its dense media leave salt-and-pepper noise; the chart's errors use no filter.

    .venv/bin/python bench/subsurface_sheet.py [--size 144] [--spp 64] [--out docs/subsurface.png]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "bench"))

from preview_chart import tonemap  # noqa: E402
from preview_chart_translucent import MESH as CHART_MESH  # noqa: E402
from preview_chart_translucent import TRANSLUCENT, backlit_key, material  # noqa: E402

MESH = "teapot"
DIM = 0.1  # our choice: the backlit scene's environment, a tenth of the studio
BACKGROUND = 0.18  # the chart's tone-map background (linear)


def scenes(renderer):
    from cnlmc.backends.preview.environment import Environment

    front = renderer.scene(MESH, "studio")
    lamp = backlit_key(front)
    back = renderer.scene(MESH, Environment(lamp.name + " dim", lamp.image * DIM, lamp.key))
    for scene in (front, back):
        scene.background = "transparent"
    return {"front": front, "back": back}


def tile(linear_rgba: np.ndarray, box: tuple[slice, slice], median: bool = False) -> np.ndarray:
    """Linear premultiplied RGBA -> the chart's tone map over its grey, as opaque uint8 RGBA, cut
    to the teapot's box (and 3x3 median filtered: the Mitsuba tiles, for display)."""
    import cv2

    rgb = np.round(tonemap(linear_rgba[box], BACKGROUND) * 255).astype(np.uint8)
    if median:
        rgb = cv2.medianBlur(np.ascontiguousarray(rgb), 3)
    return np.dstack([rgb, np.full(rgb.shape[:2], 255, np.uint8)])


def teapot_box(coverage: np.ndarray, margin: int = 6) -> tuple[slice, slice]:
    """The rows and columns around what is drawn (the frame fits the bounding sphere: the teapot
    fills its middle band), plus a margin."""
    ys, xs = np.nonzero(coverage > 0)
    h, w = coverage.shape
    return (
        slice(max(ys.min() - margin, 0), min(ys.max() + margin + 1, h)),
        slice(max(xs.min() - margin, 0), min(xs.max() + margin + 1, w)),
    )


def row(renderer, label: str, phrase: str, size: int, spp: int, work: Path) -> tuple[list[np.ndarray], float]:
    from cnlmc.backends.preview.sheet import label as caption
    from cnlmc.backends.preview.subsurface_reference import render_subsurface

    body, name = material(phrase), label.split(" (")[0]
    tiles, seconds = [], 0.0
    for lighting, scene in scenes(renderer).items():
        preview = renderer.render(body, scene=scene, tier="splitsum", hdr=True)
        box = teapot_box(preview.rgba[..., 3])
        reference, t = render_subsurface(body, scene, work / f"{label}_{lighting}", size, spp)
        seconds += t
        tiles += [
            caption(tile(preview.hdr, box), f"{name} {lighting}: preview"),
            caption(tile(reference, box, median=True), f"{name} {lighting}: Mitsuba {spp}spp med3"),
        ]
    return tiles, seconds


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", type=int, default=144)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--out", default=str(ROOT / "docs" / "subsurface.png"))
    parser.add_argument("--only", nargs="*", help="these materials (labels) only")
    args = parser.parse_args(argv)
    from cnlmc.backends.preview.render import Renderer
    from cnlmc.backends.preview.sheet import png_bytes, sheet
    from cnlmc.output import write_atomic

    start = time.time()
    rows = []
    with Renderer(args.size) as renderer, tempfile.TemporaryDirectory() as tmp:
        for label, (phrase, _) in TRANSLUCENT.items():
            if (args.only and label not in args.only) or label in CHART_MESH:  # the chart's own-mesh rows
                continue
            tiles, seconds = row(renderer, label, phrase, args.size, args.spp, Path(tmp))
            rows.append(tiles)
            print(f"{label:16s} Mitsuba {seconds:.0f} s", flush=True)
    write_atomic(Path(args.out), png_bytes(sheet(rows)))
    print(f"wrote {args.out} ({time.time() - start:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
