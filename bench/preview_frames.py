"""Frame time of the preview at 512x512 on this machine (llvmpipe), per tier and material.

    .venv/bin/python bench/preview_frames.py [--size 512] [--frames 15] [--tiers analytic,splitsum]

Each material on the sphere in the studio, with the environment background: one warm-up
frame (compiles the shader, integrates the split-sum tables), then `--frames` frames, each
timed from the first draw call to `finish()`. Prints min / median ms and fps of the median,
and the first (cold) frame, which includes compiling.
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np

MATERIALS = (
    "blue plastic",
    "gold",
    "granite",
    "clear-coated red car paint",
    "lightly brushed, blue anodized aluminum",
    "white varnished oak",
    "suede",
)


def measure(renderer, scene, material, tier, frames: int) -> tuple[float, list[float]]:
    start = time.perf_counter()
    renderer.draw(scene, material, tier)
    renderer.ctx.finish()
    cold = (time.perf_counter() - start) * 1000
    times = []
    for _ in range(frames):
        start = time.perf_counter()
        renderer.draw(scene, material, tier)
        renderer.ctx.finish()
        times.append((time.perf_counter() - start) * 1000)
    return cold, times


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--frames", type=int, default=15)
    parser.add_argument("--tiers", default="analytic,splitsum")
    args = parser.parse_args(argv)
    from cnlmc.api import compile_source
    from cnlmc.backends.preview.render import Renderer, default_scene

    renderer = Renderer(args.size)
    scene = default_scene("sphere", "studio", (args.size, args.size))
    print(f"{'material':42s} {'tier':9s} {'cold ms':>8s} {'min ms':>7s} {'median':>7s} {'fps':>5s}")
    medians = []
    for phrase in MATERIALS:
        material = compile_source(phrase + "\n").ir["materials"][0]
        for tier in args.tiers.split(","):
            cold, times = measure(renderer, scene, material, tier, args.frames)
            median = float(np.median(times))
            medians.append((tier, median))
            print(
                f"{phrase:42s} {tier:9s} {cold:8.0f} {min(times):7.1f} {median:7.1f} {1000 / median:5.0f}", flush=True
            )
    for tier in args.tiers.split(","):
        values = [m for t, m in medians if t == tier]
        print(
            f"{tier}: median frame {min(values):.1f}-{max(values):.1f} ms over {len(values)} materials "
            f"({1000 / max(values):.0f}-{1000 / min(values):.0f} fps) at {args.size}x{args.size}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
