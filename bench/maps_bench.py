"""Procedural-map benchmark: prints numbers, asserts nothing.

.venv/bin/python bench/maps_bench.py [--size 1024] [--runs 7]
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time

from cnlmc.backends.maps import NODE_TYPES, bake, write_maps
from cnlmc.backends.maps.blas import single_threaded_blas
from cnlmc.backends.maps.grid import Grid

WOOD = {
    role: {"graph": "wood", "output": output, "params": {}, "seed": 0}
    for role, output in (("base_color", "color"), ("normal", "normal"), ("roughness", "roughness"))
}


def median_seconds(function, runs: int) -> float:
    function()  # warm caches (lattice weights, graph parsing)
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def bench_bake(size: int, runs: int):
    seconds = median_seconds(lambda: bake(WOOD, {"base_color": [0.42, 0.24, 0.11]}, size, 0), runs)
    print(
        f"bake wood color+normal+roughness {size}^2: median {seconds * 1000:.1f} ms over {runs} runs (goal <= 150 ms)"
    )


def bench_write(size: int, runs: int):
    arrays = bake(WOOD, {}, size, 0)
    with tempfile.TemporaryDirectory() as out:
        for fmt in ("png8", "png16", "exr-half", "exr-float"):
            seconds = median_seconds(lambda: write_maps(arrays, out, fmt=fmt, stem="wood"), max(3, runs // 2))
            print(f"write 3 maps {size}^2 {fmt:9s}: median {seconds * 1000:.1f} ms")


def bench_generators(size: int, runs: int):
    """Each generator with its defaults, under the single-threaded BLAS that bake() uses."""
    grid = Grid(size, 1)
    with single_threaded_blas():
        for name, node_type in NODE_TYPES.items():
            if node_type.category != "generator":
                continue
            seconds = median_seconds(lambda: node_type.function(grid), max(3, runs // 2))
            print(f"generator {name:16s}: {size * size / seconds / 1e6:7.1f} Mpixel/s ({seconds * 1000:.1f} ms)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=1024)
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args()
    print(f"cpu count {os.cpu_count()}, load average {os.getloadavg()[0]:.2f}")
    bench_bake(args.size, args.runs)
    bench_write(args.size, args.runs)
    bench_generators(args.size, args.runs)


if __name__ == "__main__":
    main()
